#include "report/path_recorder.h"

#include <gtest/gtest.h>

#include "motion/event_builders.h"

namespace gcx::report {
namespace {

using motion::Kind;
using motion::Plane;
using motion::Vec2;
using motion::Vec3;
using motion::View;
using namespace motion::test;
using Pen = PathRecorder::Pen;

TEST(PathRecorder, CollinearPiecesOfOneStyleTakeOneVertex) {
  PathRecorder r;
  r.event(feed({0, 0, 0}, {1, 0, 0}));
  r.event(motion::test::valueEvent(Kind::Spindle, 1000)); // not motion: ignored
  r.event(feed({1, 0, 0}, {2.5, 0, 0}));
  r.event(feed({2.5, 0, 0}, {4, 0, 0}));
  r.event(feed({4, 0, 0}, {4, 3, 0}));
  ASSERT_EQ(r.vertices().size(), 3u);
  EXPECT_EQ(r.vertices()[0].p, Vec3(0, 0, 0));
  EXPECT_EQ(r.vertices()[0].pen, Pen::Up);
  EXPECT_EQ(r.vertices()[1].p, Vec3(4, 0, 0));
  EXPECT_EQ(r.vertices()[2].p, Vec3(4, 3, 0));
  EXPECT_EQ(r.stride(), 1u);
}

TEST(PathRecorder, RapidsAndFeedsStayApartAndJumpsStartNewRuns) {
  PathRecorder r;
  r.event(rapid({0, 0, 10}, {0, 0, 2}));
  r.event(rapid({0, 0, 2}, {0, 0, 0})); // collinear rapid: merged
  r.event(feed({0, 0, 0}, {10, 0, 0}));
  r.event(feed({20, 0, 0}, {20, 0, 5})); // starts elsewhere
  ASSERT_EQ(r.vertices().size(), 5u);
  EXPECT_EQ(r.vertices()[1].pen, Pen::Rapid);
  EXPECT_EQ(r.vertices()[2].pen, Pen::Feed);
  EXPECT_EQ(r.vertices()[3].pen, Pen::Up);
  // XZ: Z right, X up
  const auto runs = r.polylines(View::XZ);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_TRUE(runs[0].rapid);
  EXPECT_EQ(runs[0].points, (std::vector<Vec2>{{10, 0}, {0, 0}}));
  EXPECT_FALSE(runs[1].rapid);
  EXPECT_EQ(runs[1].points, (std::vector<Vec2>{{0, 0}, {0, 10}}));
  EXPECT_EQ(runs[2].points, (std::vector<Vec2>{{0, 20}, {5, 20}}));
  EXPECT_EQ(r.bounds().min(), Vec3(0, 0, 0));
  EXPECT_EQ(r.bounds().max(), Vec3(20, 0, 10));
}

TEST(PathRecorder, ArcsAreSampledToAThousandthOfTheirRadius) {
  PathRecorder r;
  r.event(arc(Plane::XY, {10, 0, 0}, {10, 0, 0}, {0, 0, 0}, false)); // full circle
  // chord error 0.01 on radius 10: ceil(2π / √(8·0.01/10)) = 71 segments
  EXPECT_EQ(r.vertices().size(), 72u);
  EXPECT_EQ(r.vertices().back().p, Vec3(10, 0, 0));
  EXPECT_NEAR(r.bounds().min().y(), -10, 1e-9);
}

TEST(PathRecorder, MemoryStaysBoundedAndBothEndsStayExact) {
  PathRecorder r(1000);
  Vec3 at(0, 0, 0);
  for (int i = 0; i < 1'000'000; ++i) { // a zigzag: nothing merges
    const Vec3 to(i + 1, (i % 2) ? 0 : 5, 0);
    r.event(i % 7 == 0 ? rapid(at, to) : feed(at, to));
    at = to;
  }
  EXPECT_LE(r.vertices().size(), 1000u);
  EXPECT_GE(r.vertices().size(), 500u);
  EXPECT_EQ(r.stride(), 1024u); // 1,000,001 vertices halved 10 times to fit
  EXPECT_EQ(r.vertices().front().p, Vec3(0, 0, 0));
  EXPECT_EQ(r.vertices().back().p, at);
  EXPECT_EQ(r.bounds().max(), Vec3(1'000'000, 5, 0));
}

TEST(PathRecorder, DecimationKeepsFeedsOverRapidsAndJumps) {
  PathRecorder r(4);
  r.event(rapid({0, 0, 0}, {1, 1, 0}));
  r.event(feed({1, 1, 0}, {2, 0, 0}));
  r.event(rapid({2, 0, 0}, {3, 1, 0}));
  r.event(rapid({3, 1, 0}, {4, 0, 0})); // the fifth vertex: compaction
  ASSERT_EQ(r.vertices().size(), 3u);
  EXPECT_EQ(r.vertices()[0].pen, Pen::Up);
  EXPECT_EQ(r.vertices()[1].p, Vec3(2, 0, 0));
  EXPECT_EQ(r.vertices()[1].pen, Pen::Feed); // rapid + feed
  EXPECT_EQ(r.vertices()[2].p, Vec3(4, 0, 0));
  EXPECT_EQ(r.vertices()[2].pen, Pen::Rapid);
  // from now on every second input folds into the vertex before it
  r.event(feed({4, 0, 0}, {5, 1, 0}));  // a new vertex (5,1): 4 in all
  r.event(rapid({7, 1, 0}, {8, 0, 0})); // the jump to (7,1) folds into it, (8,0) is the fifth
  // compaction again: (2,0)+(4,0) → (4,0) feed; (7,1) jump + (8,0) rapid → (8,0) jump
  ASSERT_EQ(r.vertices().size(), 3u);
  EXPECT_EQ(r.vertices()[1].p, Vec3(4, 0, 0));
  EXPECT_EQ(r.vertices()[1].pen, Pen::Feed);
  EXPECT_EQ(r.vertices()[2].p, Vec3(8, 0, 0));
  EXPECT_EQ(r.vertices()[2].pen, Pen::Up);
  EXPECT_EQ(r.stride(), 4u);
}

} // namespace
} // namespace gcx::report
