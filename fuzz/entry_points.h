// The fuzz targets' entry points: one input in, bounded work out, no file written outside a
// private temporary folder. The libFuzzer drivers (fuzz/*_fuzzer.cpp) and the corpus replay test
// (tests/fuzz/) call the same functions, so a saved input replays exactly.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gcx::fuzz {

/// What one input did. `violation` names a broken property (the drivers abort on it).
struct Outcome {
  std::size_t errors = 0;
  std::string firstError; // "line:col CODE"
  std::size_t outputBytes = 0;
  bool capped = false; // stopped by the harness's motion/output cap, not by the program
  std::string violation;
};

/// The harness's bounds: small limits so a runaway program costs milliseconds, not minutes.
struct Bounds {
  static constexpr std::size_t maxErrors = 50;
  static constexpr std::uint64_t maxJumps = 1'000;
  static constexpr std::uint64_t maxBlocks = 20'000;
  static constexpr std::uint64_t maxMoves = 1'000;
  // the harness's own cap, for events that are not moves (modal changes, dwells)
  static constexpr std::size_t maxEvents = 2'000;
  static constexpr std::size_t maxOutputBytes = 256 << 10;
};

/// `gcx check`: the dialect's front end (block reader, fast parser, grammar) and the static
/// checks, from memory. Property: every error is located in the input.
Outcome checkProgram(const std::string& dialect, std::string_view input);

/// `gcx expand --to canonical`: macro pass, interpreter and canonical emitter on the input as
/// program O0001 of the dialect. Lines `@@` split the input into further files O9001, O9002, ...
/// of the same folder (M98 P9001 calls them); the folder is private and emptied before each run.
Outcome expandCanonical(const std::string& dialect, std::string_view input);

/// `gcx fmt` round trip. Property: an input that parses without error prints to text that parses
/// without error to the same IR.
Outcome fmtRoundTrip(const std::string& dialect, std::string_view input);

/// `gcx translate` of the input (a program of the dialect, split at `@@` lines as for
/// expandCanonical) to every other target, each proven by gcx itself (no rs274). Property: a
/// translation that exits 0 wrote its file, one that fails (refused, or its proof found a
/// difference) wrote none. `firstError` names the first failure ("differs: canonical").
Outcome translateToEveryTarget(const std::string& dialect, std::string_view input);

/// The setup JSON reader (`--setup`). Property: errors are located in the input.
Outcome readSetup(std::string_view input);

/// The fuzz targets by name: check_<d>, expand_<d> and fmt_<d> for every dialect d of the
/// registry, translate_nct and setup_json; the names of the corpus folders
/// (tests/fuzz/corpus/<name>) and of GCX_FUZZ_TARGET, which picks the fuzz executable's target.
const std::vector<std::string>& targetNames();
/// The file extension of the programs that seed the named target (".nct", ".json").
const std::string& seedExtension(std::string_view target);
/// Runs the named target on one input; aborts on an unknown name.
Outcome runTarget(std::string_view target, std::string_view input);

} // namespace gcx::fuzz
