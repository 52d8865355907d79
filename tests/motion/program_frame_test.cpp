// The adapters behind the work frame: TransformFrame takes points back through the programmable
// transformations, ProgramUnits into the program's inches (docs/machine-model.md, frames).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "motion/event_builders.h"
#include "motion/program_units.h"
#include "motion/transform_frame.h"

namespace gcx::motion {
namespace {

using namespace test;

void expectNear(const Vec3& got, const Vec3& want) {
  EXPECT_NEAR((got - want).norm(), 0, 1e-12) << got.transpose() << " vs " << want.transpose();
}

TEST(TransformFrame, RotationTakenBackAboutItsCentre) {
  Collect out;
  // G68 X10 Y0 R90: program (20, 0) is at (10, 10)
  const Eigen::Affine3d rotate = Eigen::Translation3d(10, 0, 0) *
                                 Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) *
                                 Eigen::Translation3d(-10, 0, 0);
  TransformFrame program(out, [&] { return rotate; });
  program.event(feed({10, 0, 5}, {10, 10, 5}));
  program.event(valueEvent(Kind::Dwell, 1.5));
  ASSERT_EQ(out.events.size(), 2u);
  expectNear(out.events[0].start, {10, 0, 5});
  expectNear(out.events[0].end, {20, 0, 5});
  EXPECT_EQ(out.events[1].value, 1.5);
}

TEST(TransformFrame, ScaledArcGetsItsProgrammedRadius) {
  Collect out;
  const Eigen::Affine3d twice(Eigen::Scaling(2.0, 2.0, 1.0));
  TransformFrame program(out, [&] { return twice; });
  Event a = arc(Plane::XY, {10, 10, 0}, {30, 10, 0}, {20, 10, 0}, true);
  a.startRadius = a.endRadius = 10;
  program.event(a);
  ASSERT_EQ(out.events.size(), 1u);
  expectNear(out.events[0].start, {5, 5, 0});
  expectNear(out.events[0].end, {15, 5, 0});
  expectNear(out.events[0].center, {10, 5, 0});
  EXPECT_DOUBLE_EQ(out.events[0].startRadius, 5);
  EXPECT_DOUBLE_EQ(out.events[0].endRadius, 5);
  EXPECT_TRUE(out.events[0].clockwise);
}

TEST(TransformFrame, MirroredArcTurnsBack) {
  Collect out;
  const Eigen::Affine3d mirrorX(Eigen::Scaling(-1.0, 1.0, 1.0)); // G51.1 X0
  TransformFrame program(out, [&] { return mirrorX; });
  Event a = arc(Plane::XY, {-5, 5, 0}, {-5, 15, 0}, {-5, 10, 0}, true); // the machine's G2
  a.startRadius = a.endRadius = 5;
  program.event(a);
  ASSERT_EQ(out.events.size(), 1u);
  expectNear(out.events[0].end, {5, 15, 0});
  EXPECT_FALSE(out.events[0].clockwise); // the program's G3
  EXPECT_DOUBLE_EQ(out.events[0].startRadius, 5);
}

TEST(TransformFrame, MirrorOutsideTheArcPlaneKeepsItsDirection) {
  Collect out;
  const Eigen::Affine3d mirrorZ(Eigen::Scaling(1.0, 1.0, -1.0));
  TransformFrame program(out, [&] { return mirrorZ; });
  program.event(arc(Plane::XY, {0, 0, -2}, {10, 0, -2}, {5, 0, -2}, true));
  ASSERT_EQ(out.events.size(), 1u);
  expectNear(out.events[0].end, {10, 0, 2});
  EXPECT_TRUE(out.events[0].clockwise);
}

TEST(ProgramUnits, InchesAfterG20MillimetresAfterG21) {
  Collect out;
  ProgramUnits units(out);
  units.event(feed({0, 0, 0}, {25.4, 50.8, 0}, 254));
  units.event(valueEvent(Kind::UnitsChange, 20));
  Event f = withExtra(feed({25.4, 50.8, 0}, {50.8, 0, -12.7}, 127), extra(90, 0, 0, 25.4),
                      extra(180, 0, 0, 50.8));
  f.lead = 2.54; // a thread's lead per revolution
  units.event(f);
  Event a = arc(Plane::XY, {0, 0, 0}, {50.8, 0, 0}, {25.4, 0, 0}, false, 0, 254);
  a.startRadius = a.endRadius = 25.4;
  units.event(a);
  units.event(valueEvent(Kind::Dwell, 2));
  units.event(valueEvent(Kind::UnitsChange, 21));
  units.event(feed({50.8, 0, 0}, {0, 0, 0}, 100));
  units.finish();
  ASSERT_EQ(out.events.size(), 7u);
  EXPECT_EQ(out.events[0].end, Vec3(25.4, 50.8, 0)); // before G20: mm
  EXPECT_EQ(out.events[0].feed, 254);
  expectNear(out.events[2].start, {1, 2, 0});
  expectNear(out.events[2].end, {2, 0, -0.5});
  EXPECT_DOUBLE_EQ(out.events[2].feed, 5);
  EXPECT_DOUBLE_EQ(out.events[2].extraStart[0], 90); // A stays in degrees
  EXPECT_DOUBLE_EQ(out.events[2].extraEnd[0], 180);
  EXPECT_DOUBLE_EQ(out.events[2].extraStart[3], 1); // U in inches
  EXPECT_DOUBLE_EQ(out.events[2].extraEnd[3], 2);
  EXPECT_DOUBLE_EQ(out.events[2].lead, 0.1);
  expectNear(out.events[3].center, {1, 0, 0});
  EXPECT_DOUBLE_EQ(out.events[3].startRadius, 1);
  EXPECT_DOUBLE_EQ(out.events[3].feed, 10);
  EXPECT_EQ(out.events[4].value, 2); // a dwell is no length
  EXPECT_EQ(out.events[6].end, Vec3(0, 0, 0));
  EXPECT_EQ(out.events[6].feed, 100);
  EXPECT_TRUE(out.finished);
}

} // namespace
} // namespace gcx::motion
