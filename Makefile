# Two commands from a fresh Debian 12 machine:
#   make demo   install missing packages, configure, build, run the default job
#   make test   the same, then every test
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release
# The compiler: clang++ when installed (scripts/install-deps.sh installs it),
# else the system c++. Clang compiles vivp's Jet-heavy templates in about
# two thirds of GCC's time, which keeps .ci/run (two full builds on two
# cores) within its budget; the code is warning-clean under both.
# Override with `make test VIVP_CXX=g++`.
VIVP_CXX ?=

.PHONY: all deps configure build demo test figures bench format clean

all: build

# `make test` also installs OpenMPI and FFTW-MPI and so builds and tests the
# march across ranks; `make demo` runs on one process without them.
DEPS_FLAGS ?=
test: DEPS_FLAGS = --distributed

deps:
	@bash scripts/install-deps.sh $(DEPS_FLAGS)

configure: deps
	@cxx="$(VIVP_CXX)"; [ -n "$$cxx" ] || cxx=$$(command -v clang++ || command -v c++); \
	cmake -S . -B $(BUILD) -DCMAKE_CXX_COMPILER="$$cxx" $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS) -- --no-print-directory

# The demo needs only the command line program: the tests, figures and
# benches are built by `make test`, `make figures` and `make bench`.
demo: configure
	@cmake --build $(BUILD) -j $(JOBS) --target vivp -- --no-print-directory
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
