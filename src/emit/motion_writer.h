// A dialect's writer of flat motion (`gcx translate --to <another dialect>`): the motion a
// program executes, in the machine frame, written in the target dialect's own syntax and meaning.
// Each dialect has one (dialects/<d>/motion_writer.*); dialects/motion_writers.cpp lists them.
#pragma once
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.h"
#include "motion/event.h"

namespace gcx {
struct Profile;
}

namespace gcx::emit {

/// A structure of the source met while writing: kept as the target's own, or written as the
/// motion it runs, and why.
struct StructureNote {
  SourceLoc at;     // its block (a cycle's block, the call of a cycle program)
  std::string what; // "drilling cycle"
  std::string why;  // empty: kept
};

struct MotionWriterOptions {
  std::string programName;        // the source's name (its file stem): the target names its own
  std::vector<std::string> notes; // written as comment lines at the top
  /// The source's profile: events that carry a code (program end) are mapped by its meaning.
  const Profile* source = nullptr;
  /// Drilling cycles kept as the target's cycles where they mean the same (translate --expand
  /// without `cycles`); every cycle is run out into motion otherwise.
  bool keepCycles = false;
  /// Where each drilling cycle's hole met is recorded, kept or not (the note), when set.
  std::vector<StructureNote>* structures = nullptr;
};

/// A motion sink that writes a program. An event the target cannot express is a located error
/// in the diagnostics; the writer then writes nothing more and ok() is false.
class MotionWriter : public motion::Sink {
public:
  virtual bool ok() const = 0;
};

using MotionWriterMaker = std::unique_ptr<MotionWriter> (*)(std::ostream&,
                                                            const MotionWriterOptions&,
                                                            diag::Engine&);

/// The writer of flat motion of a dialect, or null when it has none.
MotionWriterMaker motionWriterFor(std::string_view dialect);

} // namespace gcx::emit
