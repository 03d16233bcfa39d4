# stairmap — top-level entry points. `make demo` and `make test` work from a fresh clone on Debian 12:
# they install the missing Debian packages first (with sudo when not root).

BUILD_DIR  ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
STAIRMAP   := $(BUILD_DIR)/bin/stairmap
DEMO_OUT   ?= $(BUILD_DIR)/demo

DEB_PACKAGES := cmake make g++ \
	libmrpt-obs-dev libmrpt-maps-dev libmrpt-io-dev libmrpt-config-dev libmrpt-poses-dev \
	libmrpt-system-dev libmrpt-serialization-dev libmrpt-opengl-dev libmrpt-img-dev \
	liboctomap-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev \
	nlohmann-json3-dev libcli11-dev zlib1g-dev

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test bench clean

all: build

deps:
	@missing=""; \
	for p in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "stairmap: installing missing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
	fi

$(BUILD_DIR)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

configure: deps $(BUILD_DIR)/CMakeCache.txt

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: replay the bundled two-floor building sequence into a staircase landmark map, then
# export it for planners (floor graph, floor maps, Spot staircases) for the three robot presets.
demo: build
	$(STAIRMAP) map datasets/two_floor/two_floor.rawlog --poses datasets/two_floor/poses.tum \
	  --config config/sim_legged_vlp16.ini --out $(DEMO_OUT)/two_floor
	@echo "stairmap: demo outputs in $(DEMO_OUT)/two_floor (landmarks.json, map.bt, scene.3Dscene, overview.png, ...)"
	$(STAIRMAP) export $(DEMO_OUT)/two_floor --robot config/robots/tracked.ini \
	  --robot config/robots/quadruped.ini --robot config/robots/scout.ini --out $(DEMO_OUT)/two_floor/export
	$(STAIRMAP) detect datasets/clouds/ascending_0.pcd.gz --robot-height 0.35

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

bench: build
	@for b in $(BUILD_DIR)/bin/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2 || exit 1; done

clean:
	rm -rf $(BUILD_DIR)
