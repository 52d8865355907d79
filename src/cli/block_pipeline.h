// The streaming loop of a program that needs no expansion pass: read and check each block, then
// execute it. With two jobs the reader and static checks run on their own thread, ahead of the
// interpreter and its sinks, through a bounded queue of block batches; the output, the
// diagnostics and their order are exactly those of the one-thread loop (a test runs both).
#pragma once
#include <cstddef>

#include "diag/diagnostic.h"

namespace gcx {
class BlockSource;
struct Profile;
} // namespace gcx
namespace gcx::check {
class StaticChecker;
}
namespace gcx::machine {
class Interpreter;
}

namespace gcx::cli {

struct StreamStages {
  BlockSource& source;
  check::StaticChecker& checker;
  machine::Interpreter& interp;
  diag::Engine& diags;    // the engine every stage reports to
  const Profile& profile; // the interpreter's: the reading stage sorts each block's words by it
};

/// Runs blocks until the input ends, a block fails a static check (it is not executed) or the
/// interpreter stops. jobs > 1 runs the reader on a thread of its own; there it also sorts each
/// block's words for the interpreter (machine::SortedWords), as one job does before each block.
void runBlocks(const StreamStages& s, unsigned jobs);

/// The default for --jobs: 2 when the machine has more than one core, else 1.
unsigned defaultJobs();

} // namespace gcx::cli
