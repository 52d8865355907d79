# gcx — the two commands: `make demo` and `make test`. Both install what is missing first.
# Robustness (docs/testing.md): `make test-sanitize` (the suite under ASan+UBSan) and `make fuzz`,
# both from one clang build with the sanitizers and libFuzzer's coverage instrumentation.
BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
FUZZ_WORK ?= $(SANITIZE_BUILD)/work
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
JOBS ?= $(shell nproc)
APT_PACKAGES := antlr4 libantlr4-runtime-dev libeigen3-dev libfmt-dev libcli11-dev \
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev librapidcheck-dev libpng-dev \
  cmake g++ make time clang libclang-rt-14-dev llvm ccache
# Optional: LinuxCNC's rs274 (the differential oracle) and chromium (renders the HTML report
# in its test); the tests that need them are skipped without them.
OPTIONAL_PACKAGES := linuxcnc-uspace chromium

.PHONY: deps build demo test bench mutate format clean sanitize-build test-sanitize fuzz-build fuzz \
  fuzz-merge

deps:
	@scripts/install-deps.sh $(APT_PACKAGES) -- $(OPTIONAL_PACKAGES)

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	@echo "== gcx check: syntax and static checks"
	$(BUILD)/gcx check examples/nct/O1001.nct
	@echo "== gcx expand --to canonical: flat RS274/NGC in the machine frame (offsets from the setup)"
	$(BUILD)/gcx expand examples/nct/O1001.nct --to canonical --setup examples/nct/O1001.setup.json --provenance
	@echo "== gcx run --stats: the interpreter's path length, time and bounds"
	$(BUILD)/gcx run examples/nct/O1001.nct --setup examples/nct/O1001.setup.json --stats
	@echo "== canned cycles: G71.7 roughing passes and G70.7 finishing of a mill-turn example"
	$(BUILD)/gcx expand examples/nct/O1010.nct --to canonical --setup examples/nct/O1010.setup.json --provenance
	@echo "== gcx plot: the tool path as SVG"
	$(BUILD)/gcx plot examples/nct/O1001.nct --setup examples/nct/O1001.setup.json -o $(BUILD)/O1001.svg
	@echo "wrote $(BUILD)/O1001.svg"
	@echo "== gcx equiv: the canonical output moves the tool exactly like the program"
	$(BUILD)/gcx expand examples/nct/O1001.nct --to canonical --setup examples/nct/O1001.setup.json -o $(BUILD)/O1001.ngc
	$(BUILD)/gcx equiv examples/nct/O1001.nct $(BUILD)/O1001.ngc --setup examples/nct/O1001.setup.json --setup-b none --report $(BUILD)/O1001-equiv.html
	@echo "wrote $(BUILD)/O1001-equiv.html"

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# Every sanitizer finding is fatal and prints its stack.
export UBSAN_OPTIONS ?= print_stacktrace=1

# One clang build serves the sanitizer suite and the fuzzer: ASan+UBSan (-O1 -g) with libFuzzer's
# coverage instrumentation, the test binary in SANITIZE_SHARDS gtest shards (a process per test
# costs the instrumented build more than most tests), the fuzz executable beside it.
SANITIZE_SHARDS ?= 8
# The translation matrix (some 1,500 translations, each proven) runs the same code as the
# per-structure translation tests: under the sanitizers it only costs CI time.
SANITIZE_FILTER ?= -TranslateMatrix.*

$(SANITIZE_BUILD)/CMakeCache.txt:
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
	  -DGCX_SANITIZE=ON -DGCX_FUZZ=ON -DGCX_BUILD_BENCH=OFF \
	  -DGCX_TEST_SHARDS=$(SANITIZE_SHARDS) '-DGCX_TEST_SHARD_FILTER=$(SANITIZE_FILTER)'

sanitize-build: deps $(SANITIZE_BUILD)/CMakeCache.txt
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)

test-sanitize: sanitize-build
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS)

fuzz-build: deps $(SANITIZE_BUILD)/CMakeCache.txt
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target gcx_fuzz

# Every fuzz target (or those of FUZZ_TARGETS; FUZZ_SKIP: names to leave out) for FUZZ_SECONDS,
# FUZZ_JOBS targets at a time;
# prints execs, coverage and corpus size per target and fails on any crash, hang (10 s) or
# sanitizer report.
fuzz: fuzz-build
	FUZZ_SKIP="$(FUZZ_SKIP)" scripts/fuzz.sh run $(SANITIZE_BUILD) $(FUZZ_WORK) $(FUZZ_SECONDS) \
	  $(FUZZ_JOBS) $(FUZZ_TARGETS)

# Minimises what the fuzzer found into tests/fuzz/corpus (the regression inputs).
fuzz-merge: fuzz-build
	scripts/fuzz.sh merge $(SANITIZE_BUILD) $(FUZZ_WORK) $(FUZZ_TARGETS)

bench: build
	bench/run.sh $(BUILD)

# Mutation testing (slow, not part of `make test`): scripts/mutations.txt, docs/testing.md.
# `make mutate IDS="M01 X02"` runs only the mutations named.
mutate: deps
	scripts/mutate.sh $(IDS)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD)
