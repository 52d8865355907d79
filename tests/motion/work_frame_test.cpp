#include "motion/work_frame.h"

#include <gtest/gtest.h>

#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

using namespace test;

TEST(WorkFrame, EachMoveRelativeToTheOriginInForceWhenItCame) {
  Collect out;
  Vec3 origin(100, 50, -200);
  WorkFrame work(out, [&origin] { return origin; });
  work.event(feed({110, 60, -195}, {120, 60, -195}));
  work.event(valueEvent(Kind::Dwell, 2)); // passes unchanged
  origin = Vec3(100, 50, -100);           // e.g. a new tool length
  work.event(arc(Plane::XY, {120, 60, -95}, {130, 70, -95}, {120, 70, -95}, false));
  work.finish();
  ASSERT_EQ(out.events.size(), 3u);
  EXPECT_EQ(out.events[0].start, Vec3(10, 10, 5));
  EXPECT_EQ(out.events[0].end, Vec3(20, 10, 5));
  EXPECT_EQ(out.events[1].kind, Kind::Dwell);
  EXPECT_EQ(out.events[1].value, 2);
  EXPECT_EQ(out.events[2].start, Vec3(20, 10, 5));
  EXPECT_EQ(out.events[2].end, Vec3(30, 20, 5));
  EXPECT_EQ(out.events[2].center, Vec3(20, 20, 5));
  EXPECT_TRUE(out.finished);
}

} // namespace
} // namespace gcx::motion
