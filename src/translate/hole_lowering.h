// How a target dialect writes a lifted hole (translate/hole.h) as its own drilling cycle. Each
// dialect gives one (dialects/<d>/hole_writer.*): its cycle codes found by meaning in its
// profile, its parameter words and its cycle memory. The flat writer asks it first whether it
// can write a hole (nothing is written when not: the hole is then written as the motion it
// runs), and ends its cycle mode before any other block.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "dialect/profile.h"
#include "translate/hole.h"

namespace gcx::xlate {

/// The blocks a lowering writes, through the flat writer's emitter and number format.
class BlockOut {
public:
  virtual ~BlockOut() = default;
  virtual const Profile& profile() const = 0;
  /// A G or M code in tenths (810: G81), with the target's digits.
  virtual void writeCode(char letter, int code10) = 0;
  /// A word whose value is a length, a feed or a time, rounded to the target's resolution.
  virtual void writeValue(const char* address, double value) = 0;
  /// A word whose value is written as it is (a whole number of tenths of a second).
  virtual void writeExact(const char* address, double value) = 0;
  /// `#variable=value` (WL4's cycle parameters), the value rounded like writeValue.
  virtual void writeAssign(int variable, double value) = 0;
  /// The value as written: rounded to the target's resolution.
  virtual double rounded(double value) const = 0;
  /// Ends the block.
  virtual void endBlock() = 0;
};

class HoleLowering {
public:
  virtual ~HoleLowering() = default;
  /// Why the target's cycles cannot write h after what was written so far, or nullopt.
  virtual std::optional<std::string> refuse(const Hole& h, const BlockOut& out) const = 0;
  /// Writes h (refuse() said yes). The tool is at h.start, at h.x h.y when h.positioned is not
  /// set; the writer leaves it at h.x h.y h.exit.
  virtual void write(const Hole& h, BlockOut& out) = 0;
  /// Ends cycle mode when a cycle is active: the next block is no hole.
  virtual void cancel(BlockOut& out) = 0;
};

/// The G code of `action` (with `arg`, a cycle's meaning) in tenths, or nullopt.
std::optional<int> gcodeFor(const Profile& p, GAction action, int arg = -1);

/// Whether two written values are the same number at the resolution of `out`.
bool sameWritten(const BlockOut& out, double a, double b);

} // namespace gcx::xlate
