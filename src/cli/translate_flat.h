// gcx translate --to <another dialect>: the program's executed motion written by the target
// dialect's writer of flat motion (emit/motion_writer.h), offsets and tool lengths in the
// coordinates like canonical motion.
#pragma once
#include <string>

#include "cli/commands.h"
#include "cli/translate_target.h"

namespace gcx::cli {

/// Writes the translation of `input` to `output`; 0, or the exit code after reporting why not.
int writeFlatMotion(const std::string& input, const TranslateTarget& target,
                    const TranslateOptions& opt, const std::string& output);

} // namespace gcx::cli
