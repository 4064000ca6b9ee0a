# tests/hostmot2/mesa-7i65 with the simulated card behind hm2_pci (PCI IDs, BARs, PLX bridge)
. ../../helpers/hm2-over-pci.sh
hm2_over_pci mesa-7i65
