// The call stack of the control-flow engine: a frame per running program (its program counter,
// open loops, repeat count and how it was called), the local variable frames, and the modal
// call registrations.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dialect/control_flow.h"
#include "ir/source.h"
#include "passes/macro/program_library.h"
#include "passes/macro/value.h"

namespace gcx::macro {

/// An open WHILE/DO loop of a frame.
struct Loop {
  std::size_t head;        // the WHILE/DO block
  std::uint64_t iteration; // 1 on entry
};

/// What the block at the program counter still does after its NC part, in this order
/// (wl4.md §1.9): a call (a Call statement), then a jump (a Jump statement).
struct BlockTail {
  const LoadedProgram* call = nullptr;
  std::int64_t times = 1;
  std::string what;
  SourceRange site;
  std::size_t jump = static_cast<std::size_t>(-1); // the block to continue at
};

/// A repeated fragment (FMS G25 L ... M25): its opening block and the runs left.
struct Repeat {
  std::size_t head;
  std::int64_t remaining;
};

struct Frame {
  const LoadedProgram* program = nullptr;
  std::size_t pc = 0;
  int level = 0;              // its local variable frame (a shared call keeps the caller's)
  std::int64_t remaining = 0; // runs left after this one (repeat count)
  std::size_t callBlock = 0;  // index of the calling block in the caller
  SourceLoc callSite;
  std::string what;        // the program and the code that called it
  std::vector<Value> args; // an own local frame: the values each run starts from
  std::vector<Loop> loops;
  std::vector<Repeat> repeats; // open repeated fragments, innermost last
  bool ownLocals = false;      // the call opened a local frame
  std::size_t modalVisible = static_cast<std::size_t>(-1); // modal calls this frame sees
  bool configured = false; // started by a code the machine parameters configure as a call
  BlockTail tail;          // of the block at pc
};

/// A modal call registration (the remap table's Modal* rows).
struct ModalCall {
  const LoadedProgram* program = nullptr;
  std::vector<Value> args;
  std::int64_t times = 1;
  bool everyBlock = false; // after every NC block, not only after motion blocks
  int code10 = 0;          // the registering code x10, reported in its modal group
  LocalFrame frame = LocalFrame::Arguments;
  std::string what;
};

/// The local variable frames, one contiguous pool of `size` slots per frame: opening a frame
/// for a call costs no allocation once the pool has grown.
class LocalFrames {
public:
  void reset(std::size_t size) {
    size_ = size;
    slots_.assign(size, Value{});
    count_ = 1;
  }
  std::size_t size() const { return size_; }
  int count() const { return static_cast<int>(count_); }
  Value* top(int level) { return slots_.data() + static_cast<std::size_t>(level) * size_; }
  /// Opens a frame holding `init` (missing slots vacant); returns its level.
  int push(const std::vector<Value>& init) {
    if (slots_.size() < (count_ + 1) * size_) slots_.resize((count_ + 1) * size_);
    Value* f = slots_.data() + count_ * size_;
    for (std::size_t i = 0; i < size_; ++i)
      f[i] = i < init.size() ? init[i] : Value{};
    return static_cast<int>(count_++);
  }
  void pop() { --count_; }
  /// Reloads frame `level` from `init` (a repeated run starts from its arguments).
  void load(int level, const std::vector<Value>& init) {
    Value* f = top(level);
    for (std::size_t i = 0; i < size_; ++i)
      f[i] = i < init.size() ? init[i] : Value{};
  }
  std::vector<Value> copy(int level) { return {top(level), top(level) + size_}; }

private:
  std::vector<Value> slots_;
  std::size_t size_ = 0, count_ = 0;
};

} // namespace gcx::macro
