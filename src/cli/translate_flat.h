// gcx translate --to <another dialect>: the program's executed motion written by the target
// dialect's writer of flat motion (emit/motion_writer.h), offsets and tool lengths in the
// coordinates like canonical motion; drilling cycles kept as the target's own cycles where they
// mean the same (translate/hole_lowering.h), unless --expand names them.
#pragma once
#include <string>

#include "cli/commands.h"
#include "cli/translate_target.h"

namespace gcx::cli {

/// What one attempt writes: whether it keeps cycles, and its note.
struct FlatAttempt {
  bool keepCycles = false;
  std::string note;
};

/// The note of a translation of `input`: the structures the program has (each with its block),
/// which the target keeps and which are run out into motion, and why. Keeping cycles runs the
/// program once without writing to learn which holes the target's cycles take. `refusal`: why an
/// attempt that kept cycles was not proven, when this is the attempt after it.
FlatAttempt planFlatMotion(const std::string& input, const TranslateTarget& target,
                           const TranslateOptions& opt, bool keepCycles,
                           const std::string& refusal = {});

/// Writes the translation of `input` to `output`; 0, or the exit code after reporting why not.
int writeFlatMotion(const std::string& input, const TranslateTarget& target,
                    const TranslateOptions& opt, const std::string& output,
                    const FlatAttempt& attempt);

} // namespace gcx::cli
