// G71.7 / G72.7 stock removal and G73.7 pattern repeating (cycles.md §4.8-§4.10) [F].
#include <cmath>
#include <fmt/format.h>

#include "cycles/turning_cycles.h"
#include "diag/codes.h"

namespace gcx::cycles {

namespace {

constexpr long kMaxPasses = 100000; // more is a typing error, not a part (no hang)

/// The extreme of the shifted contour on the cutting side (x_min of §4.8 step 2). A type-I
/// contour is monotonic, so its extremes are vertices.
double extreme(const Profile& c, int axis, double sign) {
  double v = c.aPrime[axis];
  for (const ProfileSegment& s : c.segments)
    for (const Vec2& p : {s.from, s.to})
      if (sign * (p[axis] - v) > 0) v = p[axis];
  return v;
}

/// One depth level (§4.8 step 4): approach in the ns mode, cut to the contour, 45° retract,
/// back along the cut axis to A.
void roughPass(TurningPath& path, const Profile& c, const RoughFrame& f, double level,
               double farEnd, double e, double feed) {
  const Vec2 a = path.start();
  Vec2 p = path.at();
  p[f.level] = level;
  path.approach(c.approach, p, feed); // from A (k = 1), else from x_(k-1) + e
  const double hit = firstCrossing(c, f, level, a[f.cut]).value_or(farEnd);
  p[f.cut] = hit;
  path.feed(p, feed);
  p[f.level] = level - f.levelSign * e;
  p[f.cut] = hit - f.cutSign * e;
  path.rapid(p);
  p[f.cut] = a[f.cut];
  path.rapid(p);
}

/// Along the shifted contour from A'' and back to A (§4.8 step 5-6, §4.10).
void contourPass(TurningPath& path, const Profile& c, double feed) {
  path.approach(c.approach, c.aPrime, feed);
  followProfile(c, path, feed);
  path.rapid(path.start());
}

} // namespace

TurningOps expandStockRemoval(const TurningRequest& req, const TurningModal& m,
                              const TurningWords& w, diag::Engine& diags) {
  const std::string& name = w.label;
  if (!m.roughDepth) {
    diags.error(diag::code::CycleParam, w.range,
                fmt::format("{}: no depth of cut: program `{} <depth> R<e>` first "
                            "(cycles.md §4.8)",
                            name, name));
    return std::nullopt;
  }
  if (!checkFeed(req.feed, w, false, diags)) return std::nullopt;
  const auto profile = makeProfile(req.contour, req.plane, w.range, diags);
  if (!profile) return std::nullopt;
  const bool facing = w.cycle == TurningCycle::RoughFacing; // §4.9: P1 and P2 swap roles
  const auto frame = checkTypeOne(*profile, facing ? 0 : 1, name.c_str(), diags);
  if (!frame) return std::nullopt;

  const Profile c = shifted(*profile, allowance(w)); // §4.8 step 1: C'
  TurningPath path(req.start, req.plane);
  const Vec2 a = path.start();
  const double dd = *m.roughDepth;
  const double limit = extreme(c, frame->level, frame->levelSign);
  const double farEnd = extreme(c, frame->cut, frame->cutSign);
  const double stock = frame->levelSign * (limit - a[frame->level]);
  if (stock / dd > kMaxPasses) {
    diags.error(
        diag::code::CycleParam, w.range,
        fmt::format("{}: more than {} passes: the depth of cut is too small", name, kMaxPasses));
    return std::nullopt;
  }
  int k = 1;
  // §4.8 step 3: x_k = x_A - k·Δd while x_k > x_min, never accumulated (§1.2 rule 3)
  for (;; ++k) {
    const double level = a[frame->level] + frame->levelSign * k * dd;
    if (!(frame->levelSign * (limit - level) > 1e-9)) break;
    path.pass(k);
    roughPass(path, c, *frame, level, farEnd, m.roughRetract, req.feed);
  }
  if (req.choices.roughingFinalPass) { // the final semi-finishing pass
    path.pass(k);
    contourPass(path, c, req.feed);
  }
  path.rapid(a); // §4.8 step 6 (without the final pass: from the last retract)
  return std::move(path.ops());
}

TurningOps expandPatternRepeat(const TurningRequest& req, const TurningModal& m,
                               const TurningWords& w, diag::Engine& diags) {
  if (!m.repeatCount) {
    diags.error(diag::code::CycleParam, w.range,
                "G73.7: no number of passes: program `G73.7 <U'>Δi <W'>Δk R<d>` first "
                "(cycles.md §4.10)");
    return std::nullopt;
  }
  if (!checkFeed(req.feed, w, false, diags)) return std::nullopt;
  const auto profile = makeProfile(req.contour, req.plane, w.range, diags);
  if (!profile) return std::nullopt;
  const int d = *m.repeatCount;
  const Vec2 finish = allowance(w);
  TurningPath path(req.start, req.plane);
  for (int k = 1; k <= d; ++k) {
    // §4.10: o_k = Δ·(d−k)/(d−1) + allowance; d = 1: the allowance only (Fanuc spacing, Q-16);
    // the textbook's Δ·(d−k)/d where the dialect chooses it
    const double t = req.choices.patternStepByPassCount ? static_cast<double>(d - k) / d
                     : d == 1                           ? 0.0
                                                        : static_cast<double>(d - k) / (d - 1);
    path.pass(k);
    contourPass(path, shifted(*profile, finish + t * Vec2(m.reliefP1, m.reliefP2)), req.feed);
  }
  return std::move(path.ops());
}

} // namespace gcx::cycles
