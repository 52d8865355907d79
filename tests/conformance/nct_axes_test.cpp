// nct.md §3.6 parallel axes (TV8), §3.10 rotary rollover (TV25), §3.8 diameter programming,
// §3.18 constant surface speed, and the modal-change events of the motion stream.
#include <gtest/gtest.h>

#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

V withoutEnd(V v) {
  if (!v.empty() && v.back() == "END") v.pop_back();
  return v;
}

TEST(NctSpec_7, TV8_PlaneSelectionWithParallelAxes) {
  machine::Setup s; // U, V, W configured as axes parallel to X, Y, Z for this vector only
  s.parameters["N0103.U"] = s.parameters["N0103.V"] = s.parameters["N0103.W"] = 1;
  ProgramRun r = runNct("G17 U10 V20\nX5 Y5\nG18 W0\nG90 G17 G00 Z100\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.all()), (V{"PLANE UV", "R 0,0,0 U10 V20", "R 5,5,0 U10 V20", "PLANE WX",
                                    "PLANE XY", "R 5,5,100 U10 V20"}));
  // an arc in a plane of parallel axes is refused, not approximated
  EXPECT_EQ(runNct("G17 U0 V0\nG2 U10 V0 I5 F100\n", s).errors, V{"2:1 GCX030"});
}

struct RolloverCase {
  double abs, ash, start;
  const char* block;
  double delta, display;
};

TEST(NctSpec_7, TV25_RotaryRollover) {
  const RolloverCase cases[] = {
      {0, 0, 0, "G90 C570", 210, 210},  {0, 0, 0, "G90 C-930", -210, 150},
      {0, 1, 0, "G90 C210", -150, 210}, {1, 0, 0, "G90 C-30", -330, 30},
      {1, 0, 30, "G90 C0", 330, 0},     {1, 0, 30, "G90 C-360", -30, 0},
  };
  for (const RolloverCase& c : cases) {
    machine::Setup s;
    s.parameters["N0107.REN"] = 1;
    s.parameters["N0107.ABS"] = c.abs;
    s.parameters["N0107.ASH"] = c.ash;
    s.parameters["N0108"] = 360;
    std::string program = "G0\n";
    if (c.start != 0) program += "G90 C" + n4(c.start) + "\n";
    ProgramRun r = runNct(program + c.block + "\n", s);
    ASSERT_TRUE(r.errors.empty()) << r.rendered;
    ASSERT_GE(r.events.size(), 2u);
    const motion::Event& e = r.events[r.events.size() - 2]; // the last move (before END)
    EXPECT_EQ(n4(e.extraEnd[2] - e.extraStart[2]), n4(c.delta)) << c.block;
    double display = std::fmod(e.extraEnd[2], 360.0);
    if (display < 0) display += 360;
    EXPECT_EQ(n4(display), n4(c.display)) << c.block;
  }
}

TEST(NctSpec_3_10, RotaryAxesWithoutRolloverAreLinear) {
  ProgramRun r = runNct("G0 X10 A90\nG91 G1 C-400 F3600\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 10,0,0 A90", "L 10,0,0 A90 C-400 F3600"}));
}

TEST(NctSpec_3_8, DiameterProgrammingHalvesTheAxisValues) {
  machine::Setup s;
  s.parameters["N0106.DIAX"] = 1;
  ProgramRun r = runNct("G0 X100 Y10\nG91 G1 X-20 F100\nG10.9 X0\nG90 G0 X100\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 50,10,0", "L 40,10,0 F100", "R 100,10,0"}));
  EXPECT_EQ(runNct("G10.9 X2\n").errors, V{"1:7 2002"});
}

TEST(NctSpec_3_18, ConstantSurfaceSpeedFollowsTheRadius) {
  ProgramRun r = runNct("G0 X50\nG96 S200 M3\nG1 X25 F100\nG92 S1000\nG1 X10\nG97 S800\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // 200 m/min at r = 50 mm: 636.6198 rpm; at 25 mm: 1273.2395; the G92 S1000 limit acts at
  // once, and at 10 mm (3183 rpm) the limit still holds
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"R 50,0,0", "EV S636.6198 M3", "L 25,0,0 F100", "EV S1273.2395 M3", "EV S1000 M3",
               "L 10,0,0 F100", "EV S800 M3"}));
  EXPECT_EQ(runNct("G0 X0\nG96 S200 M3\n").errors, V{"2:1 2004"});
  EXPECT_EQ(runNct("G92 X0 S1000\n").errors, V{"1:8 2017"});
}

TEST(MotionEvents, ModalChangesAreEventsOfTheStream) {
  ProgramRun r = runNct("G18\nG20\nG95\nG17 G21 G94\nG17\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.all()),
            (V{"PLANE ZX", "UNITS G20", "FEEDMODE G95", "PLANE XY", "UNITS G21", "FEEDMODE G94"}));
}

} // namespace
} // namespace gcx::test
