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
  /// Set for another dialect than the source's: the writer of the executed motion, whose
  /// result has the setup in its coordinates and runs without one.
  emit::MotionWriterMaker motionWriter = nullptr;
  bool printSource = false; // the source printed back in its own dialect (gcx fmt)
};

/// The target, or nullopt with the reason in why (an unknown target, or a pair of dialects gcx
/// cannot translate between yet).
std::optional<TranslateTarget> translateTarget(const Dialect& source, const std::string& to,
                                               std::string& why);

/// "canonical, ngc, nct, fms3000, wl4": every name --to takes.
std::string translateTargetNames();

} // namespace gcx::cli
