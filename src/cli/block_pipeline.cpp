#include "cli/block_pipeline.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "cli/packed_blocks.h"
#include "diag/codes.h"
#include "dialect/dialect.h"
#include "machine/interpreter.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

namespace {

// The steps of one block; both loops below use them, so they cannot disagree. A block that fails
// its static checks is not executed.
bool passesChecks(const StreamStages& s, const ir::Block& block) {
  const std::size_t before = s.diags.errorCount();
  s.checker.block(block);
  return s.diags.errorCount() == before;
}

bool execute(const StreamStages& s, const ir::Block& block) {
  motion::Provenance from;
  from.at = block.range.begin;
  return s.interp.execute(block, from);
}

void runSequential(const StreamStages& s) {
  ir::Block block;
  while (s.source.next(block)) {
    if (!passesChecks(s, block)) break;
    if (!execute(s, block)) break;
  }
}

// A bounded first-in first-out queue between two threads. After close(), push() refuses and
// pop() returns what is left, then nothing.
template <class T> class Channel {
public:
  explicit Channel(std::size_t capacity) : capacity_(capacity) {}

  bool push(T v) {
    std::unique_lock lock(mutex_);
    notFull_.wait(lock, [&] { return closed_ || queue_.size() < capacity_; });
    if (closed_) return false;
    queue_.push_back(std::move(v));
    notEmpty_.notify_one();
    return true;
  }

  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    notEmpty_.wait(lock, [&] { return closed_ || !queue_.empty(); });
    if (queue_.empty()) return std::nullopt;
    T v = std::move(queue_.front());
    queue_.pop_front();
    notFull_.notify_one();
    return v;
  }

  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    notFull_.notify_all();
    notEmpty_.notify_all();
  }

private:
  std::size_t capacity_;
  std::mutex mutex_;
  std::condition_variable notFull_, notEmpty_;
  std::deque<T> queue_;
  bool closed_ = false;
};

// A run of blocks read and checked. Blocks in the common form travel packed (see
// packed_blocks.h); the others whole, in slots reused from batch to batch.
struct Batch {
  struct Entry {
    std::uint32_t index;   // in packed or whole
    std::uint32_t diagEnd; // this block's diagnostics end here in diags (they begin where the
                           // entry before's end)
    bool packed;
    bool failedCheck;
  };
  std::vector<Entry> entries;
  PackedBlocks packed;
  std::vector<ir::Block> whole;
  std::size_t wholeUsed = 0;
  std::vector<diag::Diagnostic> diags; // reported while reading and checking, in order
  bool endOfInput = false;             // then the diagnostics after the last entry's are the
                                       // read's that found the end

  void clear() {
    entries.clear();
    packed.clear();
    wholeUsed = 0;
    diags.clear();
    endOfInput = false;
  }
};

// Blocks travel in batches, so the threads meet once per batch rather than once per block; the
// batches are recycled with their storage, so a run allocates no more after the first few.
// Measured on 1M lines (bench/README.md, Threads): 64 blocks a batch 0.36 s, 256 0.31 s, 1024
// and 2048 0.29 s, 4096 0.31 s; 2 or 8 batches in flight no better than 4. A handover wakes a
// sleeping thread, which costs a VM's processor far more than a few hundred blocks.
constexpr std::size_t kBatchBlocks = 1024;
constexpr std::size_t kBatchesInFlight = 4;

class ReaderStage {
public:
  ReaderStage(const StreamStages& s, Channel<std::unique_ptr<Batch>>& full,
              Channel<std::unique_ptr<Batch>>& empty)
      : s_(s), full_(full), empty_(empty), diags_(s.diags.errorLimit()) {}

  void run() {
    const diag::Engine::Divert divert(s_.diags, diags_);
    for (;;) {
      std::optional<std::unique_ptr<Batch>> batch = empty_.pop();
      if (!batch) break;
      const bool more = fill(**batch);
      if (!full_.push(std::move(*batch)) || !more) break;
    }
    full_.close();
  }

private:
  // Reads blocks into the batch; false when the input ended or a block failed its checks.
  bool fill(Batch& b) {
    b.clear();
    while (b.entries.size() < kBatchBlocks) {
      if (!s_.source.next(block_)) {
        b.endOfInput = true;
        takeNew(b.diags);
        return false;
      }
      const bool failed = !passesChecks(s_, block_);
      Batch::Entry& e = b.entries.emplace_back();
      e.failedCheck = failed;
      e.packed = b.packed.pack(block_);
      if (e.packed) {
        e.index = static_cast<std::uint32_t>(b.packed.size() - 1);
      } else {
        if (b.wholeUsed == b.whole.size()) b.whole.emplace_back();
        e.index = static_cast<std::uint32_t>(b.wholeUsed);
        std::swap(b.whole[b.wholeUsed++], block_);
      }
      takeNew(b.diags);
      e.diagEnd = static_cast<std::uint32_t>(b.diags.size());
      if (failed) return false;
    }
    return true;
  }

  // The diagnostics reported since the last call. The private engine keeps them too, so its
  // error count (the static checks' signal) and error limit behave as the session's would.
  void takeNew(std::vector<diag::Diagnostic>& out) {
    const std::vector<diag::Diagnostic>& all = diags_.all();
    for (; shipped_ < all.size(); ++shipped_)
      if (all[shipped_].code != diag::code::TooManyErrors) out.push_back(all[shipped_]);
  }

  const StreamStages s_; // a copy: the caller's lies in the executing thread's stack
  Channel<std::unique_ptr<Batch>>& full_;
  Channel<std::unique_ptr<Batch>>& empty_;
  diag::Engine diags_;
  std::size_t shipped_ = 0;
  ir::Block block_; // read into here, on this thread
};

void replay(diag::Engine& to, std::vector<diag::Diagnostic>& list, std::size_t begin,
            std::size_t end) {
  for (std::size_t i = begin; i < end; ++i)
    to.report(std::move(list[i]));
}

bool passes(const std::function<bool()>& part) {
  return !part || part();
}

bool runThreaded(const StreamStages& s, const StreamGate& gate) {
  Channel<std::unique_ptr<Batch>> full(kBatchesInFlight), empty(kBatchesInFlight + 2);
  for (std::size_t i = 0; i < kBatchesInFlight + 2; ++i)
    empty.push(std::make_unique<Batch>());
  std::exception_ptr failure;
  // The stage lives in the reading thread's own stack: what it writes for every block must not
  // share a cache line with what this thread writes for every block.
  std::atomic<bool> refused = false; // by the gate's second part
  std::thread reader([&] {
    try {
      if (!passes(gate.second)) {
        refused = true;
        full.close();
        return;
      }
      ReaderStage(s, full, empty).run();
    } catch (...) {
      failure = std::current_exception();
      full.close();
    }
  });
  auto drop = [&] {
    empty.close();
    full.close();
    reader.join();
    return false;
  };

  // This thread executes. Each block's reader diagnostics are reported just before it runs, so
  // the session sees the sequential order; what the reader read beyond a stop is dropped. What
  // a sink throws (out of memory, a harness's cap) stops the reader before it goes on.
  try {
    if (!passes(gate.first)) return drop();
    bool running = true;
    UnpackedBlock unpacked; // each packed block, rebuilt on this thread
    while (running) {
      std::optional<std::unique_ptr<Batch>> got = full.pop();
      if (!got && refused) return drop(); // before any block ran: refusing closed the queue
      if (!got) break;
      Batch& b = **got;
      std::size_t shown = 0;
      for (std::size_t i = 0; i < b.entries.size() && running; ++i) {
        const Batch::Entry& e = b.entries[i];
        replay(s.diags, b.diags, shown, e.diagEnd);
        shown = e.diagEnd;
        if (e.failedCheck) {
          running = false;
        } else if (e.packed) {
          b.packed.unpack(e.index, unpacked);
          running = execute(s, unpacked.block());
        } else {
          running = execute(s, b.whole[e.index]);
        }
      }
      if (running && b.endOfInput) replay(s.diags, b.diags, shown, b.diags.size());
      empty.push(std::move(*got));
    }
  } catch (...) {
    drop();
    throw;
  }
  empty.close();
  full.close();
  reader.join();
  if (failure) std::rethrow_exception(failure);
  return true;
}

} // namespace

bool runBlocks(const StreamStages& s, unsigned jobs, const StreamGate& gate) {
  if (jobs > 1) return runThreaded(s, gate);
  if (!passes(gate.first) || !passes(gate.second)) return false;
  runSequential(s);
  return true;
}

unsigned defaultJobs() {
  return std::thread::hardware_concurrency() > 1 ? 2 : 1;
}

} // namespace gcx::cli
