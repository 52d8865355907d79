// Contour checks and geometry for the contour cycles (cycles.md §4.7-§4.10).
#include "cycles/contour.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "diag/codes.h"

namespace gcx::cycles {

namespace {

constexpr double kTol = 1e-6;        // coordinates equal within this (mm)
constexpr double kZeroLength = 1e-9; // a contour move shorter than this is dropped
constexpr double kTwoPi = 2 * std::numbers::pi;

bool isArc(OpKind k) {
  return k == OpKind::ArcCW || k == OpKind::ArcCCW;
}

double radius(const ProfileSegment& s) {
  return (s.from - s.center).norm();
}

/// The angle swept from s.from to p in the arc's direction, in [0, 2π).
double turnTo(const ProfileSegment& s, const Vec2& p) {
  const Vec2 u = s.from - s.center, v = p - s.center;
  double t = std::atan2(u[0] * v[1] - u[1] * v[0], u.dot(v));
  if (s.kind == OpKind::ArcCW) t = -t;
  return t < 0 ? t + kTwoPi : t;
}

/// The whole sweep; start == end is a full circle (motion/geometry.h convention).
double sweep(const ProfileSegment& s) {
  const double t = turnTo(s, s.to);
  return t < 1e-12 ? kTwoPi : t;
}

bool onArc(const ProfileSegment& s, const Vec2& p) {
  const double t = turnTo(s, p);
  return t <= sweep(s) + 1e-12 || t >= kTwoPi - 1e-12;
}

/// An arc turns back on an axis when it passes an axis-parallel tangent strictly inside: at
/// quarter q (0 +z, 1 +x, 2 -z, 3 -x) it turns back along axis q % 2.
bool arcTurnsBack(const ProfileSegment& s, int onlyAxis = -1) {
  const double r = radius(s), sw = sweep(s);
  for (int q = 0; q < 4; ++q) {
    if (onlyAxis >= 0 && q % 2 != onlyAxis) continue;
    const double th = q * std::numbers::pi / 2;
    const double t = turnTo(s, s.center + r * Vec2(std::cos(th), std::sin(th)));
    if (t > 1e-9 && t < sw - 1e-9) return true;
  }
  return false;
}

double sign(double v) {
  return v > 0 ? 1 : -1;
}

const char* axisRole(int axis) {
  return axis == 0 ? "P1 (lathe Z)" : "P2 (lathe X)";
}

void crossings(const ProfileSegment& s, int level, double v, std::vector<double>& out) {
  const int cut = 1 - level;
  if (!isArc(s.kind)) {
    const double d = s.to[level] - s.from[level];
    if (std::abs(d) < kZeroLength) {
      if (std::abs(s.from[level] - v) < kTol) out.push_back(s.from[cut]), out.push_back(s.to[cut]);
      return;
    }
    const double t = (v - s.from[level]) / d;
    if (t >= -1e-12 && t <= 1 + 1e-12)
      out.push_back(s.from[cut] + std::clamp(t, 0.0, 1.0) * (s.to[cut] - s.from[cut]));
    return;
  }
  const double r = radius(s), dv = v - s.center[level];
  if (std::abs(dv) > r) return;
  const double h = std::sqrt(std::max(0.0, r * r - dv * dv));
  for (double b : {s.center[cut] - h, s.center[cut] + h}) {
    Vec2 q;
    q[level] = v, q[cut] = b;
    if (onArc(s, q)) out.push_back(b);
  }
}

} // namespace

std::optional<Profile> makeProfile(const std::vector<ContourSegment>& contour, motion::Plane plane,
                                   const SourceRange& block, diag::Engine& diags) {
  if (contour.empty()) {
    diags.error(diag::code::CycleContourDegenerate, block,
                "the contour ns..nf has no move (cycles.md §4.7)");
    return std::nullopt;
  }
  const ContourSegment& ns = contour.front();
  if ((ns.kind != OpKind::Rapid && ns.kind != OpKind::Feed) || !ns.modeProgrammed) {
    diags.error(diag::code::CycleNsMode, ns.range,
                "the first contour block (ns) must program G00 or G01 (cycles.md §4.7)");
    return std::nullopt;
  }
  const TurningPath frame(ns.from, plane);
  Profile p;
  p.approach = ns.kind, p.ns = ns.range;
  p.a = frame.lathe(ns.from), p.aPrime = frame.lathe(ns.to);
  for (std::size_t i = 1; i < contour.size(); ++i) {
    const ContourSegment& c = contour[i];
    ProfileSegment s;
    s.kind = isArc(c.kind) ? c.kind : OpKind::Feed;
    s.from = frame.lathe(c.from), s.to = frame.lathe(c.to), s.center = frame.lathe(c.center);
    s.range = c.range;
    if (isArc(s.kind) && (radius(s) < kTol || (s.to - s.center).norm() < kTol)) {
      diags.error(diag::code::ArcZeroRadius, c.range, "contour arc of zero radius");
      return std::nullopt;
    }
    if (!isArc(s.kind) && (s.to - s.from).norm() < kZeroLength) continue;
    p.segments.push_back(s);
  }
  return p;
}

Profile shifted(const Profile& p, const Vec2& offset) {
  Profile q = p;
  q.aPrime += offset;
  for (ProfileSegment& s : q.segments)
    s.from += offset, s.to += offset, s.center += offset;
  return q;
}

std::optional<RoughFrame> checkTypeOne(const Profile& p, int levelAxis, const char* cycle,
                                       diag::Engine& diags) {
  RoughFrame f;
  f.level = levelAxis, f.cut = 1 - levelAxis;
  const Vec2 ns = p.aPrime - p.a;
  if (std::abs(ns[f.cut]) > kTol) {
    diags.error(diag::code::CycleType2, p.ns,
                fmt::format("{}: the ns block moves along both axes (type II), which is not "
                            "supported; type I moves along {} only (cycles.md §4.8, Q-15)",
                            cycle, axisRole(f.level)));
    return std::nullopt;
  }
  if (std::abs(ns[f.level]) <= kTol) {
    diags.error(diag::code::CycleContourDegenerate, p.ns,
                fmt::format("{}: the ns block must move along {} (cycles.md §4.8)", cycle,
                            axisRole(f.level)));
    return std::nullopt;
  }
  f.levelSign = sign(ns[f.level]);
  double cutSign = 0;
  for (const ProfileSegment& s : p.segments) {
    const Vec2 d = s.to - s.from;
    const bool turns = isArc(s.kind) && arcTurnsBack(s);
    const bool wrongLevel = f.levelSign * d[f.level] > kTol;
    const bool wrongCut = std::abs(d[f.cut]) > kTol && cutSign != 0 && sign(d[f.cut]) != cutSign;
    if (turns || wrongLevel || wrongCut) {
      diags.error(diag::code::CycleNonMonotonic, s.range,
                  fmt::format("{}: a type-I contour must be monotonic in {} and {}; this block "
                              "turns back (cycles.md §4.8)",
                              cycle, axisRole(0), axisRole(1)));
      return std::nullopt;
    }
    if (cutSign == 0 && std::abs(d[f.cut]) > kTol) cutSign = sign(d[f.cut]);
  }
  if (cutSign == 0) {
    diags.error(diag::code::CycleContourDegenerate, p.ns,
                fmt::format("{}: the contour has no length along {}: nothing to rough "
                            "(cycles.md §4.8)",
                            cycle, axisRole(f.cut)));
    return std::nullopt;
  }
  f.cutSign = cutSign;
  return f;
}

std::optional<double> firstCrossing(const Profile& p, const RoughFrame& f, double v, double from) {
  std::vector<double> hits;
  for (const ProfileSegment& s : p.segments)
    crossings(s, f.level, v, hits);
  std::optional<double> best;
  for (double b : hits) {
    const double ahead = f.cutSign * (b - from);
    if (ahead < -kTol) continue;
    if (!best || ahead < f.cutSign * (*best - from)) best = b;
  }
  return best;
}

bool turnsBackAlong(const ProfileSegment& s, int axis) {
  return isArc(s.kind) && arcTurnsBack(s, axis);
}

namespace {

bool holds(const ProfileSegment& s, const Vec2& q) {
  if (isArc(s.kind)) return std::abs((q - s.center).norm() - radius(s)) < kTol && onArc(s, q);
  const Vec2 d = s.to - s.from;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((q - s.from).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (s.from + t * d - q).norm() < kTol;
}

/// Where segment s, run from `at` (on it), first has coordinate `axis` = `until`.
std::optional<Vec2> reaches(const ProfileSegment& s, const Vec2& at, int axis, double until) {
  if (!isArc(s.kind)) {
    const double d = s.to[axis] - at[axis];
    if (std::abs(d) < kZeroLength) return std::nullopt;
    const double t = (until - at[axis]) / d;
    if (t < -1e-12 || t > 1 + 1e-12) return std::nullopt;
    return Vec2(at + std::clamp(t, 0.0, 1.0) * (s.to - at));
  }
  std::vector<double> others;
  crossings(s, axis, until, others);
  ProfileSegment rest = s;
  rest.from = at;
  const double whole = turnTo(rest, s.to);
  std::optional<Vec2> best;
  double first = kTwoPi;
  for (double b : others) {
    Vec2 q;
    q[axis] = until, q[1 - axis] = b;
    const double t = turnTo(rest, q);
    if (t <= whole + 1e-12 && t < first) first = t, best = q;
  }
  return best;
}

} // namespace

void followProfileUntil(const Profile& p, const Vec2& from, int axis, double until,
                        TurningPath& path, double f) {
  std::size_t i = 0;
  while (i < p.segments.size() && !holds(p.segments[i], from))
    ++i;
  Vec2 at = from;
  for (; i < p.segments.size(); ++i) {
    const ProfileSegment& s = p.segments[i];
    if ((s.to - at).norm() < kTol) { // at its end already (a crossing found numerically)
      at = s.to;
      continue;
    }
    const auto stop = reaches(s, at, axis, until);
    const Vec2 to = stop ? *stop : s.to;
    if (isArc(s.kind))
      path.arc(s.kind, to, s.center, f);
    else
      path.feed(to, f);
    if (stop) return;
    at = s.to;
  }
}

double followOut(const Profile& p, const Vec2& from, int axis, double s, double level, double until,
                 TurningPath& path, double f) {
  std::size_t i = 0;
  while (i < p.segments.size() && !holds(p.segments[i], from))
    ++i;
  Vec2 at = from;
  double shallowest = from[axis];
  auto note = [&](const Vec2& q) {
    if (s * (q[axis] - shallowest) < 0) shallowest = q[axis];
  };
  for (; i < p.segments.size(); ++i) {
    const ProfileSegment& seg = p.segments[i];
    if ((seg.to - at).norm() < kTol) { // at its end already (a crossing found numerically)
      at = seg.to;
      continue;
    }
    // the first of: back at `until`; deeper than `level` (a zone this level cuts apart)
    ProfileSegment rest = seg;
    rest.from = at;
    auto along = [&](const Vec2& q) { // how far along the rest of the segment q lies
      return isArc(seg.kind) ? turnTo(rest, q) : (q - at).norm();
    };
    std::optional<Vec2> stop = reaches(seg, at, axis, until);
    if (const auto deeper = reaches(seg, at, axis, level + s * kTol);
        deeper && (!stop || along(*deeper) < along(*stop)))
      stop = deeper;
    const Vec2 to = stop ? *stop : seg.to;
    if (isArc(seg.kind)) {
      for (int q = axis; q < 4; q += 2) { // the arc's own extremes along `axis` on the way
        const double th = q * std::numbers::pi / 2;
        const Vec2 turn = seg.center + radius(seg) * Vec2(std::cos(th), std::sin(th));
        if (along(turn) > 1e-12 && along(turn) < along(to)) note(turn);
      }
      path.arc(seg.kind, to, seg.center, f);
    } else {
      path.feed(to, f);
    }
    note(to);
    if (stop) break;
    at = seg.to;
  }
  return shallowest;
}

std::vector<double> crossingsAt(const Profile& p, int level, double v) {
  std::vector<double> out;
  for (const ProfileSegment& s : p.segments)
    crossings(s, level, v, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [](double a, double b) { return std::abs(a - b) < kTol; }),
            out.end());
  return out;
}

double extremeAlong(const Profile& p, int axis, double s) {
  double v = p.aPrime[axis];
  auto take = [&](double x) {
    if (s * (x - v) > 0) v = x;
  };
  for (const ProfileSegment& seg : p.segments) {
    take(seg.from[axis]), take(seg.to[axis]);
    if (!isArc(seg.kind)) continue;
    for (int q = axis; q < 4; q += 2) {
      const double th = q * std::numbers::pi / 2;
      const Vec2 turn = seg.center + radius(seg) * Vec2(std::cos(th), std::sin(th));
      if (onArc(seg, turn)) take(turn[axis]);
    }
  }
  return v;
}

void followProfile(const Profile& p, TurningPath& path, double f) {
  for (const ProfileSegment& s : p.segments) {
    if (isArc(s.kind))
      path.arc(s.kind, s.to, s.center, f);
    else
      path.feed(s.to, f);
  }
}

} // namespace gcx::cycles
