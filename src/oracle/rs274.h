// Running LinuxCNC's standalone interpreter `rs274` (Debian package linuxcnc-uspace) as an
// independent oracle: it executes RS274/NGC text and prints one canonical machining call per
// line (see canon.h for reading that output).
//
// Every run is hermetic: a private temporary directory holds the program, a freshly generated
// parameter file (rs274 rewrites it at init and exit), a generated tool table and serves as
// HOME (rs274 creates $HOME/.tool.mmap, so parallel runs must not share it). Nothing is read
// from outside the repository. Units: the rs274 standalone "machine units" are INCHES, and
// both the tool table and the parameter file are read in machine units, so every length we
// write there is divided by 25.4 (measured: `Z10` in the tool table shows up as
// USE_TOOL_LENGTH_OFFSET(... 254.0000 ...) in a G21 program, and `5221 100` in the var file as
// SET_G5X_OFFSET(1, 2540.0000, ...)).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gcx::oracle {

/// A tool for the generated tool table; lengths in mm (converted to inches on write).
struct OracleTool {
  int number = 0;        // T number; also the H number rs274 uses for G43 H<n>
  double lengthMm = 0;   // tool length offset (Z)
  double diameterMm = 0; // cutter diameter (the table's D is a diameter)
};

/// A work offset to preload through the parameter file (so the program text stays unchanged).
struct OracleWorkOffset {
  int index = 1; // 1..9 = G54, G55, ... G59, G59.1, G59.2, G59.3
  Eigen::Vector3d offsetMm = Eigen::Vector3d::Zero();
  double rotationDeg = 0; // G10 L2 R (XY rotation about the work origin)
};

struct Rs274Options {
  /// Prefix every line with N<lineno> (1-based) so each canonical call carries its source
  /// line; an N word already at the start of a line is replaced. See numberLines().
  bool numberLines = true;
  std::vector<OracleTool> tools;
  std::vector<OracleWorkOffset> workOffsets;
  double timeoutSeconds = 20;
  /// rs274 executable: an absolute path, or a name looked up in PATH.
  std::string executable = "rs274";
  /// Keep the temporary directory (for debugging); its path is returned in Rs274Result.
  bool keepWorkDir = false;
};

struct Rs274Result {
  int exitCode = -1;      // rs274's exit status (0 ok, 1 interpreter error); -1: not run
  bool timedOut = false;  // killed after Rs274Options::timeoutSeconds
  int signal = 0;         // terminating signal, if any
  std::string stderrText; // rs274's diagnostics ("executing", message, failing block)
  std::string stdoutText; // normally empty (the canon goes to the output file)
  std::vector<std::string> canonLines; // the output file, one canonical call per element
  std::string error;                   // set when we could not run rs274 at all
  std::string workDir;                 // only when keepWorkDir

  bool ok() const { return error.empty() && !timedOut && signal == 0 && exitCode == 0; }
  /// One line for failure messages: exit code / timeout / error and the stderr text.
  std::string summary() const;
};

/// Full path of the rs274 executable (an absolute path is checked as is, a bare name is
/// looked up in PATH), or nullopt.
std::optional<std::string> findRs274(const std::string& executable = "rs274");
/// True when rs274 can be run here.
bool rs274Available();

/// The source-line mapping trick (refs README §3.1): rs274 echoes only N words, so every line
/// gets `N<lineno>` in front (after a leading block-delete `/`); an existing leading N word is
/// replaced (rs274 rejects two N words). `%` demarcation lines are left alone (rs274 rejects
/// `N1 %`). Line numbers are 1-based and rs274 accepts them beyond 99999 (measured with
/// N99999999).
std::string numberLines(std::string_view program);

/// The tool table text: `T<n> P<n> D<diameter in> Z<length in> ;` per tool.
std::string toolTableText(const std::vector<OracleTool>& tools);
/// The parameter (var) file text: #5220 = 1 (G54 active) and the given work offsets (#5221+20k
/// .. #5223+20k in inches, #5230+20k rotation in degrees), sorted by parameter number.
std::string parameterFileText(const std::vector<OracleWorkOffset>& offsets);

/// Runs rs274 on programs; one object may be used for many runs, also from several threads.
class Rs274 {
public:
  explicit Rs274(Rs274Options options = {}) : options_(std::move(options)) {}
  const Rs274Options& options() const { return options_; }

  /// Runs `rs274 -g -t tool.tbl -v p.var in.ngc out.canon < /dev/null` in a fresh private
  /// directory with HOME set to it, kills it after the timeout.
  Rs274Result run(std::string_view program) const;

private:
  Rs274Options options_;
};

} // namespace gcx::oracle
