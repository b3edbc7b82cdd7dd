# Thin entry points; the build itself is CMake (CMakePresets.json).
#   make deps   install the Debian packages the build needs (idempotent, skips what is present)
#   make demo   deps + Release build + the known-answer problems, the snowball_pair scene (preview,
#               rendered to frames/*.png and video.mp4) and the reference benchmark
#   make test   deps + Release build + the whole test suite
DEB_PACKAGES := build-essential cmake libeigen3-dev libcli11-dev libtomlplusplus-dev libgtest-dev libbenchmark-dev \
                python3 python3-vtk9 gnuplot-nox \
                libegl-dev libgl-dev libosmesa6-dev libegl-mesa0 libgl1-mesa-dri libstb-dev zlib1g-dev ffmpeg
JOBS ?= $(shell nproc)
FIRN := build/release/firn

.PHONY: deps build demo test bench clean

deps:
	@missing=$$(for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed$$' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing" $$missing; \
	  apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	else echo "make deps: all packages present"; fi

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

demo: build
	$(FIRN) verify
	$(FIRN) run scenes/snowball_pair.toml --preview --render spheres --video --out out/snowball_pair
	$(FIRN) bench step --problem cube_drop --steps 50

test: build
	ctest --preset release

bench: build
	build/release/bench/firn_bench_kernels

clean:
	rm -rf build
