# The HAL-level test suite (tests/*/*/) in the kernel flavor, through halrun/halcmd
# and emc_module_helper as a user would run it.
sh /tests/run-hal-tests-vm.sh /tests/hal
