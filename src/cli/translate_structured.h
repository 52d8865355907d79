// gcx translate --to <another dialect>, keeping the program's structure: its subprograms, loops,
// jumps and variables written in the target's own forms, block by block in the program's frame
// (translate/structured_writer.h), the subprograms in the target's files. The result runs on the
// same setup as its source and is proven like every translation; what the target cannot keep
// with the same meaning leaves the translation to the flat motion, with the reason in its note.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/translate_target.h"
#include "dialect/dialect.h"
#include "translate/structured_writer.h"

namespace gcx::cli {

struct StructuredAttempt {
  bool tried = false;   // the program has subprograms, loops or variables
  bool written = false; // every file is in the staging folder
  /// The files written, the main program first: paths in the staging folder and the names they
  /// take beside the output.
  std::vector<std::filesystem::path> staged;
  std::vector<std::string> names;
  std::vector<std::string> kept; // "subprogram calls (A.nct:7, 9)", ...
  std::string note;              // what it keeps, each with its source blocks
  std::string unkept;            // why not: "A.nct:12: G81: why"
};

/// Where a structured translation goes: the target's spelling, its printer and its name.
struct StructuredTarget {
  const xlate::StructuredSpelling* spelling = nullptr;
  xlate::EmitterMaker emitter = nullptr;
  std::string name; // "wl4", "ngc"
  /// Cycles alone are reason enough to write the structured program (LinuxCNC, whose flat motion
  /// keeps none); otherwise only subprograms, loops, jumps or variables are.
  bool forCycles = false;
  front::Encoding encoding = front::Encoding::Utf8; // what its files are written in
};

/// The structured target of a dialect, or none when gcx writes no structure in it.
StructuredTarget structuredTarget(const Dialect& target);

/// Writes `input` for `target` into `stage` (the main program as `mainName`) when the program has
/// structures that the flat motion would run out.
StructuredAttempt writeStructuredDialect(const Dialect& source, const StructuredTarget& target,
                                         const std::string& input,
                                         const std::filesystem::path& stage,
                                         const std::string& mainName, const TranslateOptions& opt);

} // namespace gcx::cli
