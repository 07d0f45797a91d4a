# intercurve: the commands for people. CMake does the building underneath.
#   make          build (build/)
#   make test     install missing Debian packages and web/'s npm packages, build with
#                 warnings as errors, run every test (the browser test too)
#   make demo     run the main job on a bundled example (writes demo.png)
#   make gallery  draw every bundled example into docs/gallery/
#   make bench    build and run the benchmarks
#   make bench-page  the interactive page's frames per second for 100,000 points in
#                 headless Chromium (docs/plots.md)
#   make bench-peers  install OpenCASCADE and SISL, run the benchmark against them
#                 (docs/peers.md)
#   make install  install both libraries, headers, pkg-config file, CMake package and
#                 command (PREFIX)
#   make fuzz     build the libFuzzer targets with clang and run each (FUZZ_SECONDS)
#   make tsan     build with ThreadSanitizer (build-tsan/) and run the tests of threads

BUILD ?= build
PREFIX ?= /usr/local
FUZZ_SECONDS ?= 60
CMAKE_FLAGS ?=
# g++: the test that the headers work from C++ (tests/test_cxx.cpp); the
# python3 ones: the Python package's tests (docs/python.md); chromium: the
# browser test of the interactive page (tests/browser, docs/testing.md)
DEB_PACKAGES = cmake pkg-config g++ libcjson-dev libcairo2-dev libxml2-dev poppler-utils \
               python3-numpy python3-pytest python3-dask python3-distributed chromium
# node and npm for that page (three.js) and its test (playwright-core), from
# Debian only where there is no npm already (NodeSource's nodejs has its own)
WEB_DEB_PACKAGES = $(if $(shell command -v npm 2>/dev/null),,nodejs npm)
# more, for one run: .ci/run adds clang
EXTRA_DEB_PACKAGES ?=
# the peers of `make bench-peers` (docs/peers.md), never needed by the build or CI
PEER_DEB_PACKAGES = libocct-modeling-algorithms-dev libocct-modeling-data-dev \
                    libocct-foundation-dev libsisl-dev
PEERS_BUILD ?= build-peers
PEERS_TIMEOUT ?= 60
# seconds apt-get waits for a dpkg lock another install holds
APT_LOCK_WAIT ?= 600

.PHONY: all deps configure test demo gallery bench bench-page bench-peers install fuzz sanitize tsan clean

all: configure
	cmake --build $(BUILD) -j2

# Debian packages the build needs, installed only when missing. Elsewhere
# (no dpkg-query, no apt-get) nothing is installed: the list is printed and
# CMake says what it cannot find.
deps:
	@if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then \
	  echo "not a Debian system: the build needs $(DEB_PACKAGES) $(WEB_DEB_PACKAGES) $(EXTRA_DEB_PACKAGES) (or your system's equivalents)"; \
	  exit 0; \
	fi; \
	missing=""; for p in $(DEB_PACKAGES) $(WEB_DEB_PACKAGES) $(EXTRA_DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "installing:$$missing"; \
	  if [ "$$(id -u)" = 0 ]; then SUDO=""; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && $$SUDO env DEBIAN_FRONTEND=noninteractive \
	    apt-get install -y -qq -o DPkg::Lock::Timeout=$(APT_LOCK_WAIT) $$missing; \
	fi
	@# three.js and playwright-core as web/package-lock.json pins them, when
	@# web/node_modules is missing or older than the lock file (docs/plots.md)
	@if [ ! -f web/node_modules/.package-lock.json ] || \
	    [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then \
	  if command -v npm >/dev/null 2>&1; then \
	    echo "npm ci in web/"; (cd web && npm ci --no-audit --no-fund); \
	  else \
	    echo "no npm: the interactive page (.html) and its test need 'npm ci' in web/"; \
	  fi; \
	fi

configure: deps
	@test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_INSTALL_PREFIX=$(PREFIX) $(CMAKE_FLAGS)

# developers and CI: warnings are errors (IC_WERROR, docs/packaging.md)
test: configure
	cmake -S . -B $(BUILD) -DIC_WERROR=ON >/dev/null
	cmake --build $(BUILD) -j2
	cd $(BUILD) && ctest --output-on-failure -j2

sanitize:
	LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	  $(MAKE) test BUILD=build-asan CMAKE_FLAGS="-DIC_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug"

# the library's threads under ThreadSanitizer (docs/testing.md, "Threads"): a
# report of a race fails the run
TSAN_BUILD ?= build-tsan
tsan:
	cmake -S . -B $(TSAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIC_WERROR=ON \
	  -DCMAKE_C_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
	  -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread -DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread >/dev/null
	cmake --build $(TSAN_BUILD) -j2 --target test_threads test_trace_threads
	TSAN_OPTIONS=halt_on_error=1 ./$(TSAN_BUILD)/tests/test_trace_threads .
	TSAN_OPTIONS=halt_on_error=1 ./$(TSAN_BUILD)/tests/test_threads .

demo: all
	./$(BUILD)/intercurve point examples/viviani.json --at 1.5,0.8660254037844386,1 --order 4 --format text
	./$(BUILD)/intercurve point examples/viviani.json --at 2,0,0 --order 3 --format text
	./$(BUILD)/intercurve trace examples/viviani-implicit.json --format text
	./$(BUILD)/intercurve trace examples/viviani-implicit.json -o $(BUILD)/viviani-trace.json
	./$(BUILD)/intercurve trace examples/viviani-implicit.json --format vtk -o $(BUILD)/viviani-trace.vtk
	./$(BUILD)/intercurve plot examples/viviani-implicit.json -o demo.png
	@echo "Viviani's curve traced into $(BUILD)/viviani-trace.json and .vtk (ParaView), drawn in demo.png"

# the pictures of every bundled example, for the README
gallery: all
	mkdir -p docs/gallery
	for f in examples/*.json; do \
	  n=$$(basename $$f .json); \
	  ./$(BUILD)/intercurve plot $$f -o docs/gallery/$$n.png --size 1200x700 || exit 1; \
	done
	@echo "pictures in docs/gallery/"

bench: configure
	cmake -S . -B $(BUILD) -DIC_BUILD_BENCH=ON >/dev/null
	cmake --build $(BUILD) -j2
	./$(BUILD)/bench/bench_surface
	./$(BUILD)/bench/bench_local
	./$(BUILD)/bench/bench_trace examples
	./$(BUILD)/bench/bench_threads .
	./$(BUILD)/bench/bench_torture .
	./$(BUILD)/bench/bench_json examples
	./$(BUILD)/bench/bench_memory examples

bench-page: configure
	cmake -S . -B $(BUILD) -DIC_BUILD_BENCH=ON >/dev/null
	cmake --build $(BUILD) -j2 --target bench_page_trace
	node bench/bench_page.mjs $(BUILD)

# intercurve, OpenCASCADE and SISL on the same exact NURBS (docs/peers.md):
# their Debian packages installed when missing, a build of its own, the
# report on stdout and in $(PEERS_BUILD)/peers.md
bench-peers:
	$(MAKE) --no-print-directory deps EXTRA_DEB_PACKAGES="$(EXTRA_DEB_PACKAGES) $(PEER_DEB_PACKAGES)"
	cmake -S . -B $(PEERS_BUILD) -DIC_BUILD_PEERS=ON -DIC_BUILD_TESTS=OFF -DIC_BUILD_BENCH=OFF \
	  -DCMAKE_INSTALL_PREFIX=$(PREFIX) $(CMAKE_FLAGS)
	cmake --build $(PEERS_BUILD) -j2 --target bench_peers
	{ ./$(PEERS_BUILD)/bench/peers/bench_peers --timeout $(PEERS_TIMEOUT); \
	  echo $$? > $(PEERS_BUILD)/peers.status; } | tee $(PEERS_BUILD)/peers.md; \
	  exit $$(cat $(PEERS_BUILD)/peers.status)

install: all
	cmake --install $(BUILD) --prefix $(PREFIX)

fuzz: deps
	cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DIC_FUZZ=ON -DIC_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
	cmake --build build-fuzz -j2 --target fuzz_expr fuzz_problem fuzz_trace fuzz_cad fuzz_certificate
	mkdir -p fuzz/corpus/expr fuzz/corpus/problem fuzz/corpus/trace fuzz/corpus/cad fuzz/corpus/certificate
	./build-fuzz/fuzz/fuzz_expr -max_total_time=$(FUZZ_SECONDS) -max_len=256 fuzz/corpus/expr fuzz/seeds/expr
	./build-fuzz/fuzz/fuzz_problem -max_total_time=$(FUZZ_SECONDS) -max_len=4096 \
	  -dict=fuzz/problem.dict -artifact_prefix=fuzz/ fuzz/corpus/problem fuzz/seeds/problem
	./build-fuzz/fuzz/fuzz_trace -max_total_time=$(FUZZ_SECONDS) -max_len=4096 -timeout=10 \
	  -dict=fuzz/problem.dict -artifact_prefix=fuzz/ fuzz/corpus/trace fuzz/seeds/trace
	./build-fuzz/fuzz/fuzz_cad -max_total_time=$(FUZZ_SECONDS) -max_len=8192 \
	  -dict=fuzz/cad.dict -artifact_prefix=fuzz/ fuzz/corpus/cad fuzz/seeds/cad
	./build-fuzz/fuzz/fuzz_certificate -max_total_time=$(FUZZ_SECONDS) -max_len=4096 -timeout=10 \
	  -artifact_prefix=fuzz/ fuzz/corpus/certificate fuzz/seeds/certificate

clean:
	rm -rf build build-asan build-fuzz build-gcc-release build-clang-release build-peers
