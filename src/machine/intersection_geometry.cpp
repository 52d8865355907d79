#include "machine/intersection_geometry.h"

#include <algorithm>
#include <cmath>

namespace gcx::machine::comp {

namespace {

constexpr double kSame = 1e-9;

/// Where p lies along the element: the parameter along a line, the swept angle along an arc.
double along(const Path2& e, const Vec2& p) {
  if (!e.arc) return (p - e.a).dot(e.b - e.a);
  double s = std::atan2(cross(e.a - e.c, p - e.c), (e.a - e.c).dot(p - e.c));
  if (!e.ccw) s = -s;
  return s < 0 ? s + 2 * M_PI : s;
}

} // namespace

IntersectionChoice chooseIntersection(const Path2& first, const Path2& second, double q) {
  IntersectionChoice out;
  std::vector<Vec2> points = intersections(first, second);
  if (points.size() == 2 && (points[0] - points[1]).norm() < kSame) points.pop_back();
  if (points.empty()) return out;
  if (points.size() == 1) {
    out.point = points.front();
    return out;
  }
  if (q == 0) {
    out.needsQ = true;
    return out;
  }
  // the line that orders the points: the first element's when it is a line
  const Path2& by = !first.arc ? first : !second.arc ? second : first;
  const auto [near, far] = std::minmax(points[0], points[1], [&](const Vec2& x, const Vec2& y) {
    return along(by, x) < along(by, y);
  });
  out.point = q < 0 ? near : far;
  return out;
}

} // namespace gcx::machine::comp
