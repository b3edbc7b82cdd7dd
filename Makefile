# Thin entry points; the build itself is CMake (CMakePresets.json).
#   make deps   install the Debian packages the build needs (idempotent, skips what is present)
#   make demo   deps + Release build + the known-answer problems, the snowball_pair scene (preview,
#               rendered to frames/*.png and video.mp4) and the reference benchmark
#   make test   deps + test-deps + Release build + the whole test suite (TEST_JOBS, default 2, at a
#               time), then a 30 s fuzz run where clang is present
#   make test-deps  install what only the tests use: chromium, which opens firn report's pages headless
#   make fuzz   the fuzz preset's build and FUZZ_SECONDS (default 30) of the scene fuzzer (skipped
#               without clang and libFuzzer; make fuzz-deps installs them)
#   make slurm-deps  install Slurm and munge, for the one-node Slurm test of firn sweep --scheduler slurm
DEB_PACKAGES := build-essential cmake libeigen3-dev libcli11-dev libtomlplusplus-dev libgtest-dev libbenchmark-dev \
                python3 python3-vtk9 gnuplot-nox \
                libegl-dev libgl-dev libosmesa6-dev libegl-mesa0 libgl1-mesa-dri libstb-dev zlib1g-dev ffmpeg
TEST_PACKAGES := chromium
FUZZ_PACKAGES := clang libclang-rt-14-dev libomp-14-dev
SLURM_PACKAGES := slurmctld slurmd slurm-client munge
JOBS ?= $(shell nproc)
# Tests run two at a time: each one's OpenMP runs already use every core.
TEST_JOBS ?= 2
FUZZ_SECONDS ?= 30
FIRN := build/release/firn

.PHONY: deps test-deps fuzz-deps slurm-deps build demo test fuzz bench clean

# $(call install_missing,TARGET,PACKAGES): apt-get install those of PACKAGES not installed yet.
define install_missing
	@missing=$$(for p in $(2); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed$$' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make $(1): installing" $$missing; \
	  apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	else echo "make $(1): all packages present"; fi
endef

deps:
	$(call install_missing,deps,$(DEB_PACKAGES))

test-deps:
	$(call install_missing,test-deps,$(TEST_PACKAGES))

fuzz-deps:
	$(call install_missing,fuzz-deps,$(FUZZ_PACKAGES))

slurm-deps:
	$(call install_missing,slurm-deps,$(SLURM_PACKAGES))

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

demo: build
	$(FIRN) verify
	$(FIRN) run scenes/snowball_pair.toml --preview --render spheres --video --out out/snowball_pair
	$(FIRN) bench step --problem cube_drop --steps 50

test: build test-deps
	ctest --preset release -j $(TEST_JOBS)
	$(MAKE) fuzz

fuzz:
	@if command -v clang++ >/dev/null && ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 && \
	    ls /usr/lib/llvm-*/lib/libomp.so >/dev/null 2>&1; then \
	  cmake --preset fuzz && cmake --build --preset fuzz -j $(JOBS) && \
	  nice tests/fuzz/run_fuzz.sh build/fuzz/tests/fuzz/firn_fuzz_scene $(FUZZ_SECONDS); \
	else echo "make fuzz: skipped: no clang++ with libFuzzer and libomp (make fuzz-deps installs them)"; fi

bench: build
	build/release/bench/firn_bench_kernels

clean:
	rm -rf build
