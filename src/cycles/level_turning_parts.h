// The pieces the FMS-3000 turning cycles share (level_turning.h): a path on the lathe axes X
// (slot 0, radius) and Z (slot 2) that drops zero-length moves, and the per-family expanders
// behind expandLevelTurning(). Internal to the level turning cycles.
#pragma once
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "cycles/level_turning.h"

namespace gcx::cycles::level {

constexpr int kX = 0, kZ = 2;

using Result = std::variant<std::vector<CycleOp>, std::string>;

inline double sign(double v) {
  return v < 0 ? -1.0 : 1.0;
}

class Path {
public:
  explicit Path(const Vec3& start) : at_(start) {}
  void to(OpKind kind, double x, double z, double feed = 0) {
    Vec3 p = at_;
    p[kX] = x;
    p[kZ] = z;
    appendMove(ops_, at_, kind, p, feed);
  }
  /// Along one lathe axis only.
  void along(int axis, OpKind kind, double v, double feed = 0) {
    Vec3 p = at_;
    p[axis] = v;
    appendMove(ops_, at_, kind, p, feed);
  }
  void arc(OpKind kind, double x, double z, double cx, double cz, double feed) {
    CycleOp op;
    op.kind = kind;
    op.to = at_;
    op.to[kX] = x;
    op.to[kZ] = z;
    op.center = at_;
    op.center[kX] = cx;
    op.center[kZ] = cz;
    op.feed = feed;
    ops_.push_back(op);
    at_ = op.to;
  }
  /// A spindle event (or any op without motion) where the path is.
  void event(OpKind kind) {
    CycleOp op;
    op.kind = kind;
    op.to = at_;
    ops_.push_back(op);
  }
  /// A spindle-synchronised move along Z with `lead` mm per revolution.
  void thread(double z, double lead) { thread(at_[kX], z, lead); }
  /// The same to (x, z): `lead` is the travel along Z per revolution.
  void thread(double x, double z, double lead) {
    Vec3 p = at_;
    p[kX] = x;
    p[kZ] = z;
    const std::size_t before = ops_.size();
    appendMove(ops_, at_, OpKind::Thread, p);
    if (ops_.size() > before) ops_.back().value = lead;
  }
  /// Ops made elsewhere from where the path is (chipBreakingCut()).
  void append(const std::vector<CycleOp>& ops) {
    for (const CycleOp& op : ops) {
      ops_.push_back(op);
      at_ = op.to;
    }
  }
  const Vec3& at() const { return at_; }
  double x() const { return at_[kX]; }
  double z() const { return at_[kZ]; }
  std::vector<CycleOp> take() { return std::move(ops_); }

private:
  Vec3 at_;
  std::vector<CycleOp> ops_;
};

/// A position parameter: absolute, or under G91 a signed distance from `origin`.
inline double position(const LevelTurnRequest& req, char c, double origin) {
  return req.words.at(c) + (req.incremental ? origin : 0);
}

/// The lathe axes of a cycle that goes in depth along one and cuts (or steps) along the other:
/// X in depth, Z along, unless `swapped` (the facing and face-groove variants); where И.Т. is on
/// each, and where the cycle's X and Z words put their ends.
struct DepthAndCut {
  int depth, cut;
  char depthWord, cutWord;
  double out, back;   // И.Т. on the depth and on the cut axis
  double bottom, end; // the depth and the cut axis's word
};
inline DepthAndCut depthAndCut(const LevelTurnRequest& req, bool swapped) {
  DepthAndCut a{swapped ? kZ : kX, swapped ? kX : kZ, swapped ? 'Z' : 'X', swapped ? 'X' : 'Z',
                0,          0,          0,          0};
  a.out = req.position[a.depth];
  a.back = req.position[a.cut];
  a.bottom = position(req, a.depthWord, a.out);
  a.end = position(req, a.cutWord, a.back);
  return a;
}

/// A cut from `from` along `axis` to `to` at `feed` with the chip breaking of G86 (fms3000.md
/// §5.2): steps of `step`, a rapid back by `retract` between them, up to `to`. The message of a
/// bad step or retract.
std::variant<std::vector<CycleOp>, std::string>
chipBreakingCut(const Vec3& from, int axis, double to, double step, double retract, double feed);

/// G152 multi-pass longitudinal turning / G153 multi-pass facing (Tables 21, 22).
Result multiPassTurning(const LevelTurnRequest& req, double feed);
/// G162 multi-pass thread (Table 31); `pitch` is F, mm per revolution.
Result multiPassThread(const LevelTurnRequest& req, double pitch);
/// G151 single-pass facing (Table 20).
Result singlePassFacing(const LevelTurnRequest& req, double feed);
/// G158 cylindrical / G159 face grooves (Tables 27, 28).
Result grooves(const LevelTurnRequest& req, double feed);
/// G163 tap or die (Table 32).
Result tapping(const LevelTurnRequest& req, double feed);
/// G164 longitudinal / G165 facing roughing to the profile req.profile (Tables 33, 34).
Result profileRoughing(const LevelTurnRequest& req, double feed);

} // namespace gcx::cycles::level
