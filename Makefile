# Convenience wrapper around CMake/CTest. Plain CMake works too:
#   cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build
BUILD     ?= build
JOBS      ?= $(shell nproc)
WERROR    ?= OFF
BUILD_TYPE ?= Release
CTEST_ARGS ?=

.PHONY: all deps test-deps configure build test test-unit demo bench bench-quick clean

all: build

deps:
	@scripts/install-deps.sh

test-deps:
	@scripts/install-deps.sh test

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) -DGRIDFREE_WERROR=$(WERROR) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: test-deps build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

test-unit: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L unit

demo: build
	@$(BUILD)/bin/gridfree run studies/quickstart.json --db gridfree.sqlite; status=$$?; \
	  echo "Report: $(CURDIR)/reports/quickstart/report.html (and report.md)"; \
	  echo "Database: $(CURDIR)/gridfree.sqlite"; exit $$status

bench: build
	@bench/run.sh $(BUILD)/bin

bench-quick: build
	@bench/run.sh $(BUILD)/bin --quick

clean:
	@rm -rf $(BUILD)
