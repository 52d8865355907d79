// gcx check of one file on several threads. The file is cut at line ends into parts; each part
// after the first is read and checked by a source and a checker of its own, from a fresh state
// and with its lines numbered from 1, by whichever thread is free. The parts are joined in file
// order, and a part's findings are taken only where they are exactly what reading on would have
// found: the reading before it stopped at its first byte, on a block boundary, carrying no state
// over (an open comment, a G10 data-record mode, an open loop, a pending '%'); its diagnostics
// and kept findings then move to the lines the reading before it stopped at. Otherwise the part
// is read again in sequence. The diagnostics, their order and the counts are those of one
// thread (a test runs both).
#pragma once
#include <cstddef>

namespace gcx::check {
class StaticChecker;
}

namespace gcx::cli {

class Session;

struct CheckedBlocks {
  std::size_t blocks = 0;     // blocks read and checked
  std::size_t failed = 0;     // blocks with syntax errors, skipped
  std::size_t partsTaken = 0; // parts read on their own thread and taken (the rest read again)
};

/// Reads the session's program into the checker (without finish()). jobs > 1 reads a large
/// enough file of a source that can be read in parts on that many threads, in partsPerJob parts
/// a thread (at least 1 MB each), which the threads take as they become free.
CheckedBlocks checkBlocks(Session& s, check::StaticChecker& checker, unsigned jobs,
                          unsigned partsPerJob = 4);

} // namespace gcx::cli
