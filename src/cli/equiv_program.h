// gcx's side of `gcx equiv` (and later `translate --verify`): a program opened through the
// command line's Session and run by executeProgram with the command's options.
#pragma once
#include <memory>

#include "cli/commands.h"
#include "equiv/equiv.h"

namespace gcx::cli {

/// A maker for equiv::EquivOptions::gcxProgram: each program gets its own session.
std::function<std::unique_ptr<equiv::GcxProgram>()> gcxProgramMaker(const CommonOptions& opt);

} // namespace gcx::cli
