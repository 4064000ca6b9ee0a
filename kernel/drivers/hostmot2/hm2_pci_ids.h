/* SPDX-License-Identifier: GPL-2.0-or-later */
/* hm2_pci_ids.h - the PCI IDs of the Mesa cards (hostmot2.md 12.1): vendor, device,
 * subsystem vendor, subsystem device, board (hm2_boards.h) and, for cards whose
 * driver programs the FPGA, the part a .BIT file must be for (5i22, 4i69 and 3x20
 * come with several FPGA sizes, told apart by the subsystem device). One list for
 * hm2_pci's match table and the simulated cards of hm2_sim bus=pci. */
#ifndef HM2_PCI_IDS_H
#define HM2_PCI_IDS_H

#define HM2_PCI_PLX 0x10B5
#define HM2_PCI_MESA 0x2718

#define HM2_PCI_CARDS(X)									\
	X(HM2_PCI_PLX, 0x9030, HM2_PCI_PLX, 0x3131, "5i20", "2s200pq208")			\
	X(HM2_PCI_PLX, 0x9030, HM2_PCI_PLX, 0x3132, "4i65", "2s200pq208")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3312, "5i21", "3s400pq208")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3314, "5i22", "3s1000fg320")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3313, "5i22", "3s1500fg320")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3315, "5i23", "3s400pq208")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3311, "4i68", "3s400pq208")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3133, "4i68", "3s400pq208")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3472, "4i69", "6slx16ftg256")			\
	X(HM2_PCI_PLX, 0x9054, HM2_PCI_PLX, 0x3473, "4i69", "6slx25ftg256")			\
	X(HM2_PCI_PLX, 0x9056, HM2_PCI_PLX, 0x3427, "3x20", "3s1000fg456")			\
	X(HM2_PCI_PLX, 0x9056, HM2_PCI_PLX, 0x3428, "3x20", "3s1500fg456")			\
	X(HM2_PCI_PLX, 0x9056, HM2_PCI_PLX, 0x3429, "3x20", "3s2000fg456")			\
	X(HM2_PCI_MESA, 0x5124, HM2_PCI_MESA, 0x5124, "5i24", 0)				\
	X(HM2_PCI_MESA, 0x5125, HM2_PCI_MESA, 0x5125, "5i25", 0)				\
	X(HM2_PCI_MESA, 0x5925, HM2_PCI_MESA, 0x5925, "5i25", 0)				\
	X(HM2_PCI_MESA, 0x6125, HM2_PCI_MESA, 0x6125, "6i25", 0)				\
	X(HM2_PCI_MESA, 0x6925, HM2_PCI_MESA, 0x6925, "6i25", 0)

/* BARs: the HostMot2 window of a PLX 9030 card, of a 9054/9056 card, of a card
 * without a bridge; the PLX registers; the FPGA configuration data port */
#define HM2_PCI_BAR_9030 5
#define HM2_PCI_BAR_9054 3
#define HM2_PCI_BAR_DIRECT 0
#define HM2_PCI_BAR_PLX 1
#define HM2_PCI_BAR_CFGDATA 2

#endif /* HM2_PCI_IDS_H */
