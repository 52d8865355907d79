// `gcx translate --to ngc`: the source's structure kept as LinuxCNC's where it means the same
// there (dialects/ngc), else the flat motion with a note saying what could not be kept and why.
#pragma once
#include <string>
#include <vector>

#include "cli/commands.h"
#include "dialect/dialect.h"

namespace gcx::cli {

struct NgcStructure {
  bool written = false;          // the structured program is in the file
  std::vector<std::string> kept; // what it keeps ("WHILE loops as o-word while")
  std::string unkept;            // why not: "O1.nct:12: GOTO: LinuxCNC has no jump ..."
};

/// Writes `input` as structured ngc to `file` when its dialect has a structured writer and every
/// construct keeps its meaning; with --write-offsets the setup's work offsets come first, as
/// G10 L2. A program that does not load is left to the flat expansion, which reports its errors.
NgcStructure writeStructuredNgc(const Dialect& source, const std::string& input,
                                const std::string& file, const TranslateOptions& opt);

/// What the note says: the structures kept, or, after `flat` (the target's note for plain
/// motion), why they were not: a construct the writer could not keep, or the proof (`proof`:
/// what the equivalence engine printed).
std::string ngcNote(const NgcStructure& ngc, bool kept, const std::string& flat,
                    const std::string& proof);

/// ": what differs at A.nct:3:1" from what the equivalence engine printed, or empty.
std::string divergence(const std::string& proof);

/// Puts `( note )` before the first line of `file`.
bool prependComment(const std::string& file, const std::string& note);

} // namespace gcx::cli
