# Thin wrapper over the CMake presets. Every target installs its own dependencies first.
JOBS ?= 2
BUILD := build/release
TAILOR := $(BUILD)/tailor

.PHONY: deps build demo test bench asan clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake --preset release >/dev/null
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

clean:
	rm -rf build
