// FMS-3000 G164 longitudinal and G165 facing roughing to a profile (fms3000.md §5.3.1, Tables
// 33, 34, 001:3245-3389): depth levels from И.Т. toward the profile's end, each cut along the
// other axis to the first profile point, the chip breaking of G86 on that cut, then back; the
// finishing pass along the approach block and the profile unless P. A reconstruction [R] of
// the spec, unverified against the control. The geometry is the contour cycles' (contour.h).
#include <cmath>
#include <fmt/format.h>

#include "cycles/level_turning_parts.h"

namespace gcx::cycles {

namespace {

constexpr double kTol = 1e-6;
constexpr long kMaxLevels = 100000; // more is a typing error, not a part (no hang)

// lathe coordinates (z, x): G164 steps its depth along x and cuts along z; G165 the reverse
struct Axes {
  int level, cut;
};
Axes axesOf(LevelCycle cycle) {
  return cycle == LevelCycle::FacingRoughing ? Axes{0, 1} : Axes{1, 0};
}

const char* depthAxisName(LevelCycle cycle) {
  return cycle == LevelCycle::FacingRoughing ? "Z" : "X";
}

const char* approachAxisName(LevelCycle cycle) {
  return cycle == LevelCycle::FacingRoughing ? "X" : "Z";
}

} // namespace

std::optional<ProfileFault> checkRoughingProfile(LevelCycle cycle, std::string_view code,
                                                 const Profile& p) {
  const Axes ax = axesOf(cycle);
  const Vec2 approach = p.aPrime - p.a;
  if (std::abs(approach[ax.level]) > kTol || std::abs(approach[ax.cut]) <= kTol)
    return ProfileFault{p.ns, fmt::format("the first block after {} approaches the profile "
                                          "along {} only (001:3271-3272, 001:3916)",
                                          code, approachAxisName(cycle))};
  double direction = 0;
  for (const ProfileSegment& s : p.segments) {
    const double d = s.to[ax.level] - s.from[ax.level];
    const bool back = std::abs(d) > kTol && direction != 0 && level::sign(d) != direction;
    if (back || turnsBackAlong(s, ax.level))
      return ProfileFault{s.range, fmt::format("the profile of {} must be monotonic along {}; "
                                               "this block turns back (001:3287-3289, 001:3975)",
                                               code, depthAxisName(cycle))};
    if (direction == 0 && std::abs(d) > kTol) direction = level::sign(d);
  }
  if (direction == 0)
    return ProfileFault{p.ns, fmt::format("the profile of {} has no length along {}: nothing "
                                          "to rough before endcont",
                                          code, depthAxisName(cycle))};
  return std::nullopt;
}

namespace level {

namespace {

// the cut of one level from the start along f.cut to `hit`: one feed, or with V and W the steps
// of G86 (chip breaking: a rapid back by W between steps) up to the bottom
bool cut(TurningPath& path, const LevelTurnRequest& req, int cutAxis, double hit, double feed) {
  if (!req.words.count('V')) {
    Vec2 p = path.at();
    p[cutAxis] = hit;
    path.feed(p, feed);
    return true;
  }
  const auto ops = chipBreakingCut(path.program(path.at()), cutAxis == 0 ? kZ : kX, hit,
                                   req.words.at('V'), req.words.at('W'), feed);
  if (!std::holds_alternative<std::vector<CycleOp>>(ops)) return false;
  for (const CycleOp& op : std::get<std::vector<CycleOp>>(ops)) {
    if (op.kind == OpKind::Rapid)
      path.rapid(path.lathe(op.to));
    else
      path.feed(path.lathe(op.to), feed);
  }
  return true;
}

} // namespace

// Levels x_k = x0 - s*k*Q strictly between x0 and the profile's end B (s = sign(x0 - x_B)):
// to x_k at z0 (rapid with the G0 flag, else at F), cut along Z to the first profile point from
// z0, rapid X by D when given, rapid Z back to z0. Then, unless P, the finishing pass: И.Т., the
// approach block in its mode, the profile, rapid X then Z back to И.Т. G165 swaps X and Z.
Result profileRoughing(const LevelTurnRequest& req, double feed) {
  const Profile& c = *req.profile;
  const Axes ax = axesOf(req.cycle);
  if (req.words.count('V') != req.words.count('W'))
    return fmt::format("{}: V and W come together (001:3950-3953)", req.code);
  if (req.words.count('V') && (req.words.at('V') <= 0 || req.words.at('W') < 0))
    return fmt::format("{}: the step V must be > 0 and the retract W >= 0", req.code);
  const double q = std::abs(req.words.at('Q'));
  if (q < 0.0005) return fmt::format("{}: the depth per pass Q must not be 0", req.code);
  if (feed <= 0) return fmt::format("{} without a feed F", req.code);
  TurningPath path(req.position, motion::Plane::ZX);
  const Vec2 a = path.start();
  const Vec2 b = c.segments.empty() ? c.aPrime : c.segments.back().to;
  const double s = sign(a[ax.level] - b[ax.level]);
  if (std::abs(a[ax.level] - b[ax.level]) / q > kMaxLevels)
    return fmt::format("{}: more than {} passes: is Q a typing error?", req.code, kMaxLevels);
  RoughFrame frame;
  frame.level = ax.level, frame.cut = ax.cut;
  frame.levelSign = -s, frame.cutSign = sign(c.aPrime[ax.cut] - a[ax.cut]);
  const auto d = req.words.find('D');
  for (long k = 1;; ++k) {
    const double v = a[ax.level] - s * static_cast<double>(k) * q;
    if (!(s * (v - b[ax.level]) > kTol)) break;
    path.pass(static_cast<int>(k));
    Vec2 p = path.at();
    p[ax.level] = v;
    if (req.rapidFlag)
      path.rapid(p);
    else
      path.feed(p, feed);
    const double hit = firstCrossing(c, frame, v, a[ax.cut]).value_or(b[ax.cut]);
    if (!cut(path, req, ax.cut, hit, feed))
      return fmt::format("{}: the chip-breaking steps V W are wrong", req.code);
    p = path.at();
    if (d != req.words.end()) {
      p[ax.level] = v + d->second;
      path.rapid(p);
    }
    p[ax.cut] = a[ax.cut];
    path.rapid(p);
  }
  path.rapid(a);
  if (!req.words.count('P')) { // the finishing pass И.Т. -> approach, profile -> И.Т.
    path.approach(c.approach, c.aPrime, feed);
    followProfile(c, path, feed);
    Vec2 p = path.at();
    p[ax.level] = a[ax.level];
    path.rapid(p);
    path.rapid(a);
  }
  return std::move(path.ops());
}

} // namespace level

} // namespace gcx::cycles
