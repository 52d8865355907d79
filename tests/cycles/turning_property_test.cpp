// Properties of G71.7/G72.7 stock removal (cycles.md §4.8, §4.9) over random monotonic type-I
// profiles (lines and arcs), random Δd, e, Δu, Δw, quadrants and ns modes:
//  (1) no roughing feed enters the part enlarged by the allowance;
//  (2) the final pass runs exactly along the shifted contour (the contour itself when Δu=Δw=0);
//  (3) the levels are exactly A − k·Δd (§1.2 rule 3), and the last one is the last above C'.
#ifdef GCX_HAVE_RAPIDCHECK
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <rapidcheck/gtest.h>

#include "cycles/turning_harness.h"

namespace gcx::test {
namespace {

using cycles::OpKind;
using cycles::Vec2;
using cycles::Vec3;

/// A profile generated in depth coordinates (u: depth along the level axis from A toward the
/// part, v: distance along the cut direction from A) and its placement in lathe (z, x).
struct Case {
  bool facing = false; // G72.7: levels along z
  double levelSign = -1, cutSign = -1;
  Vec2 a{2, 30}; // A in lathe (z, x), radius
  struct Piece {
    bool arc = false;
    Vec2 to, center; // (u, v)
  };
  Vec2 aPrime; // (u, v)
  std::vector<Piece> pieces;
  double depth = 1, retract = 0.5, du = 0, dw = 0; // Δd, e (radius); Δu (diameter), Δw
  bool feedApproach = false;

  int levelAxis() const { return facing ? 0 : 1; }
  /// (u, v) -> lathe (z, x)
  Vec2 lathe(const Vec2& uv) const {
    Vec2 p;
    p[levelAxis()] = a[levelAxis()] + levelSign * uv[0];
    p[1 - levelAxis()] = a[1 - levelAxis()] + cutSign * uv[1];
    return p;
  }
  Vec2 depthCoords(const Vec2& p) const {
    return {levelSign * (p[levelAxis()] - a[levelAxis()]),
            cutSign * (p[1 - levelAxis()] - a[1 - levelAxis()])};
  }
  static Vec3 program(const Vec2& zx) { return {zx[1], 0, zx[0]}; }
};

rc::Gen<Case> genCase() {
  return rc::gen::exec([] {
    Case c;
    c.facing = *rc::gen::arbitrary<bool>();
    c.levelSign = *rc::gen::element(-1.0, 1.0);
    c.cutSign = *rc::gen::element(-1.0, 1.0);
    c.feedApproach = *rc::gen::arbitrary<bool>();
    auto real = [](int lo, int hi) { return *rc::gen::inRange(lo, hi) / 100.0; };
    c.aPrime = {real(200, 3000), 0};
    Vec2 p = c.aPrime;
    // first a run along the cut direction (longer than any Δw): A stays clear of C'
    p[1] += real(150, 1500);
    c.pieces.push_back({false, p, Vec2::Zero()});
    const int n = *rc::gen::inRange(1, 6);
    for (int i = 0; i < n; ++i) {
      if (*rc::gen::arbitrary<bool>()) { // line: u does not increase, v does not decrease
        const Vec2 d(-real(0, 800), real(0, 1500));
        if (d.norm() < 0.05) continue;
        p += d;
        c.pieces.push_back({false, p, Vec2::Zero()});
      } else { // arc inside one quadrant: monotonic in u (down) and v (up)
        const double r = real(50, 1000);
        const bool up = *rc::gen::arbitrary<bool>(); // θ rising in [0, π/2], else falling
        const double base = up ? 0 : std::numbers::pi;
        double t0 = real(0, 157), t1 = real(0, 157);
        if (std::abs(t1 - t0) < 0.1) continue;
        if (up == (t0 > t1)) std::swap(t0, t1);
        const Vec2 center = p - r * Vec2(std::cos(base + t0), std::sin(base + t0));
        p = center + r * Vec2(std::cos(base + t1), std::sin(base + t1));
        c.pieces.push_back({true, p, center});
      }
    }
    c.depth = real(20, 500);
    c.retract = real(0, 200);
    c.du = real(-100, 100);
    c.dw = real(-100, 100);
    return c;
  });
}

std::vector<cycles::ContourSegment> contourOf(const Case& c) {
  std::vector<cycles::ContourSegment> out;
  cycles::ContourSegment ns;
  ns.kind = c.feedApproach ? OpKind::Feed : OpKind::Rapid;
  ns.from = Case::program(c.a), ns.to = Case::program(c.lathe(c.aPrime));
  out.push_back(ns);
  Vec2 from = c.aPrime;
  for (const Case::Piece& piece : c.pieces) {
    cycles::ContourSegment s;
    s.from = Case::program(c.lathe(from)), s.to = Case::program(c.lathe(piece.to));
    s.kind = OpKind::Feed;
    if (piece.arc) {
      const Vec2 f = c.lathe(from) - c.lathe(piece.center),
                 t = c.lathe(piece.to) - c.lathe(piece.center);
      s.kind = f[0] * t[1] - f[1] * t[0] > 0 ? OpKind::ArcCCW : OpKind::ArcCW;
      s.center = Case::program(c.lathe(piece.center));
    }
    out.push_back(s);
    from = piece.to;
  }
  return out;
}

std::vector<cycles::CycleOp> run(const Case& c, double du, double dw) {
  cycles::TurningRequest req;
  req.start = Case::program(c.a);
  req.feed = 0.2;
  req.contour = contourOf(c);
  cycles::TurningModal modal;
  modal.roughDepth = c.depth, modal.roughRetract = c.retract;
  cycles::TurningWords w;
  w.cycle = c.facing ? cycles::TurningCycle::RoughFacing : cycles::TurningCycle::RoughTurning;
  w.diameter = 1;
  w.set('P', 50), w.set('Q', 60), w.set('U', du), w.set('W', dw), w.set('F', 0.2);
  diag::Engine diags;
  const auto ops = cycles::expandTurning(req, modal, w, diags);
  RC_ASSERT(ops.has_value());
  return *ops;
}

/// The contour A' -> B shifted by the allowance, in depth coordinates, as (from, to, centre).
struct Seg {
  bool arc;
  Vec2 from, to, center;
};
std::vector<Seg> shiftedProfile(const Case& c, double du, double dw) {
  const Vec2 shift(dw, du / 2);
  std::vector<Seg> out;
  Vec2 from = c.aPrime;
  for (const Case::Piece& p : c.pieces) {
    auto moved = [&](const Vec2& uv) { return c.depthCoords(c.lathe(uv) + shift); };
    out.push_back({p.arc, moved(from), moved(p.to), moved(p.center)});
    from = p.to;
  }
  return out;
}

/// The shallowest profile depth at v (the face a cut meets first), or nullopt off the profile.
std::optional<double> profileDepth(const std::vector<Seg>& prof, double v) {
  std::optional<double> best;
  auto take = [&](double u) { best = best ? std::max(*best, u) : u; };
  for (const Seg& s : prof) {
    const double lo = std::min(s.from[1], s.to[1]), hi = std::max(s.from[1], s.to[1]);
    if (v < lo || v > hi) continue;
    if (s.arc) {
      const double r = (s.from - s.center).norm(), dv = v - s.center[1];
      const double h = std::sqrt(std::max(0.0, r * r - dv * dv));
      for (double u : {s.center[0] - h, s.center[0] + h}) // the root inside the arc's box
        if (u >= std::min(s.from[0], s.to[0]) - 1e-9 && u <= std::max(s.from[0], s.to[0]) + 1e-9)
          take(u);
    } else if (hi - lo < 1e-12) {
      take(std::max(s.from[0], s.to[0]));
    } else {
      take(s.from[0] + (v - s.from[1]) / (s.to[1] - s.from[1]) * (s.to[0] - s.from[0]));
    }
  }
  return best;
}

Vec2 latheOf(const Vec3& p) {
  return {p[2], p[0]};
}

int lastStep(const std::vector<cycles::CycleOp>& ops) {
  return ops.empty() ? 0 : ops.back().step;
}

RC_GTEST_PROP(CyclesSpec_4_8_Property, RoughingNeverCutsIntoThePart, ()) {
  const Case c = *genCase();
  const auto ops = run(c, c.du, c.dw);
  const auto prof = shiftedProfile(c, c.du, c.dw);
  const int final = lastStep(ops);
  Vec2 at = c.a;
  for (const cycles::CycleOp& o : ops) {
    const Vec2 to = latheOf(o.to);
    if (o.kind == OpKind::Feed && o.step != final) {
      for (int i = 0; i <= 64; ++i) {
        const Vec2 q = c.depthCoords(at + (to - at) * (i / 64.0));
        const auto u = profileDepth(prof, q[1]);
        RC_ASSERT(!(u && q[0] > *u + 1e-6));
      }
    }
    at = to;
  }
}

/// The final pass: approach to A'' in the ns mode, then exactly the shifted segments.
void checkFinalPass(const Case& c, double du, double dw) {
  const auto ops = run(c, du, dw);
  const int final = lastStep(ops);
  std::vector<cycles::CycleOp> pass;
  for (const cycles::CycleOp& o : ops)
    if (o.step == final) pass.push_back(o);
  const auto prof = shiftedProfile(c, du, dw);
  RC_ASSERT(pass.size() == prof.size() + 2); // approach, the segments, back to A
  std::size_t i = 0;
  RC_ASSERT(pass.back().kind == OpKind::Rapid);
  RC_ASSERT((latheOf(pass.back().to) - c.a).norm() < 1e-12);
  const Vec2 aShifted = c.lathe(c.aPrime) + Vec2(dw, du / 2);
  RC_ASSERT((latheOf(pass[i].to) - aShifted).norm() < 1e-9);
  for (const Seg& s : prof) {
    const cycles::CycleOp& o = pass[++i];
    RC_ASSERT((c.depthCoords(latheOf(o.to)) - s.to).norm() < 1e-9);
    RC_ASSERT((o.kind == OpKind::ArcCW || o.kind == OpKind::ArcCCW) == s.arc);
    if (s.arc) RC_ASSERT((c.depthCoords(latheOf(o.center)) - s.center).norm() < 1e-9);
  }
}

RC_GTEST_PROP(CyclesSpec_4_8_Property, FinalPassIsTheShiftedContour, ()) {
  const Case c = *genCase();
  checkFinalPass(c, c.du, c.dw);
  checkFinalPass(c, 0, 0);
}

RC_GTEST_PROP(CyclesSpec_4_8_Property, LevelsAreExactMultiplesOfTheDepth, ()) {
  const Case c = *genCase();
  const auto ops = run(c, c.du, c.dw);
  const int final = lastStep(ops);
  const int level = c.levelAxis();
  double deepest = -1e300; // the limit of §4.8 step 2 (x_min), in depth coordinates
  for (const Seg& s : shiftedProfile(c, c.du, c.dw))
    deepest = std::max({deepest, s.from[0], s.to[0]});
  int k = 0;
  for (const cycles::CycleOp& o : ops) {
    if (o.step == final || o.step == k) continue;
    k = o.step; // the first op of pass k reaches its level
    const double expected = c.a[level] + c.levelSign * k * c.depth;
    RC_ASSERT(latheOf(o.to)[level] == expected);
    RC_ASSERT(k * c.depth < deepest + 1e-9);
  }
  RC_ASSERT((k + 1) * c.depth >= deepest - 1e-9);
}

} // namespace
} // namespace gcx::test
#endif
