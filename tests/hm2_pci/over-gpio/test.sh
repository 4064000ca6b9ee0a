# tests/hostmot2/gpio with the simulated card behind hm2_pci (PCI IDs, BARs, PLX bridge)
. ../../helpers/hm2-over-pci.sh
hm2_over_pci gpio
