# The HAL-level test suite (tests/*/*/) in the kernel flavor, through halrun/halcmd
# and emc_module_helper as a user would run it.
# As a member of group 'hal', not root (issue 9): everything goes through the
# helper and the /dev/rtapi interface.
su haluser -s /bin/sh -c "cd /home/haluser && PATH=$PATH sh /tests/run-hal-tests-vm.sh /tests/hal"
