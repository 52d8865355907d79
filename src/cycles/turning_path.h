// Builds the op list of a turning cycle in lathe coordinates (z = P1, x = P2, cycles.md §4.2)
// and writes program coordinates: the plane's normal axis keeps the start's value. Moves of zero
// length are dropped (§1.2 rule 2). Internal to the turning cycles.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "cycles/ops.h"
#include "cycles/turning_state.h"

namespace gcx::cycles {

using Vec2 = Eigen::Vector2d; // (z, x) = (P1, P2), x in radius

class TurningPath {
public:
  TurningPath(const Vec3& start, motion::Plane plane)
      : ax_(latheAxes(plane)), start3_(start), at_(lathe(start)) {}

  Vec2 lathe(const Vec3& p) const { return {p[ax_.p1], p[ax_.p2]}; }
  Vec3 program(const Vec2& p) const {
    Vec3 v = start3_;
    v[ax_.p1] = p[0], v[ax_.p2] = p[1];
    return v;
  }
  const Vec2& at() const { return at_; }
  Vec2 start() const { return lathe(start3_); }

  void pass(int n) { step_ = n; }
  void rapid(const Vec2& to) { move(OpKind::Rapid, to, Vec2::Zero(), 0); }
  void feed(const Vec2& to, double f) { move(OpKind::Feed, to, Vec2::Zero(), f); }
  /// G0 or G1 as the ns block programmed it (§4.7).
  void approach(OpKind mode, const Vec2& to, double f) {
    move(mode, to, Vec2::Zero(), mode == OpKind::Rapid ? 0 : f);
  }
  void arc(OpKind kind, const Vec2& to, const Vec2& center, double f) { move(kind, to, center, f); }
  void thread(const Vec2& to, double lead) {
    if (move(OpKind::Thread, to, Vec2::Zero(), 0)) ops_.back().value = lead;
  }
  std::vector<CycleOp>& ops() { return ops_; }

private:
  bool move(OpKind k, const Vec2& to, const Vec2& center, double f) {
    constexpr double kZeroLength = 0.0005;
    const bool zero = (to - at_).norm() < kZeroLength;
    at_ = to;
    if (zero) return false;
    CycleOp o;
    o.kind = k, o.step = step_, o.to = program(to), o.feed = f;
    if (k == OpKind::ArcCW || k == OpKind::ArcCCW) o.center = program(center);
    ops_.push_back(o);
    return true;
  }

  LatheAxes ax_;
  Vec3 start3_;
  Vec2 at_;
  int step_ = 0;
  std::vector<CycleOp> ops_;
};

} // namespace gcx::cycles
