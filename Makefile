# gcx — the two commands: `make demo` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= $(shell nproc)
APT_PACKAGES := antlr4 libantlr4-runtime-dev libeigen3-dev libfmt-dev libcli11-dev \
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev librapidcheck-dev libpng-dev \
  cmake g++ make time
# Optional: LinuxCNC's rs274 (the differential oracle) and chromium (renders the HTML report
# in its test); the tests that need them are skipped without them.
OPTIONAL_PACKAGES := linuxcnc-uspace chromium

.PHONY: deps build demo test bench mutate format clean

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

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

bench: build
	bench/run.sh $(BUILD)

# Mutation testing (slow, not part of `make test`): scripts/mutations.txt, docs/testing.md.
# `make mutate IDS="M01 X02"` runs only the mutations named.
mutate: deps
	scripts/mutate.sh $(IDS)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h')

clean:
	rm -rf $(BUILD)
