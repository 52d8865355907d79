#include "motion/interpolator.h"

#include <gtest/gtest.h>
#include <numbers>
#include <random>
#include <stdexcept>

#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

using test::Collect;
constexpr double pi = std::numbers::pi;

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

TEST(Interpolator, ChordErrorStaysWithinToleranceOnRandomArcs) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0, 1);
  const Plane planes[] = {Plane::XY, Plane::ZX, Plane::YZ};
  double worstRatio = 0;
  for (int i = 0; i < 400; ++i) {
    const Plane plane = planes[i % 3];
    const PlaneAxes ax = axesOf(plane);
    const Vec3 c(unit(rng) * 20 - 10, unit(rng) * 20 - 10, unit(rng) * 20 - 10);
    const double r0 = 0.1 + unit(rng) * 50;
    const double r1 = i % 4 == 0 ? r0 : 0.1 + unit(rng) * 50; // circles and spirals
    const double a0 = unit(rng) * 2 * pi, a1 = unit(rng) * 2 * pi;
    Vec3 s = c, e = c;
    s[ax.first] += r0 * std::cos(a0);
    s[ax.second] += r0 * std::sin(a0);
    e[ax.first] += r1 * std::cos(a1);
    e[ax.second] += r1 * std::sin(a1);
    e[ax.normal] += i % 3 == 0 ? 0 : unit(rng) * 40 - 20; // helices
    const Event arc = test::arc(plane, s, e, c, unit(rng) < 0.5, static_cast<int>(unit(rng) * 3));
    const double tol = std::pow(10.0, -3 + 3 * unit(rng)); // 0.001 .. 1 mm
    const ArcGeometry g(arc);

    const std::vector<Vec3> pts = samplePoints(arc, tol);
    ASSERT_EQ(pts.size(), arcSegments(g, tol) + 1);
    EXPECT_EQ(pts.front(), arc.start);
    EXPECT_EQ(pts.back(), arc.end);
    const std::size_t n = pts.size() - 1;
    for (std::size_t k = 0; k < n; ++k) {
      for (int j = 1; j < 16; ++j) {
        const double t = (k + j / 16.0) / n;
        const double err = distanceToSegment(g.point(t), pts[k], pts[k + 1]);
        ASSERT_LE(err, tol * (1 + 1e-9)) << "arc " << i << " segment " << k;
        worstRatio = std::max(worstRatio, err / tol);
      }
    }
  }
  // The bound is meant to be tight, not just safe: some arcs come close to the tolerance.
  EXPECT_GT(worstRatio, 0.5);
}

TEST(Interpolator, SegmentCounts) {
  const Event circle = test::arc(Plane::XY, {10, 0, 0}, {10, 0, 0}, {0, 0, 0}, false);
  // Δθ = √(8·0.01/10) per segment -> 71 segments (the exact sagitta rule gives 71 too)
  EXPECT_EQ(arcSegments(ArcGeometry(circle), 0.01), 71u);
  // a coarse tolerance still gives one segment per quarter turn
  EXPECT_EQ(arcSegments(ArcGeometry(circle), 100), 4u);
  EXPECT_THROW(arcSegments(ArcGeometry(circle), 0), std::invalid_argument);
}

TEST(Interpolator, LinesAndOtherEvents) {
  const Event l = test::feed({0, 0, 0}, {1, 2, 3});
  const std::vector<Vec3> pts = samplePoints(l, 0.1);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Vec3(1, 2, 3));
  EXPECT_TRUE(samplePoints(test::valueEvent(Kind::Dwell, 1), 0.1).empty());
}

TEST(ArcLinearizer, TurnsArcsIntoContinuousFeedsAndPassesTheRestThrough) {
  Collect out;
  ArcLinearizer lin(out, 0.01);
  Event a = test::arc(Plane::XY, {10, 0, 0}, {0, 10, 5}, {0, 0, 0}, false, 0, 250);
  a.perRevolution = true;
  a.from.at = SourceLoc{2, 7, 1, 0};
  lin.event(test::rapid({0, 0, 0}, {10, 0, 0}));
  lin.event(a);
  lin.event(test::valueEvent(Kind::Dwell, 1.5));
  lin.finish();

  const std::size_t n = arcSegments(ArcGeometry(a), 0.01);
  ASSERT_EQ(out.events.size(), n + 2);
  EXPECT_EQ(out.events.front().kind, Kind::Rapid);
  EXPECT_EQ(out.events.back().kind, Kind::Dwell);
  Vec3 prev = a.start;
  for (std::size_t i = 1; i <= n; ++i) {
    const Event& e = out.events[i];
    EXPECT_EQ(e.kind, Kind::Feed);
    EXPECT_EQ(e.start, prev);
    EXPECT_EQ(e.feed, 250);
    EXPECT_TRUE(e.perRevolution);
    EXPECT_EQ(e.from.at.line, 7u);
    prev = e.end;
  }
  EXPECT_EQ(prev, a.end);
  EXPECT_TRUE(out.finished);
}

TEST(ArcLinearizer, InterpolatesTheExtraAxesLinearly) {
  Collect out;
  ArcLinearizer lin(out, 0.01);
  const Event a = test::withExtra(test::arc(Plane::XY, {10, 0, 0}, {-10, 0, 0}, {0, 0, 0}, false),
                                  test::extra(0, 10, 0), test::extra(90, 10, 0, 0, 0, -4));
  lin.event(a);
  const std::size_t n = arcSegments(ArcGeometry(a), 0.01);
  ASSERT_EQ(out.events.size(), n);
  Extra prev = a.extraStart;
  for (std::size_t i = 0; i < n; ++i) {
    const Event& e = out.events[i];
    const double t = static_cast<double>(i + 1) / static_cast<double>(n);
    EXPECT_EQ(e.extraStart, prev);
    EXPECT_NEAR(e.extraEnd[0], 90 * t, 1e-12);
    EXPECT_EQ(e.extraEnd[1], 10);
    EXPECT_NEAR(e.extraEnd[5], -4 * t, 1e-12);
    prev = e.extraEnd;
  }
  EXPECT_EQ(prev, a.extraEnd); // exactly
}

} // namespace
} // namespace gcx::motion
