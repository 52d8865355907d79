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

#include "diag/codes.h"
#include "dialect/dialect.h"
#include "machine/interpreter.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

namespace {

// The steps of one block; both loops below use them, so they cannot disagree. Reading a block
// checks it and sorts its words; executing runs it with them.
bool passesChecks(const StreamStages& s, const ir::Block& block, machine::SortedWords& sorted) {
  const std::size_t before = s.diags.errorCount();
  s.checker.block(block);
  if (s.diags.errorCount() != before) return false;
  sorted.notLiteral = machine::sortWords(block, s.profile, sorted.words);
  return true;
}

bool execute(const StreamStages& s, const ir::Block& block, machine::SortedWords& sorted) {
  motion::Provenance from;
  from.at = block.range.begin;
  return s.interp.execute(block, from, &sorted);
}

void runSequential(const StreamStages& s) {
  ir::Block block;
  machine::SortedWords sorted;
  while (s.source.next(block)) {
    if (!passesChecks(s, block, sorted)) break;
    if (!execute(s, block, sorted)) break;
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

struct Item {
  ir::Block block;
  machine::SortedWords sorted;         // block's words, sorted for the interpreter
  std::vector<diag::Diagnostic> diags; // reported while reading and checking this block
  bool failedCheck = false;
};

struct Batch {
  std::vector<Item> items;
  std::size_t size = 0;
  bool endOfInput = false;
  std::vector<diag::Diagnostic> tail; // reported by the read that found the end
};

// Blocks travel in batches, so the threads meet once per batch rather than once per block; the
// batches are recycled with their blocks' storage, so a run allocates no more after the first few.
constexpr std::size_t kBatchBlocks = 256;
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
    b.size = 0;
    b.endOfInput = false;
    b.tail.clear();
    while (b.size < b.items.size()) {
      Item& it = b.items[b.size];
      if (!s_.source.next(it.block)) {
        b.endOfInput = true;
        takeNew(b.tail);
        return false;
      }
      it.failedCheck = !passesChecks(s_, it.block, it.sorted);
      takeNew(it.diags);
      ++b.size;
      if (it.failedCheck) return false;
    }
    return true;
  }

  // The diagnostics reported since the last call. The private engine keeps them too, so its
  // error count (the static checks' signal) and error limit behave as the session's would.
  void takeNew(std::vector<diag::Diagnostic>& out) {
    out.clear();
    const std::vector<diag::Diagnostic>& all = diags_.all();
    for (; shipped_ < all.size(); ++shipped_)
      if (all[shipped_].code != diag::code::TooManyErrors) out.push_back(all[shipped_]);
  }

  const StreamStages& s_;
  Channel<std::unique_ptr<Batch>>& full_;
  Channel<std::unique_ptr<Batch>>& empty_;
  diag::Engine diags_;
  std::size_t shipped_ = 0;
};

void replay(diag::Engine& to, std::vector<diag::Diagnostic>& list) {
  for (diag::Diagnostic& d : list)
    to.report(std::move(d));
  list.clear();
}

void runThreaded(const StreamStages& s) {
  Channel<std::unique_ptr<Batch>> full(kBatchesInFlight), empty(kBatchesInFlight + 2);
  for (std::size_t i = 0; i < kBatchesInFlight + 2; ++i) {
    auto b = std::make_unique<Batch>();
    b->items.resize(kBatchBlocks);
    empty.push(std::move(b));
  }
  ReaderStage stage(s, full, empty);
  std::exception_ptr failure;
  std::thread reader([&] {
    try {
      stage.run();
    } catch (...) {
      failure = std::current_exception();
      full.close();
    }
  });

  // This thread executes. Each block's reader diagnostics are reported just before it runs, so
  // the session sees the sequential order; what the reader read beyond a stop is dropped.
  bool running = true;
  while (running) {
    std::optional<std::unique_ptr<Batch>> got = full.pop();
    if (!got) break;
    Batch& b = **got;
    for (std::size_t i = 0; i < b.size && running; ++i) {
      Item& it = b.items[i];
      replay(s.diags, it.diags);
      running = !it.failedCheck && execute(s, it.block, it.sorted);
    }
    if (running && b.endOfInput) replay(s.diags, b.tail);
    empty.push(std::move(*got));
  }
  empty.close();
  full.close();
  reader.join();
  if (failure) std::rethrow_exception(failure);
}

} // namespace

void runBlocks(const StreamStages& s, unsigned jobs) {
  if (jobs > 1)
    runThreaded(s);
  else
    runSequential(s);
}

unsigned defaultJobs() {
  return std::thread::hardware_concurrency() > 1 ? 2 : 1;
}

} // namespace gcx::cli
