#include "machine/offset_geometry.h"

#include <cmath>
#include <limits>

namespace gcx::machine::comp {

namespace {

constexpr double kEps = 1e-9;

double radiusOf(const Path2& p) {
  return (p.a - p.c).norm();
}

/// The point of `candidates` nearest to `near`, if any lies within `bound`.
std::optional<Vec2> nearest(const std::vector<Vec2>& candidates, const Vec2& near,
                            double bound = std::numeric_limits<double>::infinity()) {
  std::optional<Vec2> best;
  double bestDistance = bound;
  for (const Vec2& x : candidates) {
    const double d = (x - near).norm();
    if (d <= bestDistance) best = x, bestDistance = d;
  }
  return best;
}

std::vector<Vec2> lineLine(const Path2& x, const Path2& y) {
  const Vec2 u = x.b - x.a, v = y.b - y.a;
  const double den = cross(u, v);
  if (std::fabs(den) < kEps * u.norm() * v.norm()) return {};
  const double t = cross(y.a - x.a, v) / den;
  return {x.a + t * u};
}

std::vector<Vec2> lineCircle(const Path2& line, const Vec2& c, double r) {
  const Vec2 u = line.b - line.a;
  const double len = u.norm();
  if (len < kEps) return {};
  const Vec2 dir = u / len;
  const Vec2 foot = line.a + dir * dir.dot(c - line.a);
  const double h = (foot - c).norm();
  if (h > r + kEps) return {};
  const double half = std::sqrt(std::max(0.0, r * r - h * h));
  if (half < kEps) return {foot};
  return {foot - dir * half, foot + dir * half};
}

std::vector<Vec2> circleCircle(const Vec2& c0, double r0, const Vec2& c1, double r1) {
  const Vec2 d = c1 - c0;
  const double dist = d.norm();
  if (dist < kEps || dist > r0 + r1 + kEps || dist < std::fabs(r0 - r1) - kEps) return {};
  const double a = (r0 * r0 - r1 * r1 + dist * dist) / (2 * dist);
  const double h = std::sqrt(std::max(0.0, r0 * r0 - a * a));
  const Vec2 mid = c0 + d * (a / dist), across = leftOf(d / dist) * h;
  if (h < kEps) return {mid};
  return {mid + across, mid - across};
}

std::vector<Vec2> dedupe(std::vector<Vec2> points) {
  std::vector<Vec2> out;
  for (const Vec2& p : points)
    if (out.empty() || (out.back() - p).norm() > kEps) out.push_back(p);
  return out;
}

} // namespace

Vec2 tangentAt(const Path2& p, bool atEnd) {
  if (!p.arc) {
    const Vec2 u = p.b - p.a;
    const double n = u.norm();
    return n < kEps ? Vec2::Zero() : Vec2(u / n);
  }
  const Vec2 r = (atEnd ? p.b : p.a) - p.c;
  const double n = r.norm();
  if (n < kEps) return Vec2::Zero();
  const Vec2 t = leftOf(r / n);
  return p.ccw ? t : Vec2(-t);
}

std::optional<Path2> offsetPath(const Path2& p, double d) {
  Path2 o = p;
  if (!p.arc) {
    const Vec2 n = leftOf(tangentAt(p, false)) * d;
    o.a += n, o.b += n;
    return o;
  }
  // left of a counter-clockwise arc points to its centre: the radius shrinks
  const double change = p.ccw ? -d : d;
  const double ra = (p.a - p.c).norm(), rb = (p.b - p.c).norm();
  if (ra + change <= kEps || rb + change <= kEps) return std::nullopt;
  o.a = p.c + (p.a - p.c) * ((ra + change) / ra);
  o.b = p.c + (p.b - p.c) * ((rb + change) / rb);
  return o;
}

std::vector<Vec2> intersections(const Path2& x, const Path2& y) {
  if (!x.arc && !y.arc) return lineLine(x, y);
  if (!x.arc) return lineCircle(x, y.c, radiusOf(y));
  if (!y.arc) return lineCircle(y, x.c, radiusOf(x));
  return circleCircle(x.c, radiusOf(x), y.c, radiusOf(y));
}

CornerResult corner(const Path2& first, const Path2& second, double dFirst, double dSecond,
                    Join join, OuterCorner rule, const std::optional<Vec2>& virtualDir) {
  CornerResult out;
  const Vec2 p = first.b;
  const Vec2 tA = tangentAt(first, true), tB = tangentAt(second, false);
  // a start-up line is offset on the side of the element it leads to; a cancel line likewise
  const double dA = join == Join::StartUp ? dSecond : dFirst;
  const double dB = join == Join::Cancel ? dFirst : dSecond;
  const Vec2 nA = p + dA * leftOf(tA), nB = p + dB * leftOf(tB);
  const double r = std::fabs(join == Join::StartUp ? dB : dA);
  if (std::fabs(dA) < kEps && std::fabs(dB) < kEps) {
    out.points = {p};
    return out;
  }
  const auto offA = offsetPath(first, dA), offB = offsetPath(second, dB);
  auto meet = [&](const std::optional<Path2>& x, const std::optional<Path2>& y, double bound) {
    return x && y ? nearest(intersections(*x, *y), p, bound) : std::nullopt;
  };
  const double inf = std::numeric_limits<double>::infinity();
  if (virtualDir && virtualDir->norm() > kEps && (join == Join::StartUp || join == Join::Cancel)) {
    // the I J K direction of a virtual element before (start-up) or after (cancel) the corner
    const Vec2 v = virtualDir->normalized();
    const bool up = join == Join::StartUp;
    const Path2 virt{false, up ? Vec2(p - v) : p, up ? p : Vec2(p + v), Vec2::Zero(), true};
    const auto x =
        up ? meet(offsetPath(virt, dB), offB, inf) : meet(offA, offsetPath(virt, dA), inf);
    out.points = {x ? *x : (up ? nB : nA)};
    return out;
  }
  if (join == Join::StartUp && tA.isZero()) return out.points = {nB}, out;
  if (join == Join::Cancel && tB.isZero()) return out.points = {nA}, out;
  if (join == Join::Perpendicular) return out.points = dedupe({nA, nB}), out;
  if (join == Join::Direction) { // 000:8019-8100
    // no intersection: the first element ends on the perpendicular at the second's start, a
    // line straight there, an arc on its programmed radius about a shifted centre
    const auto x = meet(offA, offB, inf);
    out.points = {x ? *x : nB};
    out.shiftedArc = !x && first.arc;
    return out;
  }
  const double turn = cross(tA, tB), along = tA.dot(tB);
  if (std::fabs(turn) < kEps && along > 0) return out.points = dedupe({nA, nB}), out; // tangent
  const bool inner = turn * dA > 0; // the tool on the inside of the turn
  if (inner) {
    if (join == Join::StartUp) return out.points = {nB}, out; // nct.md §3.17.2
    if (join == Join::Cancel) return out.points = {nA}, out;  // nct.md §3.17.3
    const auto x = meet(offA, offB, inf);
    if (!x) {
      out.noIntersection = true;
      return out;
    }
    out.points = {*x};
    return out;
  }
  if (rule == OuterCorner::Arc) {
    out.points = {nA, nB};
    out.arcAbout = true;
    return out;
  }
  if (along >= -kEps) // obtuse: the offsets meet within r·√2 of the corner
    if (const auto x = meet(offA, offB, 1.5 * r)) return out.points = {*x}, out;
  // acute (or offsets that do not meet near the corner): extended vectors, three lines
  out.points = dedupe({nA, nA + r * tA, nB - r * tB, nB});
  return out;
}

std::optional<Vec2> shiftedCentre(const Vec2& from, const Vec2& to, double radius,
                                  const Vec2& programmed) {
  if ((to - from).norm() < kEps) { // a full circle: its centre moves with its start
    const Vec2 towards = programmed - from;
    if (towards.norm() < kEps) return std::nullopt;
    return Vec2(from + towards.normalized() * radius);
  }
  return nearest(circleCircle(from, radius, to, radius), programmed);
}

namespace {

/// Swept angle from a to b about c in the arc's direction, in [0, 2π).
double sweepTo(const Path2& arc, const Vec2& a, const Vec2& b) {
  double s = std::atan2(cross(a - arc.c, b - arc.c), (a - arc.c).dot(b - arc.c));
  if (!arc.ccw) s = -s;
  return s < -kEps ? s + 2 * M_PI : std::max(s, 0.0);
}

/// `t` lies on the element between its start and its end.
bool onElement(const Path2& p, const Vec2& t) {
  if (!p.arc) {
    const Vec2 u = p.b - p.a;
    const double s = (t - p.a).dot(u);
    return s >= -kEps && s <= u.squaredNorm() + kEps;
  }
  const double whole = p.a == p.b ? 2 * M_PI : sweepTo(p, p.a, p.b);
  return sweepTo(p, p.a, t) <= whole + 1e-9;
}

/// The point of the element at distance (chord) `c` from the corner: before it on the first
/// element, after it on the second.
std::optional<Vec2> atChord(const Path2& p, const Vec2& corner, double c, bool before) {
  const Vec2 t = tangentAt(p, before);
  if (!p.arc) return corner + (before ? -c : c) * t;
  Path2 ring = p;
  ring.a = ring.b = corner + Vec2(c, 0);
  ring.c = corner;
  for (const Vec2& x : intersections(p, ring))
    if ((x - corner).dot(t) * (before ? -1 : 1) > 0) return x;
  return std::nullopt;
}

Vec2 footOn(const Path2& p, const Vec2& x) {
  if (!p.arc) {
    const Vec2 u = (p.b - p.a).normalized();
    return p.a + u * u.dot(x - p.a);
  }
  return p.c + (x - p.c).normalized() * (p.a - p.c).norm();
}

} // namespace

Blend chamfer(const Path2& first, const Path2& second, double c) {
  Blend out;
  const auto a = atChord(first, first.b, c, true), b = atChord(second, first.b, c, false);
  out.fits = a && b && onElement(first, *a) && onElement(second, *b);
  if (out.fits) out.endFirst = *a, out.startSecond = *b;
  return out;
}

Blend rounding(const Path2& first, const Path2& second, double r) {
  Blend out;
  const Vec2 p = first.b;
  const double turn = cross(tangentAt(first, true), tangentAt(second, false));
  const auto offA = offsetPath(first, turn > 0 ? r : -r);
  const auto offB = offsetPath(second, turn > 0 ? r : -r);
  const auto centre = std::fabs(turn) > kEps && offA && offB
                          ? nearest(intersections(*offA, *offB), p)
                          : std::nullopt;
  if (!centre) return out.fits = false, out;
  out.arc = true;
  out.ccw = turn > 0;
  out.centre = *centre;
  out.endFirst = footOn(first, *centre);
  out.startSecond = footOn(second, *centre);
  out.fits = onElement(first, out.endFirst) && onElement(second, out.startSecond);
  return out;
}

} // namespace gcx::machine::comp
