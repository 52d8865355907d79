// The gcx subcommands. Each returns the process exit code: 0 ok, 1 the program has errors,
// 2 usage or I/O error.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gcx::cli {

enum Exit { Ok = 0, ProgramErrors = 1, UsageError = 2 };

struct CommonOptions {
  std::string dialect;  // empty: from the file extension
  std::string encoding; // --encoding: empty: the dialect's own
  bool json = false;    // diagnostics as JSON
  std::size_t maxErrors = 50;
  // execution (expand, run, plot)
  std::vector<std::string> libraryDirs; // --lib: where M98 P / G65 P look after the folder
  // Runaway limits (docs/limits.md): each stops a runaway within seconds on a small machine
  // while the bench programs (1,000,000 blocks, 100,000 G83 holes) run with them.
  std::uint64_t maxJumps = 1'500'000;   // --max-jumps: backward jumps and L repeats of calls
  std::uint64_t maxBlocks = 20'000'000; // --max-blocks: blocks the expansion pass executes
  std::uint64_t maxMoves = 10'000'000;  // --max-moves: rapids, feeds, arc turns
  // --max-output: bytes of all outputs together; 0 (the default) is automatic: 256 MiB, or 32
  // bytes written per byte of the main program when that is more, so a long CAM program is never
  // refused while an amplifying loop or repeat still stops within seconds
  std::uint64_t maxOutput = 0;
  int maxDepth = 16;             // --max-depth: nested calls (the manual's 16)
  std::string printFile;         // --print: DPRNT output (default: standard output)
  bool fanucVacantOrder = false; // --vacant-order fanuc (nct-macro.md §12 Q1)
  unsigned jobs = 1;             // --jobs: 2 reads on its own thread (the default on 2+ cores)
  bool keepCompensation = false; // expand --keep comp: G41/G42 stay for the target
};

struct ExpandOptions {
  CommonOptions common;
  std::string to;
  /// What to flatten for a dialect target; empty (gcx expand's default): what the target cannot
  /// keep (a dialect without variables keeps its calls and repeats as written).
  std::string expand = "macros,subprograms";
  std::string keep;   // --keep cycles | comp: structure the target keeps
  std::string output; // empty: standard output
  std::string setup;
  bool provenance = false;
};
struct RunOptions {
  CommonOptions common;
  std::string setup;
  std::string trace;
  bool stats = false;
  std::string frame = "machine"; // of the trace (machine, work or program); stats: machine
};
struct PlotOptions {
  CommonOptions common;
  std::string setup;
  std::string output;
  std::string view = "xy";
  std::string frame = "work"; // work, program or machine
};

struct EquivCommandOptions {
  CommonOptions common;
  std::string setup;  // both programs
  std::string setupB; // B's own
  double tolerance = 0.001;
  bool strictRapids = false;
  std::string rs274 = "rs274"; // --rs274: the executable reading .ngc programs
  std::string report;          // --report: the HTML page (docs/equivalence.md), empty: none
};

struct TranslateOptions {
  CommonOptions common; // common.dialect: --from
  std::string to;
  std::string output; // a file, or the folder of a batch; empty: standard output
  std::string setup;
  bool verify = true;        // --no-verify: write without the equivalence proof
  std::string expand;        // --expand: what the translation may not keep ("cycles,loops", "all")
  bool writeOffsets = false; // --write-offsets: ngc sets the setup's work offsets by G10 L2
  double tolerance = 0.001;
  std::string rs274 = "rs274";
  unsigned batchJobs = 2; // --jobs of a batch: translations at once
};

int runCheck(const std::vector<std::string>& files, const CommonOptions& opt);
int runFmt(const std::string& file, const std::string& output, const CommonOptions& opt);
int runDumpIr(const std::string& file, const CommonOptions& opt);
int runExpand(const std::string& file, const ExpandOptions& opt);
int runRun(const std::string& file, const RunOptions& opt);
int runPlot(const std::string& file, const PlotOptions& opt);
int runEquiv(const std::string& a, const std::string& b, const EquivCommandOptions& opt);
/// A file, or every program of a folder tree (cli/translate_batch.h).
int runTranslate(const std::string& input, const TranslateOptions& opt);

} // namespace gcx::cli
