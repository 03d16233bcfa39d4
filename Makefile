# stairmap — top-level entry points. `make demo` and `make test` work from a fresh clone on Debian 12:
# they install the missing Debian packages first (with sudo when not root).

BUILD_DIR  ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
STAIRMAP   := $(BUILD_DIR)/bin/stairmap
SAN_DIR    ?= build-sanitize
FUZZ_DIR   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := fuzz_cloud fuzz_cloud_gz fuzz_rawlog fuzz_landmarks_json fuzz_gt_json fuzz_ini fuzz_tum
DEMO_OUT   ?= $(BUILD_DIR)/demo

DEB_PACKAGES := cmake make g++ \
	libmrpt-obs-dev libmrpt-maps-dev libmrpt-io-dev libmrpt-config-dev libmrpt-poses-dev \
	libmrpt-system-dev libmrpt-serialization-dev libmrpt-opengl-dev libmrpt-img-dev \
	liboctomap-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev \
	nlohmann-json3-dev libcli11-dev zlib1g-dev cyclonedds-dev cyclonedds-tools \
	libmrpt-gui-dev libmrpt-hwdrivers-dev xvfb xdotool x11-apps imagemagick ffmpeg mrpt-apps \
	clang-14 libclang-rt-14-dev

# Sanitizer settings: leaks are findings; UBSan prints a stack. The only suppressions are for
# third-party code, each explained in the file.
SAN_ASAN_OPTIONS  := detect_leaks=1:strict_init_order=1
SAN_LSAN_OPTIONS  := suppressions=$(CURDIR)/.ci/lsan.supp:print_suppressions=0
SAN_UBSAN_OPTIONS := print_stacktrace=1:halt_on_error=1:suppressions=$(CURDIR)/.ci/ubsan.supp

SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: all deps configure build demo test test-sanitize fuzz fuzz-build bench eval clean

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

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer (gcc, like MRPT): any finding
# aborts the test that triggered it. -O1 -g1 keeps the build affordable on two cores.
test-sanitize: deps
	cmake -S . -B $(SAN_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
	  -DSTAIRMAP_SANITIZE=ON -DSTAIRMAP_BUILD_BENCH=OFF
	cmake --build $(SAN_DIR) -j $(JOBS)
	cd $(SAN_DIR) && ASAN_OPTIONS=$(SAN_ASAN_OPTIONS) LSAN_OPTIONS=$(SAN_LSAN_OPTIONS) \
	  UBSAN_OPTIONS=$(SAN_UBSAN_OPTIONS) \
	  ctest --output-on-failure -j $(JOBS)

# libFuzzer drivers (fuzz/, clang) over the seed corpora; each target runs FUZZ_SECONDS seconds.
fuzz-build: deps
	CXX=clang++-14 cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
	  -DSTAIRMAP_BUILD_FUZZ=ON -DSTAIRMAP_BUILD_TESTS=OFF -DSTAIRMAP_BUILD_BENCH=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target $(FUZZ_TARGETS)

fuzz: fuzz-build
	fuzz/run-all $(FUZZ_DIR) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

bench: build
	@for b in $(BUILD_DIR)/bin/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2 || exit 1; done

# Randomised detector benchmark (issue 10; outside `make test`): a dev and a separate check set drawn
# by `stairmap sim --random`, cached in $(EVAL_DIR)/<set>-seed<S>-n<N>-v<generator version> (a rerun
# reuses a complete set), then the per-family table of `stairmap eval --detect` for each; the full
# reports (misses, false positives) go to <set dir>.eval.txt, a breakdown by sensor kind to
# <set dir>.sensors.txt. Then the "all" row of each set in a few perturbed realisations (every
# coordinate moved by up to EVAL_PERTURB_M, far below sensor noise): how far the scores move
# between them is the evaluation's noise floor (docs/detector.md); reports in <set dir>.perturb<S>.txt.
EVAL_DIR        ?= $(BUILD_DIR)/eval
EVAL_N          ?= 300
EVAL_DEV_SEED   ?= 1001
EVAL_CHECK_SEED ?= 2002
EVAL_JOBS       ?= 2
EVAL_PERTURB_M  ?= 0.00001
EVAL_PERTURB_SEEDS ?= 1 2 3

eval: build
	@ver=$$($(STAIRMAP) sim --random-version) || exit 1; \
	for set in dev:$(EVAL_DEV_SEED) check:$(EVAL_CHECK_SEED); do \
	  name=$${set%%:*}; seed=$${set##*:}; dir=$(EVAL_DIR)/$$name-seed$$seed-n$(EVAL_N)-v$$ver; \
	  if [ ! -f $$dir/.complete ]; then \
	    rm -rf $$dir; \
	    $(STAIRMAP) sim --random $(EVAL_N) --seed $$seed --jobs $(EVAL_JOBS) --out $$dir -q || exit 1; \
	    touch $$dir/.complete; \
	  else echo "stairmap: reusing $$dir"; fi; \
	  $(STAIRMAP) eval --detect $$dir > $$dir.eval.txt || exit 1; \
	  $(STAIRMAP) eval --detect $$dir --group-by sensor_kind > $$dir.sensors.txt || exit 1; \
	  echo "== $$name set (seed $$seed, $(EVAL_N) scenes, generator v$$ver): current detector"; \
	  sed -n '1,/^false positives on true flights/p' $$dir.eval.txt; \
	  echo "-- by sensor kind"; sed -n '3,/^all /p' $$dir.sensors.txt; \
	  echo "-- perturbed realisations (every coordinate moved by up to $(EVAL_PERTURB_M) m)"; \
	  for ps in $(EVAL_PERTURB_SEEDS); do \
	    $(STAIRMAP) eval --detect $$dir --perturb-m $(EVAL_PERTURB_M) --perturb-seed $$ps > $$dir.perturb$$ps.txt || exit 1; \
	    printf 'seed %s  ' $$ps; grep '^all ' $$dir.perturb$$ps.txt; \
	  done; \
	done

clean:
	rm -rf $(BUILD_DIR)
