// IR blocks as LinuxCNC RS274/NGC lines: words, parameters, o-word subroutines, loops and calls
// (what translate/structured_writer.h writes for the ngc target).
#pragma once
#include <memory>
#include <ostream>
#include <string>

#include "emit/emitter.h"
#include "ir/block.h"

namespace gcx::ngc {

/// A comment as LinuxCNC reads it as one: `(text)` without the text's own parentheses, and
/// `(- ...)` where the text would start a command such as (MSG, ...).
std::string commentText(const std::string& text);

/// One block as its line; empty when it holds nothing LinuxCNC writes.
std::string printBlock(const ir::Block& b);

std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out);

} // namespace gcx::ngc
