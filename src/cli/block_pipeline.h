// The streaming loop of a program that needs no expansion pass: read and check each block, then
// execute it. With two jobs the reader and static checks run on their own thread, ahead of the
// interpreter and its sinks, through a bounded queue of block batches (the usual blocks packed
// small, cli/packed_blocks.h); the output, the diagnostics and their order are exactly those of
// the one-thread loop (a test runs both).
#pragma once
#include <cstddef>
#include <functional>

#include "diag/diagnostic.h"

namespace gcx {
class BlockSource;
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
  diag::Engine& diags; // the engine every stage reports to
};

/// A question to answer before any block runs, in two parts that two threads may answer at once
/// (the halves of a scan of the file). Either part missing counts as yes.
struct StreamGate {
  std::function<bool()> first, second;
};

/// Runs blocks until the input ends, a block fails a static check (it is not executed) or the
/// interpreter stops, and returns true. jobs > 1 runs the reader on a thread of its own. The
/// gate is asked first: with two jobs its second part by the reading thread before it reads,
/// its first by this thread while the other reads ahead. A no from either drops what was read
/// and returns false, with nothing executed or reported.
bool runBlocks(const StreamStages& s, unsigned jobs, const StreamGate& gate = {});

/// The default for --jobs: 2 when the machine has more than one core, else 1.
unsigned defaultJobs();

} // namespace gcx::cli
