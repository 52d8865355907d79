// The motion and coordinate test vectors of nct.md §7, one test each, asserting the exact motion
// (positions rounded to 4 decimals as in the spec). Positions are the machine-frame gauge point.
#include <gtest/gtest.h>

#include "motion/geometry.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

machine::Setup at(double x, double y, double z) {
  machine::Setup s;
  s.initialPosition = {x, y, z};
  return s;
}

V withoutEnd(V v) {
  if (!v.empty() && v.back() == "END") v.pop_back();
  return v;
}

TEST(NctSpec_7, TV1_CommentsSpanningLinesAndBlockSkip) {
  machine::Setup s;
  s.blockSkip = {1};
  ProgramRun r = runNct("N10 G0 X100 (POSITIONING)\nN20 Z30\n(N30 G1 Z60 F0.3\nN40 X300)\n"
                        "/ N50 G0 X200\n/2 N60 Y50\n",
                        s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,0", "R 100,0,30", "R 100,50,30", "END"}));
}

TEST(NctSpec_7, TV2_IncrementalOperatorAndUVW) {
  for (const char* block :
       {"G90 G01 X20 Y50", "G91 G01 X-40 Y30", "G90 G01 XI-40 YI30", "G90 G01 X20 YI30",
        "G90 G01 XI-40 Y50", "G90 G01 U-40 V30", "G90 G01 X20 V30", "G90 G01 U-40 Y50"}) {
    ProgramRun r = runNct(std::string("F100\n") + block + "\n", at(60, 20, 0));
    ASSERT_TRUE(r.errors.empty()) << block << "\n" << r.rendered;
    EXPECT_EQ(withoutEnd(r.motion()), V{"L 20,50,0 F100"}) << block;
  }
  EXPECT_EQ(runNct("G53 XI10\n").errors, V{"1:5 2097"});
}

TEST(NctSpec_7, TV3_ModalityOfG0G1AndF) {
  ProgramRun r = runNct("G90 G0 X20 Y30 Z0\nX10 Z1\nG1 X80 Y115 F500\nX0\n");
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"R 20,30,0", "R 10,30,1", "L 80,115,1 F500", "L 0,115,1 F500"}));
}

TEST(NctSpec_7, TV4_ArcsByRAndByIJAbsoluteAndIncremental) {
  const V expected{"R 130,0,0",
                   "EV S1000 M3",
                   "L 130,20,0 F500",
                   "CCW 60,90,0 C60,20 r70 θ90",
                   "CW 40,50,0 C10,90 r50 θ53.1301",
                   "L 0,50,0 F500"};
  for (const char* arcs : {"G90\nG3 X60 Y90 R70\nG2 X40 Y50 R50\nG1 X0\n",
                           "G90\nG3 X60 Y90 I-70\nG2 X40 Y50 I-50\nG1 X0\n",
                           "G91\nG3 X-70 Y70 R70\nG2 X-20 Y-40 R50\nG1 X-40\n",
                           "G91\nG3 X-70 Y70 I-70\nG2 X-20 Y-40 I-50\nG1 X-40\n"}) {
    ProgramRun r = runNct(std::string("G90 G17\nG0 X130 Y0 M3 S1000\nG1 Y20 F500\n") + arcs);
    ASSERT_TRUE(r.errors.empty()) << arcs << r.rendered;
    EXPECT_EQ(withoutEnd(r.motion()), expected) << arcs;
  }
  EXPECT_EQ(withoutEnd(runNct("G0 X100 Y0 F500\nG17 G03 X0 Y100 I-100\n").motion()),
            (V{"R 100,0,0", "CCW 0,100,0 C0,0 r100 θ90"}));
  EXPECT_EQ(withoutEnd(runNct("G0 X200 Y0 F500\nG17 G03 I-100\n").motion()),
            (V{"R 200,0,0", "CCW 200,0,0 C100,0 r100 θ360"}));
  ProgramRun noMotion = runNct("G0 X200 Y0 F500\nG17 G03 R100\n");
  EXPECT_TRUE(noMotion.errors.empty());
  EXPECT_EQ(withoutEnd(noMotion.motion()), V{"R 200,0,0"});
  EXPECT_EQ(runNct("G17 G2 X10 Y10 F100\n").errors, V{"1:1 2015"});
  EXPECT_EQ(runNct("G17 G2 X10 K5 F100\n").errors, V{"1:12 2015"});
}

TEST(NctSpec_7, TV5_SignOfR) {
  const std::pair<const char*, const char*> cases[] = {
      {"G2 X50 Y40 R40", "CW 50,40,0 C39.9797,1.2754 r40 θ106.3348"},
      {"G2 X50 Y40 R-40", "CW 50,40,0 C10.0203,38.7246 r40 θ253.6652"},
      {"G3 X50 Y40 R40", "CCW 50,40,0 C10.0203,38.7246 r40 θ106.3348"},
      {"G3 X50 Y40 R-40", "CCW 50,40,0 C39.9797,1.2754 r40 θ253.6652"},
  };
  for (auto [block, expected] : cases) {
    ProgramRun r = runNct(std::string("G90 G17 G0 X0 Y0 F100\n") + block + "\n");
    ASSERT_TRUE(r.errors.empty()) << r.rendered;
    EXPECT_EQ(r.motion().at(0), expected) << block; // G0 X0 Y0 from the origin moves nothing
  }
}

TEST(NctSpec_7, TV6_PlanarSpiralWithLAndRadiusDifferenceAlarm) {
  ProgramRun r = runNct("G17 G90 G94 M3 S1000\nG0 X90 Y0 F1000\nG3 X-30 I-90 L3\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"EV S1000 M3", "R 90,0,0", "CCW -30,0,0 C0,0 r90->30 θ900"}));
  const motion::ArcGeometry g(r.events.at(2));
  EXPECT_EQ(n4(g.point(360.0 / 900).x()), "66"); // check points of the spec
  EXPECT_EQ(n4(g.point(720.0 / 900).x()), "42");
  EXPECT_EQ(r.events.at(2).feed, 1000);
  EXPECT_EQ(runNct("G17 G90 G0 X50 Y0 F100\nG3 X-20 I-50\n").errors, V{"2:1 2012"});
  EXPECT_EQ(withoutEnd(runNct("G17 G90 G0 X50 Y0 F100\nG3 X-20 I-50 L1\n").motion()),
            (V{"R 50,0,0", "CCW -20,0,0 C0,0 r50->20 θ180"}));
}

TEST(NctSpec_7, TV7_HelixMultiTurnHelixConicalHelix) {
  EXPECT_EQ(withoutEnd(runNct("G17 G90 G0 X100 Y0 Z0\nG03 X0 Y100 Z20 R100 F150\n").motion()),
            (V{"R 100,0,0", "CCW 0,100,20 C0,0 r100 θ90"}));
  EXPECT_EQ(withoutEnd(runNct("G54 G17 G90\nG0 X-50 Y0\nZ0\nG2 I50 Z-20 L4 F100\n").motion()),
            (V{"R -50,0,0", "CW -50,0,-20 C0,0 r50 θ1440"}));
  EXPECT_EQ(withoutEnd(runNct("G17 G90\nG0 X-50 Y0\nZ0\nG2 X-20 I50 Z-20 L4 F100\n").motion()),
            (V{"R -50,0,0", "CW -20,0,-20 C0,0 r50->20 θ1440"}));
}

TEST(NctSpec_7, TV9_PolarCoordinatesHexagon) {
  const std::string program = "N1 G90 G17 G0 X120 Y120 F120\nN2 G16 G1 X100 Y60\nN3 Y120\nN4 Y180\n"
                              "N5 Y240\nN6 Y300\nN7 Y0\nN8 Y60\n";
  ProgramRun r = runNct(program + "N9 G15 G0 X120 Y120\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"R 120,120,0", "L 50,86.6025,0 F120", "L -50,86.6025,0 F120", "L -100,0,0 F120",
               "L -50,-86.6025,0 F120", "L 50,-86.6025,0 F120", "L 100,0,0 F120",
               "L 50,86.6025,0 F120", "R 120,120,0"}));
  ProgramRun inc = runNct(program + "G90 G16 G1 X100 YI40\n");
  EXPECT_EQ(inc.motion().at(8), "L -17.3648,98.4808,0 F120");
}

TEST(NctSpec_7, TV13_ToolLengthCompensationIsATransformation) {
  machine::Setup s = at(0, 0, 1200);
  s.tools[1].length = 400;
  s.tools[2].length = 50;
  ProgramRun r = runNct("N1 G90 G0 X500 Y600\nN2 G43 G17 Z410 H1\nN3 G1 Z100 F180\nN4 G4 P2\n"
                        "N5 G0 Z1100 H0\nN6 X-800 Y-300\n",
                        s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 500,600,1200", "R 500,600,810", "L 500,600,500 F180",
                                       "DW 2s", "R 500,600,1100", "R -800,-300,1100"}));
  EXPECT_EQ(withoutEnd(runNct("G43 G0 G91 Z0 H2\n", s).motion()), V{});
  EXPECT_EQ(withoutEnd(runNct("G43 H2\n", s).motion()), V{});
}

// nct.md §3.16: G43.7 H applies the register's turning offsets on all three axes as a
// transformation; G43 returns to the length offset, G49 cancels (000:7194-7237).
TEST(NctSpec_3_16, TurningOffsetsG43_7) {
  machine::Setup s;
  s.tools[11].turning = {150, 0, 90};
  s.tools[11].length = 40;
  ProgramRun r = runNct("G18 G90 G43.7 H11\nG0 X10 Z5\nG43 H11\nG0 X20\nG49\nG0 Z1\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // G43 re-expresses the position (nothing moves): X20 keeps the machine Z of 95
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 160,0,95", "R 20,0,95", "R 20,0,1"}));
}

TEST(NctSpec_7, TV14_WorkOffsetsG52G92) {
  machine::Setup s = at(1000, 1300, 0);
  s.workOffsets["G54"] = {300, 800, 0};
  s.workOffsets["G55"] = {1300, 400, 0};
  ProgramRun readout = runNct("G55\n", s);
  EXPECT_EQ(n4(readout.program.x()) + "," + n4(readout.program.y()), "-300,900");
  EXPECT_EQ(withoutEnd(runNct("G55\nG90 G0 X0 Y0\n", s).motion()), V{"R 1300,400,0"});

  ProgramRun local = runNct("G90 G52 X60 Y40\n", at(150, 100, 0));
  EXPECT_EQ(n4(local.program.x()) + "," + n4(local.program.y()), "90,60");
  EXPECT_EQ(withoutEnd(runNct("G90 G52 X60 Y40\nG90 G0 X0 Y0\n", at(150, 100, 0)).motion()),
            V{"R 60,40,0"});
  for (const char* second : {"G90 G52 X30 Y60\n", "G91 G52 X-30 Y20\n"}) {
    ProgramRun moved = runNct(std::string("G90 G52 X60 Y40\n") + second, at(150, 100, 0));
    EXPECT_EQ(n4(moved.program.x()) + "," + n4(moved.program.y()), "120,40") << second;
  }
  ProgramRun g92 = runNct("G92 X90 Y60\n", at(150, 100, 0));
  EXPECT_EQ(n4(g92.program.x()) + "," + n4(g92.program.y()), "90,60");
  EXPECT_EQ(withoutEnd(runNct("G92 X90 Y60\nG90 G0 X0 Y0\n", at(150, 100, 0)).motion()),
            V{"R 60,40,0"});
  ProgramRun both = runNct("G52 X60 Y40\nG92 X110 Y40\n", at(200, 120, 0));
  EXPECT_EQ(n4(both.program.x()) + "," + n4(both.program.y()), "110,40");
}

TEST(NctSpec_7, TV15a_RotationAboutAPointWithIncrementalMoves) {
  ProgramRun r =
      runNct("G17 G90 G0 X0 Y0\nG68 X10 Y0 R90\nG1 X20 Y0 F100\nG91 X10\nG90 G69 G0 X0 Y0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"L 10,10,0 F100", "L 10,20,0 F100", "R 0,0,0"}));
}

TEST(NctSpec_7, TV15b1_RotationManualExampleAsTypo) {
  ProgramRun r = runNct("N1 G17 G90 G0 X0 Y0\nN2 G68 X90 Y60 R80\nN3 G1 X60 Y20 F150\nN4 X140\n"
                        "N5 G3 Y80 R50\nN6 G1 X60\nN7 Y20\nN8 G69 G0 X0 Y0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"L 124.1829,23.5098,0 F150", "L 138.0747,102.2945,0 F150",
               "CCW 78.9863,112.7134,0 C101.5846,68.1116 r50 θ73.7398", "L 65.0944,33.9287,0 F150",
               "L 124.1829,23.5098,0 F150", "R 0,0,0"}));
}

TEST(NctSpec_7, TV15b2_RotationManualExampleLiteral) {
  ProgramRun r = runNct("N1 G17 G90 G0 X0 Y0\nN2 G68 X90 Y60 R80\nN3 G1 X60 Y20 F150\nN4 G91 X140\n"
                        "N5 G3 Y80 R50\nN6 G1 X60\nN7 Y20\nN8 G69 G0 X0 Y0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"L 124.1829,23.5098,0 F150", "L 148.4936,161.3829,0 F150",
               "CCW 69.709,175.2748,0 C103.8919,138.7846 r50 θ106.2602",
               "L 80.1279,234.3632,0 F150", "L 60.4317,237.8362,0 F150", "R 260,120,0"}));
}

TEST(NctSpec_7, TV16_ScalingG51P) {
  ProgramRun r = runNct("N1 G17 G90 G0 X0 Y0\nN2 G51 X90 Y60 P0.6\nN3 G1 X60 Y20 F150\nN4 X140\n"
                        "N5 G3 Y80 R50\nN6 G1 X60\nN7 Y20\nN8 G50 G0 X0 Y0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"L 72,36,0 F150", "L 120,36,0 F150", "CCW 120,72,0 C96,54 r30 θ73.7398",
               "L 72,72,0 F150", "L 72,36,0 F150", "R 0,0,0"}));
}

TEST(NctSpec_7, TV17_ProgrammableMirror) {
  // O0101 inlined where O0100 calls it (M98 needs the subprogram pass)
  const std::string sub = "G90 G0 X180 Y120 F120\nG1 X240\nY160\nG3 X180 Y120 R80\n";
  ProgramRun r = runNct("G0 X100 Y0\n" + sub + "G51.1 X140\n" + sub + "G51.1 Y100\n" + sub +
                        "G50.1 X0\n" + sub + "G50.1 Y0\nG0 X100 Y0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"R 100,0,0", "R 180,120,0", "L 240,120,0 F120", "L 240,160,0 F120",
               "CCW 180,120,0 C249.6135,80.5797 r80 θ53.5764", "R 100,120,0", "L 40,120,0 F120",
               "L 40,160,0 F120", "CW 100,120,0 C30.3865,80.5797 r80 θ53.5764", "R 100,80,0",
               "L 40,80,0 F120", "L 40,40,0 F120", "CCW 100,80,0 C30.3865,119.4203 r80 θ53.5764",
               "R 180,80,0", "L 240,80,0 F120", "L 240,40,0 F120",
               "CW 180,80,0 C249.6135,119.4203 r80 θ53.5764", "R 100,0,0"}));
  EXPECT_EQ(runNct("G68 X0 Y0 R10\nG51.1 X0\n").errors, V{"2:1 2001"});
}

TEST(NctSpec_7, TV26_G28IntermediatePoint) {
  machine::Setup s = at(20, 50, 0);
  s.referencePoints[1] = {-5, -6, -7};
  EXPECT_EQ(withoutEnd(runNct("G91 G28 X100 Y50\n", s).motion()), (V{"R 120,100,0", "R -5,-6,0"}));
  EXPECT_EQ(withoutEnd(runNct("G90 G28 X100 Y50\n", s).motion()), (V{"R 100,50,0", "R -5,-6,0"}));
}

TEST(NctSpec_7, TV27_DwellSecondsOrRevolutions) {
  EXPECT_EQ(withoutEnd(runNct("G94 G4 P2\n").motion()), V{"DW 2s"});
  EXPECT_EQ(withoutEnd(runNct("G95 G4 P2\n").motion()), V{"DW 2rev"});
  EXPECT_EQ(withoutEnd(runNct("G94 G4 P0.5\n").motion()), V{"DW 0.5s"});
  machine::Setup sec;
  sec.parameters["N1337.SEC"] = 1;
  EXPECT_EQ(withoutEnd(runNct("G95 G4 P2\n", sec).motion()), V{"DW 2s"});
  EXPECT_EQ(runNct("G4 X2\n").errors, V{"1:4 GCX035"});
}

} // namespace
} // namespace gcx::test
