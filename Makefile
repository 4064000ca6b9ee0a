# SPDX-License-Identifier: GPL-2.0-or-later
# Top-level driver: installs missing Debian packages, builds userspace and the
# simulated-realtime flavor with CMake into build/, runs tests, demo and benchmarks.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

.PHONY: all deps configure build test unit-test hal-test kmod kernel-test demo bench install clean

all: build

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt:
	@$(MAKE) --no-print-directory deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j$(JOBS)

unit-test: build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

hal-test: build
	tests/run-hal-tests.sh --build $(BUILD) --flavor sim

# Kernel flavor: modules built against Debian's standard and PREEMPT_RT kernels,
# each booted in qemu (two VMs in parallel) to run the HAL-level suite.

kmod:
	$(MAKE) -f kernel/Makefile.kmod

kernel-test: build
	KERNEL_TEST_RT=1 scripts/kernel-test-deps
	tests/kernel/fp-check-test.sh
	tests/kernel/run-kernel-tests.sh \
		$$(ls -d /usr/src/linux-headers-*-amd64 | sed 's|.*/linux-headers-||' | grep -v -- -rt- | sort -V | tail -1) \
		$$(ls -d /usr/src/linux-headers-*-rt-amd64 | sed 's|.*/linux-headers-||' | sort -V | tail -1)

test: unit-test hal-test kernel-test

demo: build
	demo/run-demo.sh $(BUILD)

bench: build
	bench/run-bench.sh $(BUILD)

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD)
