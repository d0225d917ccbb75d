# Thin wrapper over the CMake presets. Every target installs its own dependencies first.
JOBS ?= 2
# Extra cache settings for the release configure, e.g. CMAKE_ARGS=-DCMAKE_UNITY_BUILD=ON
# (what CI uses: a clean build in about half the compile time, but a one-file change
# recompiles its whole batch, so it is not the default for working trees).
CMAKE_ARGS ?=
BUILD := build/release
TAILOR := $(BUILD)/tailor

.PHONY: deps build demo test bench asan fuzz docs clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake --preset release $(CMAKE_ARGS) >/dev/null
	@cmake --build --preset release -j $(JOBS)

## The main job: the arm-sleeve simulation (no input needed): OBJ frames, contact files,
## a rendered PNG of every frame and a contact sheet (out/sleeve/contact_sheet.png).
demo: build
	$(TAILOR) simulate --out out/sleeve --render

## Release build + every test suite.
test: build
	ctest --preset release

## Google Benchmark micro-benchmarks.
bench: build
	@for b in $(BUILD)/bench/tailor_bench_*; do echo "== $$b"; $$b; done

## AddressSanitizer + UndefinedBehaviorSanitizer build and tests.
asan: deps
	@cmake --preset asan >/dev/null
	@cmake --build --preset asan -j $(JOBS)
	ctest --preset asan

## libFuzzer targets (clang++, ASan + UBSan): build, then run each for FUZZ_SECONDS,
## FUZZ_JOBS at a time (fuzz/README.md).
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 2
FUZZ_TARGETS ?= ply obj scene_json observers_json ccd_queries mesh_round_trip detector
fuzz:
	@scripts/install-deps.sh --fuzz
	@cmake --preset fuzz >/dev/null
	@cmake --build --preset fuzz -j $(JOBS)
	@scripts/run-fuzzers.sh $(FUZZ_SECONDS) $(FUZZ_JOBS) $(FUZZ_TARGETS)

## Doxygen API reference of the public headers (build/docs/html/index.html); fails on
## any Doxygen warning, e.g. an undocumented public declaration (scripts/check-docs.sh).
docs: deps
	@scripts/check-docs.sh

clean:
	rm -rf build
