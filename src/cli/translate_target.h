// What `gcx translate --to T` writes for a source dialect: the expansion that produces it, the
// file extension, and the note saying which structures were expanded and why.
#pragma once
#include <optional>
#include <string>

#include "dialect/dialect.h"
#include "emit/motion_writer.h"

namespace gcx::cli {

struct TranslateTarget {
  std::string name;                 // as given: "ngc", "canonical", "nct"
  std::string expandTo;             // the expansion that writes it: "canonical" or a dialect
  const Dialect* dialect = nullptr; // null: RS274/NGC that LinuxCNC runs
  std::string extension;            // of the output file: ".ngc", ".nct"
  std::string note;                 // the structures the output does not keep, and why
  bool keepCycles = false;          // another dialect: drilling cycles as the target's own
  /// Set for another dialect than the source's: the writer of the executed motion, whose
  /// result has the setup in its coordinates and runs without one.
  emit::MotionWriterMaker motionWriter = nullptr;
  bool printSource = false; // the source printed back in its own dialect (gcx fmt)
};

/// What `--expand` says the translation may not keep.
struct ExpandSet {
  bool cycles = false, subprograms = false, loops = false, variables = false;
  bool any() const { return cycles || subprograms || loops || variables; }
};

/// "cycles,loops" or "all"; nullopt with the reason in why for another word.
std::optional<ExpandSet> parseExpand(const std::string& list, std::string& why);

/// The target, or nullopt with the reason in why (an unknown target, or a pair of dialects gcx
/// cannot translate between yet).
std::optional<TranslateTarget> translateTarget(const Dialect& source, const std::string& to,
                                               const ExpandSet& expand, std::string& why);

/// A translation's note as the batch report's columns: what it kept, what it ran out.
struct NoteParts {
  std::string kept, expanded;
};
NoteParts splitNote(const std::string& note);

/// "canonical, ngc, nct, fms3000, wl4": every name --to takes.
std::string translateTargetNames();

} // namespace gcx::cli
