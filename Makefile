# SPDX-License-Identifier: GPL-3.0-or-later
# Convenience wrapper around CMake/CTest. Plain CMake works too:
#   cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build
BUILD     ?= build
JOBS      ?= $(shell nproc)
WERROR    ?= OFF
BUILD_TYPE ?= Release
CTEST_ARGS ?=
ASAN_BUILD ?= build-asan
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
FUZZ_TARGETS = fuzz_json_text fuzz_job fuzz_study fuzz_series fuzz_particle_files fuzz_result

.PHONY: all deps test-deps configure configure-app build build-app test test-unit test-sanitize fuzz demo bench bench-quick clean install deb

all: build

deps:
	@scripts/install-deps.sh

test-deps:
	@scripts/install-deps.sh test

configure: test-deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DGRIDFREE_WERROR=$(WERROR) \
	  -DGRIDFREE_BUILD_TESTS=ON -DGRIDFREE_BUILD_BENCH=ON >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Only what the demo runs: the two executables, without the test suite, the
# benchmarks or the test-only packages (docs/BENCHMARKS.md "Build and CI time").
configure-app: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DGRIDFREE_WERROR=$(WERROR) \
	  -DGRIDFREE_BUILD_TESTS=OFF -DGRIDFREE_BUILD_BENCH=OFF >/dev/null

build-app: configure-app
	@cmake --build $(BUILD) -j $(JOBS) --target gridfree gridfree-worker

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

test-unit: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L unit

# Unit and integration tests under AddressSanitizer + UndefinedBehaviorSanitizer
# (GCC, -g1; -O1 for the numeric modules, -O0 for the rest); verification
# tests are neither built nor run there (minutes of numerics, no new paths).
# Nor are the tests that time a real Slurm cluster or the worker against
# itself, count SQLite steps of large studies, print or render through
# Chromium, or solve a dump ensemble end to end (SANITIZE_EXCLUDE,
# docs/LIMITS.md): their code paths run there through the fake-sbatch,
# timeout, report and ensemble tests.
SANITIZE_EXCLUDE ?= ^(SlurmCluster\.|RunTimeoutResume\.|SchedulerCost\.|ReportPrint\.|ReportRender\.Chromium|ReportRenderEnsembles\.|DumpEnsembleCli\.)
test-sanitize: test-deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Release -DGRIDFREE_SANITIZE=ON -DGRIDFREE_BUILD_BENCH=OFF \
	  -DGRIDFREE_BUILD_VERIFICATION_TESTS=OFF >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	@cd $(ASAN_BUILD) && OMP_WAIT_POLICY=passive ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j $(JOBS) -L 'unit|integration' \
	  $(if $(SANITIZE_EXCLUDE),-E '$(SANITIZE_EXCLUDE)') $(CTEST_ARGS)

# Each libFuzzer target for FUZZ_SECONDS on its corpus (fuzz/corpus/<name>,
# read only; new inputs go to $(FUZZ_BUILD)/corpus). Needs clang.
fuzz:
	@scripts/install-deps.sh fuzz
	@CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Release -DGRIDFREE_FUZZ=ON \
	  -DGRIDFREE_BUILD_TESTS=OFF -DGRIDFREE_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(FUZZ_BUILD) -j $(JOBS) --target $(FUZZ_TARGETS)
	@set -e; for t in $(FUZZ_TARGETS); do \
	  name=$${t#fuzz_}; mkdir -p $(FUZZ_BUILD)/corpus/$$name fuzz/corpus/$$name; \
	  echo "== $$t: $(FUZZ_SECONDS) s"; \
	  rc=0; $(FUZZ_BUILD)/bin/$$t -max_total_time=$(FUZZ_SECONDS) -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
	    -artifact_prefix=$(FUZZ_BUILD)/$$name- -print_final_stats=1 \
	    $(FUZZ_BUILD)/corpus/$$name fuzz/corpus/$$name >$(FUZZ_BUILD)/$$name.log 2>&1 || rc=$$?; \
	  grep -a -E "ERROR|SUMMARY|stat::number_of_executed_units|Test unit written" $(FUZZ_BUILD)/$$name.log | tail -4; \
	  [ $$rc -eq 0 ] || { echo "$$t failed (exit $$rc): see $(FUZZ_BUILD)/$$name.log"; exit 1; }; \
	done

demo: build-app
	@$(BUILD)/bin/gridfree run studies/quickstart.json --db gridfree.sqlite; status=$$?; \
	  echo "Report: $(CURDIR)/reports/quickstart/report.html (and report.md)"; \
	  echo "Database: $(CURDIR)/gridfree.sqlite"; exit $$status

# `make install PREFIX=P`: the executables, studies, documents, man pages,
# completion and Lmod module file under P (docs/INSTALL.md). Needs no root
# when P is writable, and installs no package: an unconfigured $(BUILD) is
# configured with what CMake finds (CMAKE_PREFIX_PATH, pkg-config).
PREFIX ?= /usr/local
install:
	@test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) \
	  -DGRIDFREE_BUILD_TESTS=OFF -DGRIDFREE_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target gridfree gridfree-worker cli_docs
	@cmake --install $(BUILD) --prefix $(PREFIX)

# `make deb`: $(BUILD)/gridfree_<version>_<arch>.deb (cmake/Packaging.cmake),
# from $(BUILD) as it is configured (else configured without tests); CPack
# builds whatever that build tree builds before packaging.
deb:
	@scripts/install-deps.sh deb
	@test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) \
	  -DGRIDFREE_BUILD_TESTS=OFF -DGRIDFREE_BUILD_BENCH=OFF >/dev/null
	@cd $(BUILD) && cpack -G DEB

bench: build
	@bench/run.sh $(BUILD)/bin

bench-quick: build
	@bench/run.sh $(BUILD)/bin --quick

clean:
	@rm -rf $(BUILD) $(ASAN_BUILD) $(FUZZ_BUILD)
