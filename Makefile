# gcx — the two commands: `make demo` and `make test`. Both install what is missing first.
# Robustness (docs/testing.md): `make test-sanitize` (the suite under ASan+UBSan) and `make fuzz`.
BUILD ?= build
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
FUZZ_WORK ?= $(FUZZ_BUILD)/work
FUZZ_SECONDS ?= 60
FUZZ_JOBS ?= 1
JOBS ?= $(shell nproc)
APT_PACKAGES := antlr4 libantlr4-runtime-dev libeigen3-dev libfmt-dev libcli11-dev \
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev librapidcheck-dev libpng-dev \
  cmake g++ make time clang libclang-rt-14-dev llvm
# Optional: LinuxCNC's rs274 (the differential oracle) and chromium (renders the HTML report
# in its test); the tests that need them are skipped without them.
OPTIONAL_PACKAGES := linuxcnc-uspace chromium

.PHONY: deps build demo test bench mutate format clean test-sanitize fuzz-build fuzz fuzz-merge

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

$(SANITIZE_BUILD)/CMakeCache.txt:
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Debug -DGCX_SANITIZE=ON -DGCX_BUILD_BENCH=OFF

# The translation matrix (some 1,500 translations, each proven) runs the same code as the
# per-structure translation tests: under the sanitizers it only costs CI time.
SANITIZE_SKIP ?= ^TranslateMatrix\.

test-sanitize: deps $(SANITIZE_BUILD)/CMakeCache.txt
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ctest --output-on-failure -j $(JOBS) -E '$(SANITIZE_SKIP)'

$(FUZZ_BUILD)/CMakeCache.txt:
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ \
	  -DGCX_FUZZ=ON -DGCX_BUILD_TESTS=OFF -DGCX_BUILD_BENCH=OFF

fuzz-build: deps $(FUZZ_BUILD)/CMakeCache.txt
	cmake --build $(FUZZ_BUILD) -j $(JOBS)

# Every fuzz target for FUZZ_SECONDS, FUZZ_JOBS targets at a time; prints execs, coverage and
# corpus size per target and fails on any crash, hang (10 s) or sanitizer report.
fuzz: fuzz-build
	scripts/fuzz.sh run $(FUZZ_BUILD) $(FUZZ_WORK) $(FUZZ_SECONDS) $(FUZZ_JOBS)

# Minimises what the fuzzer found into tests/fuzz/corpus (the regression inputs).
fuzz-merge: fuzz-build
	scripts/fuzz.sh merge $(FUZZ_BUILD) $(FUZZ_WORK)

bench: build
	bench/run.sh $(BUILD)

# Mutation testing (slow, not part of `make test`): scripts/mutations.txt, docs/testing.md.
# `make mutate IDS="M01 X02"` runs only the mutations named.
mutate: deps
	scripts/mutate.sh $(IDS)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD)
