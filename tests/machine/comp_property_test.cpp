// Properties of cutter radius compensation (docs/compensation.md) over random closed contours:
// convex and star-shaped concave polygons and circles, the tool inside or outside:
//  (1) every programmed element is passed at exactly the tool radius (1e-6 mm);
//  (2) no point of the tool path between start-up and cancel comes closer to the contour than
//      the radius (no gouge);
//  (3) outside corners follow the type-C rule: obtuse at the offsets' intersection, acute on
//      the extended vectors (nct.md §3.17.1).
#ifdef GCX_HAVE_RAPIDCHECK
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using P2 = Eigen::Vector2d;

double round4(double v) {
  return std::round(v * 1e4) / 1e4;
}
/// On a 0.002 grid, so the middle of two vertices is exact at 4 decimals.
double grid(double v) {
  return std::round(v * 500) / 500;
}
P2 xy(const motion::Vec3& v) {
  return {v.x(), v.y()};
}
double cross(const P2& a, const P2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Signed distance of p from the line a→b, positive on the left.
double side(const P2& a, const P2& b, const P2& p) {
  return cross(b - a, p - a) / (b - a).norm();
}

double pointSegment(const P2& p, const P2& a, const P2& b) {
  const P2 u = b - a;
  const double t = std::clamp((p - a).dot(u) / u.squaredNorm(), 0.0, 1.0);
  return (a + t * u - p).norm();
}

double segmentSegment(const P2& a, const P2& b, const P2& c, const P2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (d1 * d2 < 0 && d3 * d4 < 0) return 0;
  return std::min(
      {pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
}

/// A polygon about the origin, counter-clockwise, star-shaped from the origin (convex when all
/// radii are equal), vertices on a 0.002 mm grid. The origin, where an inside contour starts,
/// lies strictly inside: each edge subtends less than 180° there. (A triangle whose edge 0
/// passes through the origin makes the start-up block a zero move, whose r-move the next block
/// makes: CompNctSpec_3_17_2.StartUpOnTheContourMovesInTheNextBlock.)
std::vector<P2> genPolygon(bool convex) {
  const int n = *rc::gen::inRange(3, 10);
  std::vector<double> angles;
  const double gap = 360.0 / n;
  // one vertex in each sector at 0-49 % of it: neighbours are 51-149 % of a sector apart, below
  // 180° also for a triangle
  for (int i = 0; i < n; ++i)
    angles.push_back(gap * i + *rc::gen::inRange(0, 50) / 100.0 * gap);
  const double radius = *rc::gen::inRange(60, 100);
  std::vector<P2> out;
  for (double a : angles) {
    const double r = convex ? radius : *rc::gen::inRange(70, 100);
    out.emplace_back(grid(r * std::cos(a * M_PI / 180)), grid(r * std::sin(a * M_PI / 180)));
  }
  return out;
}

struct Contour {
  std::vector<P2> poly;
  P2 mid;              // the middle of edge 0, where the contour starts and ends
  std::string program; // start-up on line 2, edges on lines 3 .. n+3, cancel after them
};

/// G41 inside (start from the origin) or G42 outside (start 50 out from the middle of edge 0).
Contour program(const std::vector<P2>& poly, bool inside) {
  Contour c;
  c.poly = poly;
  const std::size_t n = poly.size();
  c.mid = (poly[0] + poly[1]) / 2;
  const P2 u = (poly[1] - poly[0]).normalized();
  const P2 away =
      inside ? P2(0, 0) : P2(round4(c.mid.x() + 50 * u.y()), round4(c.mid.y() - 50 * u.x()));
  auto at = [](const P2& p) { return fmt::format("X{:.4f} Y{:.4f}", p.x(), p.y()); };
  c.program = fmt::format("G17 G90 G0 {}\n{} G1 {} D1 F1000\n", at(away), inside ? "G41" : "G42",
                          at(c.mid));
  for (std::size_t i = 1; i <= n; ++i)
    c.program += "G1 " + at(poly[i % n]) + "\n";
  c.program += "G1 " + at(c.mid) + "\nG40 G1 " + at(away) + "\n";
  return c;
}

/// The programmed edges in order: mid→v1, v1→v2, …, v0→mid (source lines 3 .. n+3).
std::vector<std::pair<P2, P2>> edges(const Contour& c) {
  std::vector<std::pair<P2, P2>> out;
  const std::size_t n = c.poly.size();
  out.emplace_back(c.mid, c.poly[1]);
  for (std::size_t i = 1; i < n; ++i)
    out.emplace_back(c.poly[i], c.poly[(i + 1) % n]);
  out.emplace_back(c.poly[0], c.mid);
  return out;
}

void checkPolygon(const Contour& c, bool inside, double r) {
  ProgramRun run = runNct(c.program, compSetup(r));
  RC_ASSERT(run.errors.empty());
  const auto e = edges(c);
  const double want = inside ? r : -r; // G41: tool on the left
  const unsigned first = 3, last = static_cast<unsigned>(first + e.size() - 1);
  for (std::size_t k = 0; k < e.size(); ++k) {
    const auto main = std::find_if(run.events.begin(), run.events.end(), [&](const auto& ev) {
      return ev.kind == motion::Kind::Feed && ev.from.at.line == first + k;
    });
    RC_ASSERT(main != run.events.end());
    const auto [a, b] = e[k];
    // (1) the element's move runs on its offset at exactly r
    RC_ASSERT(std::fabs(side(a, b, xy(main->start)) - want) < 1e-6);
    RC_ASSERT(std::fabs(side(a, b, xy(main->end)) - want) < 1e-6);
    RC_ASSERT((xy(main->end) - xy(main->start)).dot(b - a) > 0);
    if (inside || k + 1 == e.size()) continue;
    // (3) the outside corner at b
    const P2 tA = (b - a).normalized(), tB = (e[k + 1].second - b).normalized();
    const P2 nA = b + want * P2(-tA.y(), tA.x()), nB = b + want * P2(-tB.y(), tB.x());
    std::vector<P2> ends;
    for (auto it = main; it != run.events.end() && it->from.at.line == first + k; ++it)
      ends.push_back(xy(it->end));
    if (tA.dot(tB) >= -1e-9) { // turn of 90° or less: obtuse, alpha >= 90°
      RC_ASSERT(ends.size() == 1u);
      RC_ASSERT(std::fabs(side(b, e[k + 1].second, ends[0]) - want) < 1e-6);
    } else {
      RC_ASSERT(ends.size() == 4u);
      RC_ASSERT((ends[0] - nA).norm() < 1e-6);
      RC_ASSERT((ends[1] - (nA + r * tA)).norm() < 1e-6);
      RC_ASSERT((ends[2] - (nB - r * tB)).norm() < 1e-6);
      RC_ASSERT((ends[3] - nB).norm() < 1e-6);
    }
  }
  // (2) no gouge between start-up and cancel
  for (const motion::Event& ev : run.events) {
    if (ev.kind != motion::Kind::Feed || ev.from.at.line < first || ev.from.at.line > last)
      continue;
    for (std::size_t i = 0; i < c.poly.size(); ++i)
      RC_ASSERT(segmentSegment(xy(ev.start), xy(ev.end), c.poly[i],
                               c.poly[(i + 1) % c.poly.size()]) > r - 1e-6);
  }
}

RC_GTEST_PROP(CompNctSpec_3_17_Property, ConvexPolygonInside, ()) {
  checkPolygon(program(genPolygon(true), true), true, *rc::gen::inRange(5, 80) / 10.0);
}

RC_GTEST_PROP(CompNctSpec_3_17_Property, ConvexPolygonOutside, ()) {
  checkPolygon(program(genPolygon(true), false), false, *rc::gen::inRange(5, 200) / 10.0);
}

RC_GTEST_PROP(CompNctSpec_3_17_Property, ConcavePolygonInside, ()) {
  checkPolygon(program(genPolygon(false), true), true, *rc::gen::inRange(5, 20) / 10.0);
}

RC_GTEST_PROP(CompNctSpec_3_17_Property, CircleInsideAndOutside, ()) {
  const double radius = *rc::gen::inRange(20, 200) / 2.0, r = *rc::gen::inRange(5, 90) / 10.0;
  const double cx = *rc::gen::inRange(-100, 100), cy = *rc::gen::inRange(-100, 100);
  for (bool inside : {true, false}) {
    const std::string text = fmt::format(
        "G17 G90 G0 X{0} Y{1}\n{2} G1 X{3} Y{1} D1 F1000\nG3 I{4}\nG40 G1 X{0} Y{1}\n",
        inside ? cx : cx + radius + 50, cy, inside ? "G41" : "G42", cx + radius, -radius);
    ProgramRun run = runNct(text, compSetup(r));
    RC_ASSERT(run.errors.empty());
    const auto arc = std::find_if(run.events.begin(), run.events.end(),
                                  [](const auto& ev) { return ev.kind == motion::Kind::Arc; });
    RC_ASSERT(arc != run.events.end());
    const double want = inside ? radius - r : radius + r;
    RC_ASSERT((xy(arc->center) - P2(cx, cy)).norm() < 1e-9);
    RC_ASSERT(std::fabs((xy(arc->start) - P2(cx, cy)).norm() - want) < 1e-6);
    RC_ASSERT(std::fabs((xy(arc->end) - P2(cx, cy)).norm() - want) < 1e-6);
    RC_ASSERT((xy(arc->end) - xy(arc->start)).norm() < 1e-9); // the whole circle
  }
}

} // namespace
} // namespace gcx::test
#endif
