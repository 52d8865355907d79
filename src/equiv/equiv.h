// `gcx equiv`: whether two programs, in any dialect gcx reads, move the tool the same
// (docs/equivalence.md). Each program runs in its own thread, gcx's interpreter for the
// dialects gcx reads and LinuxCNC's `rs274` for RS274/NGC, feeding a bounded queue; the
// comparison walks both event streams as they come, so memory does not grow with the program.
// `gcx translate --verify` calls the same check.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.h"
#include "equiv/result.h"
#include "equiv/walker.h"
#include "machine/setup.h"

namespace gcx::equiv {

/// A program on gcx's side of a comparison: opened and run by the caller's machinery (the
/// command line's session, its options and limits), so this folder depends on none of it.
class GcxProgram {
public:
  virtual ~GcxProgram() = default;
  /// Opens the program and its machine setup (empty: defaults); false when it cannot, with the
  /// problem printed. `canonicalSubset`: an RS274/NGC file gcx reads as canonical motion.
  virtual bool open(const std::string& path, const std::string& setup, bool canonicalSubset) = 0;
  virtual FileId file() const = 0;
  virtual const machine::Setup& setup() const = 0;
  virtual const SourceManager& sources() const = 0;
  virtual diag::Engine& diags() = 0;
  /// Runs the whole program into the sink; false on an error (in diags()).
  virtual bool run(motion::Sink& sink) = 0;
};

struct ProgramInput {
  std::string path;
  std::string setup; // machine setup (JSON, machine/setup.h); empty: defaults
  /// Auto: `.ngc` through rs274 when it is installed, else gcx's reading of the canonical
  /// subset; everything else through gcx's interpreter.
  enum class Reader { Auto, Gcx, Rs274 } reader = Reader::Auto;
};

struct EquivOptions {
  WalkOptions walk;
  /// Makes the gcx side's program (with the caller's options: --lib, limits, ...).
  std::function<std::unique_ptr<GcxProgram>()> gcxProgram;
  /// Makes B's program when it differs from A's (a translation read in its own dialect while
  /// --from names the source's); empty: gcxProgram.
  std::function<std::unique_ptr<GcxProgram>()> gcxProgramB;
  std::string rs274 = "rs274"; // executable: a path, or a name looked up in PATH
  double rs274TimeoutSeconds = 600;
  motion::Sink* tapA = nullptr; // receives every event of A, on A's thread
  motion::Sink* tapB = nullptr;
};

/// One program as it was read: its name, sources (for provenance and excerpts) and
/// diagnostics.
class ProgramSide {
public:
  virtual ~ProgramSide() = default;
  virtual const std::string& name() const = 0;
  virtual const SourceManager& sources() const = 0;
  virtual const std::vector<diag::Diagnostic>& diagnostics() const = 0;
};

struct EquivOutcome {
  /// False when a program could not be read or run (its diagnostics say why; a usage problem
  /// such as an unreadable file was printed already).
  bool ok = false;
  EquivResult result;
  std::shared_ptr<ProgramSide> a, b;
};

EquivOutcome checkEquivalence(const ProgramInput& a, const ProgramInput& b,
                              const EquivOptions& options);

} // namespace gcx::equiv
