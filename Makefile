# Two commands from a fresh Debian 12 machine:
#   make demo   install missing packages, configure, build, run the default job
#   make test   the same, then every test
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release

.PHONY: all deps configure build demo test figures bench format clean

all: build

deps:
	@bash scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS) -- --no-print-directory

demo: build
	./$(BUILD)/apps/vivp run --out $(BUILD)/demo --force

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

figures: build
	@cmake --build $(BUILD) --target figures

bench: build
	@cmake --build $(BUILD) --target bench

format:
	@git ls-files '*.h' '*.cc' | xargs clang-format -i

clean:
	rm -rf $(BUILD)
