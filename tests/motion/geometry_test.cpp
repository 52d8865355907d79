#include "motion/geometry.h"

#include <gtest/gtest.h>
#include <numbers>
#include <random>

#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

using test::arc;
constexpr double pi = std::numbers::pi;
constexpr double eps = 1e-9;

void expectVec(const Vec3& actual, const Vec3& expected, double tol = eps) {
  EXPECT_NEAR(actual.x(), expected.x(), tol) << actual.transpose();
  EXPECT_NEAR(actual.y(), expected.y(), tol) << actual.transpose();
  EXPECT_NEAR(actual.z(), expected.z(), tol) << actual.transpose();
}

// A point given in the plane's own (first, second, normal) coordinates.
Vec3 inPlane(Plane p, double u, double v, double w = 0) {
  const PlaneAxes ax = axesOf(p);
  Vec3 r;
  r[ax.first] = u;
  r[ax.second] = v;
  r[ax.normal] = w;
  return r;
}

class ArcInEveryPlane : public ::testing::TestWithParam<Plane> {};

TEST_P(ArcInEveryPlane, QuarterHalfAndFullCirclesBothWays) {
  const Plane p = GetParam();
  const Vec3 c = inPlane(p, 1, 2, 3);
  auto at = [&](double u, double v) { return Vec3(c + inPlane(p, u, v)); };
  struct Case {
    Vec3 from, to;
    bool cw;
    int turns;
    double sweep;
  } cases[] = {
      {at(10, 0), at(0, 10), false, 0, pi / 2},    // quarter CCW
      {at(10, 0), at(0, 10), true, 0, 3 * pi / 2}, // the other way round
      {at(10, 0), at(0, -10), true, 0, pi / 2},    // quarter CW
      {at(10, 0), at(0, -10), false, 0, 3 * pi / 2},
      {at(10, 0), at(-10, 0), false, 0, pi}, // half
      {at(10, 0), at(-10, 0), true, 0, pi},
      {at(10, 0), at(10, 0), false, 0, 2 * pi}, // full
      {at(10, 0), at(10, 0), true, 0, 2 * pi},
      {at(10, 0), at(10, 0), true, 2, 6 * pi},
      {at(10, 0), at(0, 10), false, 1, 2.5 * pi},
  };
  for (const Case& k : cases) {
    const ArcGeometry g(arc(p, k.from, k.to, c, k.cw, k.turns));
    EXPECT_NEAR(g.sweep(), k.sweep, eps);
    EXPECT_NEAR(g.length(), 10 * k.sweep, 1e-9);
    EXPECT_FALSE(g.isSpiral());
    expectVec(g.point(0), k.from);
    expectVec(g.point(1), k.to);
  }
}

TEST_P(ArcInEveryPlane, PointsAndTangentsFollowTheDirection) {
  const Plane p = GetParam();
  const Vec3 c = inPlane(p, 1, 2, 3);
  const double h = std::sqrt(0.5) * 10;
  const ArcGeometry ccw(arc(p, c + inPlane(p, 10, 0), c + inPlane(p, 0, 10), c, false));
  expectVec(ccw.point(0.5), c + inPlane(p, h, h));
  expectVec(ccw.tangent(0), inPlane(p, 0, 1));
  expectVec(ccw.tangent(1), inPlane(p, -1, 0));
  const ArcGeometry cw(arc(p, c + inPlane(p, 10, 0), c + inPlane(p, 0, -10), c, true));
  expectVec(cw.point(0.5), c + inPlane(p, h, -h));
  expectVec(cw.tangent(0), inPlane(p, 0, -1));
}

std::string planeName(const ::testing::TestParamInfo<Plane>& param) {
  return param.param == Plane::XY ? "XY" : param.param == Plane::ZX ? "ZX" : "YZ";
}
INSTANTIATE_TEST_SUITE_P(Planes, ArcInEveryPlane,
                         ::testing::Values(Plane::XY, Plane::ZX, Plane::YZ), planeName);

TEST(ArcGeometry, PlaneAxesFollowRs274) {
  // G18: from Z10 to X10 about the origin is a counter-clockwise quarter seen from +Y.
  EXPECT_NEAR(sweptAngle(arc(Plane::ZX, {0, 0, 10}, {10, 0, 0}, {0, 0, 0}, false)), pi / 2, eps);
  // G19: from Y10 to Z10 is a counter-clockwise quarter seen from +X.
  EXPECT_NEAR(sweptAngle(arc(Plane::YZ, {0, 10, 0}, {0, 0, 10}, {0, 0, 0}, false)), pi / 2, eps);
  // G17: from X10 to Y10 is counter-clockwise seen from +Z.
  EXPECT_NEAR(sweptAngle(arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false)), pi / 2, eps);
}

TEST(ArcGeometry, HelixLength) {
  // NCT TV7 (a): G17 G90 G0 X100 Y0 Z0 / G03 X0 Y100 Z20 R100
  const ArcGeometry a(arc(Plane::XY, {100, 0, 0}, {0, 100, 20}, {0, 0, 0}, false));
  EXPECT_NEAR(a.sweep(), pi / 2, eps);
  EXPECT_NEAR(a.length(), std::hypot(50 * pi, 20), 1e-9);
  expectVec(a.point(0.5), {100 * std::sqrt(0.5), 100 * std::sqrt(0.5), 10});
  expectVec(a.tangent(0), Vec3(0, 50 * pi, 20).normalized());
  // TV7 (b): G0 X-50 Y0 / Z0 / G2 I50 Z-20 L4: four full turns, pitch 5
  const ArcGeometry b(arc(Plane::XY, {-50, 0, 0}, {-50, 0, -20}, {0, 0, 0}, true, 3));
  EXPECT_NEAR(b.sweep(), 8 * pi, eps);
  EXPECT_NEAR(b.length(), 1256.796206301681, 1e-9);
  expectVec(b.point(0.25), {-50, 0, -5});
  expectVec(b.point(0.125 / 4), {-50 * std::sqrt(0.5), 50 * std::sqrt(0.5), -0.625});
  // A helix in G18 rises along Y.
  const ArcGeometry c(arc(Plane::ZX, {0, 0, 10}, {0, 4, 10}, {0, 0, 0}, false));
  EXPECT_NEAR(c.length(), std::hypot(20 * pi, 4), 1e-9);
  expectVec(c.point(0.25), {10, 1, 0});
}

// The radii alone (what a writer tells a spiral by) are ArcGeometry's, in each plane's own axes.
TEST(ArcGeometry, ArcRadiiAreTheGeometrysRadii) {
  const Event spiral = arc(Plane::XY, {90, 0, 0}, {-30, 0, 0}, {0, 0, 0}, false, 2);
  EXPECT_DOUBLE_EQ(arcRadii(spiral).start, 90);
  EXPECT_DOUBLE_EQ(arcRadii(spiral).end, 30);
  // G18: Z and X are the plane's axes; Y (the normal) is not a radius
  const Event zx = arc(Plane::ZX, {3, 7, 4}, {0, -5, 1}, {0, 0, 0}, true);
  EXPECT_DOUBLE_EQ(arcRadii(zx).start, 5);
  EXPECT_DOUBLE_EQ(arcRadii(zx).end, 1);
  const ArcGeometry g(zx);
  EXPECT_EQ(arcRadii(zx).start, g.startRadius());
  EXPECT_EQ(arcRadii(zx).end, g.endRadius());
}

TEST(ArcGeometry, SpiralOfNctTv6) {
  // start (90,0), G3 X-30 I-90 L3: 2.5 turns, radius 90 -> 30 linear in the angle
  const ArcGeometry s(arc(Plane::XY, {90, 0, 0}, {-30, 0, 0}, {0, 0, 0}, false, 2));
  EXPECT_TRUE(s.isSpiral());
  EXPECT_NEAR(s.sweep(), 5 * pi, eps);
  EXPECT_DOUBLE_EQ(s.startRadius(), 90);
  EXPECT_DOUBLE_EQ(s.endRadius(), 30);
  expectVec(s.point(0.2), {-78, 0, 0});
  expectVec(s.point(0.4), {66, 0, 0}); // θ = 360°, the manual's check point
  expectVec(s.point(0.8), {42, 0, 0}); // θ = 720°
  // ∫ √(r² + b²) dθ with b = dr/dθ = −12/π (independently integrated: Simpson, 2·10⁵ steps)
  EXPECT_NEAR(s.length(), 944.572566215394, 1e-9);
  // L1 form: G0 X50 Y0 / G3 X-20 I-50 L1 -> half a turn, radius 50 -> 20
  EXPECT_NEAR(sweptAngle(arc(Plane::XY, {50, 0, 0}, {-20, 0, 0}, {0, 0, 0}, false)), pi, eps);
}

TEST(ArcGeometry, ConicalHelixLength) {
  // G0 X-50 Y0 / Z0 / G2 X-20 I50 Z-20 L4: radius 50 -> 20, four turns, pitch 5
  const ArcGeometry g(arc(Plane::XY, {-50, 0, 0}, {-20, 0, -20}, {0, 0, 0}, true, 3));
  EXPECT_NEAR(g.sweep(), 8 * pi, eps);
  EXPECT_NEAR(g.length(), 880.435402369598, 1e-9);
}

TEST(ArcGeometry, NearlyCircularSpiralLengthIsContinuous) {
  // Radii differing by rounding noise must not change the length visibly.
  const double r = 10 + 1e-9;
  const ArcGeometry g(arc(Plane::XY, {10, 0, 0}, {-r, 0, 1}, {0, 0, 0}, false));
  EXPECT_NEAR(g.length(), std::hypot(10 * pi, 1), 1e-8);
}

TEST(ArcGeometry, BoundsOfCirclesAndArcs) {
  auto box = [](const Event& e) { return ArcGeometry(e).bounds(); };
  const Box3 full = box(arc(Plane::XY, {15, 5, 2}, {15, 5, 2}, {5, 5, 2}, true));
  expectVec(full.min(), {-5, -5, 2});
  expectVec(full.max(), {15, 15, 2});
  const Box3 quarter = box(arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false));
  expectVec(quarter.min(), {0, 0, 0});
  expectVec(quarter.max(), {10, 10, 0});
  const Box3 threeQuarters = box(arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, true));
  expectVec(threeQuarters.min(), {-10, -10, 0});
  expectVec(threeQuarters.max(), {10, 10, 0});
  // 30° -> 60° crosses no axis: the end points are the bounds.
  const double c30 = 10 * std::cos(pi / 6), s30 = 5;
  const Box3 small = box(arc(Plane::XY, {c30, s30, 0}, {s30, c30, 0}, {0, 0, 0}, false));
  expectVec(small.min(), {s30, s30, 0});
  expectVec(small.max(), {c30, c30, 0});
  // G18 half circle with a helix: Z and X bulge, Y runs from start to end.
  const Box3 zx = box(arc(Plane::ZX, {0, 0, 10}, {0, 3, -10}, {0, 0, 0}, false));
  expectVec(zx.min(), {0, 0, -10});
  expectVec(zx.max(), {10, 3, 10});
}

TEST(ArcGeometry, SpiralBoundsMatchDenseSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(0.5, 100), angle(-pi, pi);
  for (int i = 0; i < 60; ++i) {
    const double r0 = radius(rng), r1 = radius(rng), a = angle(rng), b = angle(rng);
    const Event e = arc(Plane::XY, {r0 * std::cos(a), r0 * std::sin(a), 0},
                        {r1 * std::cos(b), r1 * std::sin(b), 1}, {0, 0, 0}, i % 2 == 0, i % 7);
    const ArcGeometry g(e);
    const Box3 exact = g.bounds();
    Box3 sampled;
    const int n = 200000;
    for (int k = 0; k <= n; ++k)
      sampled.extend(g.point(static_cast<double>(k) / n));
    // Dense samples lie inside the exact box and come within their own spacing error of it.
    const double slack = 1e-3;
    for (int d = 0; d < 3; ++d) {
      EXPECT_LE(exact.min()[d], sampled.min()[d] + 1e-9) << i;
      EXPECT_GE(exact.max()[d], sampled.max()[d] - 1e-9) << i;
      EXPECT_NEAR(exact.min()[d], sampled.min()[d], slack) << i;
      EXPECT_NEAR(exact.max()[d], sampled.max()[d], slack) << i;
    }
  }
}

TEST(ArcGeometry, PathLengthAndBoundsOfLines) {
  const Event l = test::feed({0, 0, 0}, {3, 4, 12});
  EXPECT_DOUBLE_EQ(pathLength(l), 13);
  EXPECT_DOUBLE_EQ(pathLength(test::valueEvent(Kind::Dwell, 2)), 0);
  EXPECT_TRUE(pathBounds(test::valueEvent(Kind::Dwell, 2)).isEmpty());
  expectVec(pathBounds(l).max(), {3, 4, 12});
}

} // namespace
} // namespace gcx::motion
