# SPDX-License-Identifier: GPL-2.0-or-later
# Top-level driver: installs missing Debian packages, builds userspace and the
# simulated-realtime flavor with CMake into build/, runs tests, demo and benchmarks.
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=

# make test runs: units, the HAL-level suite (simulated flavor), the sanitizer job,
# the fuzz smoke run, the kernel flavor in qemu, the package test, the fresh-clone
# test. Each of the last five can be left out: KERNEL_TEST=0 (no kernel images, qemu
# or root needed), SANITIZE_TEST=0 (no ASan/UBSan build and run), FUZZ_TEST=0 (no
# libFuzzer build and run), PACKAGE_TEST=0 (no packages, debootstrap or chroot),
# FRESH_CLONE_TEST=0 (no clone, make kmod or bench run there).
# make test-sim is the plain simulated flavor: units and the HAL-level suite only.
KERNEL_TEST ?= 1
SANITIZE_TEST ?= 1
FUZZ_TEST ?= 1
PACKAGE_TEST ?= 1
FRESH_CLONE_TEST ?= 1

.PHONY: all deps configure build test test-sim unit-test hal-test kmod kernel-test demo demo-hal bench install clean \
	deb package-test fresh-clone-test

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

# The modules need the C that comp generates from the .comp sources: configure and
# build just that (target comp_sources), then kbuild. KDIR=... picks another kernel.
# The self-test modules of tests/kernel are built with them (the same tree as the
# kernel test's, which then reuses it).
kmod: configure
	@scripts/kernel-test-deps --headers
	cmake --build $(BUILD) -j$(JOBS) --target comp_sources
	COMP_GEN_DIR=$(abspath $(BUILD))/gen $(MAKE) -f kernel/Makefile.kmod -j$(JOBS) KMOD_WITH_SELFTESTS=1
	kernel/kmod-deps-check.sh $$($(MAKE) -s --no-print-directory -f kernel/Makefile.kmod print-KMOD_BUILD)

kernel-test: build
	KERNEL_TEST_RT=1 scripts/kernel-test-deps
	tests/kernel/fp-check-test.sh
	tests/kernel/run-kernel-tests.sh \
		$$(ls -d /usr/src/linux-headers-*-amd64 | sed 's|.*/linux-headers-||' | grep -v -- -rt- | sort -V | tail -1) \
		$$(ls -d /usr/src/linux-headers-*-rt-amd64 | sed 's|.*/linux-headers-||' | sort -V | tail -1)

# (cold, on 2 cores: package-test about 8 min, fresh-clone-test under 2)
test: unit-test hal-test $(if $(filter 0,$(SANITIZE_TEST)),,sanitize-test) \
	$(if $(filter 0,$(FUZZ_TEST)),,fuzz-smoke) $(if $(filter 0,$(KERNEL_TEST)),,kernel-test) \
	$(if $(filter 0,$(PACKAGE_TEST)),,package-test) $(if $(filter 0,$(FRESH_CLONE_TEST)),,fresh-clone-test)

test-sim: unit-test hal-test

# Debian packages (debhelper, dh-dkms) into $(BUILD)/deb/, checked by lintian.
deb: deps
	@scripts/deb-deps
	tests/deb/build-debs.sh $(BUILD)/deb

# The packages installed into a clean Debian 12 root: halrun there, an out-of-tree
# component through pkg-config, dkms build for the standard and PREEMPT_RT kernels.
package-test: deb
	KERNEL_TEST_RT=1 scripts/kernel-test-deps
	tests/deb/run-package-test.sh $(BUILD)/deb

# make kmod and make bench from a fresh clone of this repository (HEAD).
fresh-clone-test: build
	@scripts/kernel-test-deps --headers
	tests/fresh-clone/run.sh $(BUILD)

# make demo: the simulated mill homes, runs its sample program, and the sampled
# joint positions are checked and drawn into $(BUILD)/demo/toolpath.png (demo/run-demo.sh).
# make demo-hal: the small siggen -> sampler HAL file of demo/demo.hal, printed.
demo: build
	demo/run-demo.sh $(BUILD)

demo-hal: build
	demo/run-hal-demo.sh $(BUILD)

bench: build
	bench/run-bench.sh $(BUILD)

install: build
	cmake --install $(BUILD)

clean:
	rm -rf $(BUILD)

# --- Robustness (issue 19): a sanitizer build and libFuzzer targets --------------
# Both are part of make test (SANITIZE_TEST=0 / FUZZ_TEST=0 leave them out).
# sanitize-test: ASan + UBSan build of everything (own tree, same ccache) running the
# unit tests and the simulated-flavor HAL-level suite, no suppressions. UBSan findings
# abort (-fno-sanitize-recover), so they fail the tests that hit them; ASan's leak
# check is on. The fault-injection test runs SAN_FAULT_ROUNDS of its kills here
# (all 100 run in hal-test), which keeps the job within CI's budget.
# fuzz-smoke: every fuzz target for FUZZ_SECONDS (in make test);
# fuzz: the same for FUZZ_LONG_SECONDS each, keeping the corpus in build-fuzz/corpus.
SAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 15
FUZZ_LONG_SECONDS ?= 600
SAN_FAULT_ROUNDS ?= 20
SAN_ENV = ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

.PHONY: sanitize-test fuzz-build fuzz-smoke fuzz

sanitize-test:
	@$(MAKE) --no-print-directory deps
	# -O1 -g1: half the compile time of -O2 -g, still enough for ASan's reports
	cmake -S . -B $(SAN_BUILD) -DHAL_SANITIZE=ON -DCMAKE_BUILD_TYPE=SanCheck \
		'-DCMAKE_C_FLAGS_SANCHECK=-O1 -g1' '-DCMAKE_CXX_FLAGS_SANCHECK=-O1 -g1' $(CMAKE_FLAGS)
	cmake --build $(SAN_BUILD) -j$(JOBS)
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j$(JOBS)
	$(SAN_ENV) HAL_TEST_TIMEOUT=300 FAULT_ROUNDS=$(SAN_FAULT_ROUNDS) \
		tests/run-hal-tests.sh --build $(SAN_BUILD) --flavor sim -j$(JOBS)

fuzz-build:
	@scripts/fuzz-deps
	cmake -S tests/fuzz -B $(FUZZ_BUILD) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
	cmake --build $(FUZZ_BUILD) -j$(JOBS)

fuzz-smoke: fuzz-build
	tests/fuzz/run-fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

fuzz: fuzz-build
	tests/fuzz/run-fuzz.sh $(FUZZ_BUILD) $(FUZZ_LONG_SECONDS)

