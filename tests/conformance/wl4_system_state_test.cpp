// The system variables of wl4.md §2.2 / §6.2 that read the machine's state (#114 coolant,
// #117 gear range, #141 D, #200 the tool in the spindle), the canned cycles %87/%88 that save
// and restore the gear range, G36 home (§3.7), the G38 probing move and its results #1000-#1027
// (§3.8) and M99 in the main program (§6.7).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4SystemVariables_6_2, CoolantGearDAndToolReadTheMachineState) {
  MacroRun r = runWl4({{"main.wl4", "%P\n#30=#114 #31=#117\nM8 M43 D5 T3 M6\n"
                                    "#32=#114 #33=#117 #34=#141 #35=#200\nT4 M9\n"
                                    "#36=#200 #37=#121 #38=#114\nM2\n%\n"}},
                      "main.wl4", {}, {30, 31, 32, 33, 34, 35, 36, 37, 38});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // power-on: coolant off (M9), the setup's gear range (41 unless "gear_range" says)
  EXPECT_EQ(r.vars[30].number, 9);
  EXPECT_EQ(r.vars[31].number, 41);
  EXPECT_EQ(r.vars[32].number, 8);
  EXPECT_EQ(r.vars[33].number, 43);
  EXPECT_EQ(r.vars[34].number, 5);
  EXPECT_EQ(r.vars[35].number, 3);
  EXPECT_EQ(r.vars[36].number, 3); // T without M6 only selects: the spindle keeps T3
  EXPECT_EQ(r.vars[37].number, 4);
  EXPECT_EQ(r.vars[38].number, 9);
}

TEST(Wl4SystemVariables_6_2, ThePowerOnGearRangeIsASetupParameter) {
  machine::Setup s;
  s.parameters["gear_range"] = 42;
  MacroRun r = runWl4({{"main.wl4", "%P\n#30=#117\nM2\n%\n"}}, "main.wl4", s, {30});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.vars[30].number, 42);
}

TEST(Wl4Cycles_5_2, G87BoresOrientsShiftsAndRestoresTheGearRange) {
  MacroRun r = runWl4("%P\nG90 G17 G0 X0 Y0 Z50 S500 M3 M42\nG87 #2=2 #3=-10 F100\nX10 Y10\n"
                      "G80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"EV S500 M3", "R 0,0,50", "R 10,10,50", "R 10,10,2", "L 10,10,-10 F100", "EV M19",
               "EV S500 M5", "R 10.5,10,-10", "R 10.5,10,2", "EV S500 M3", "END"}));
  EXPECT_TRUE(r.warnings.empty()) << r.rendered; // M40-M48 are gear ranges, not unknown codes
}

TEST(Wl4Cycles_5_2, G88DwellsAtTheBottomBeforeTheOrientation) {
  MacroRun r = runWl4("%P\nG90 G17 G0 X0 Y0 Z50 S500 M3\nG88 #2=2 #3=-10 #4=1.5 F100\nX10\n"
                      "G80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"EV S500 M3", "R 0,0,50", "R 10,0,50", "R 10,0,2", "L 10,0,-10 F100", "DW 1.5s",
               "EV M19", "EV S500 M5", "R 10.5,0,-10", "R 10.5,0,2", "EV S500 M3", "END"}));
}

TEST(Wl4Motion_3_7, G36GoesToMachineZeroOnTheNamedAxesWhateverTheirValues) {
  machine::Setup s;
  s.workOffsets["G54"] = {100, 50, 20};
  MacroRun r = runWl4("%P\nG54 G0 X10 Y10 Z10\nN100 G36 Z55\nN101 G36 X0 Y-3\nG0 X1\nM2\n%\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // machine frame: home Z, then X and Y together; G0 stays modal, X1 is in G54 again
  EXPECT_EQ(r.motion(), (V{"R 110,60,30", "R 110,60,0", "R 0,0,0", "R 101,0,0", "END"}));
}

TEST(Wl4Motion_3_8, G38RunsOutAndBackAndKeepsTheEndPointWithoutAProbeModel) {
  machine::Setup s;
  s.workOffsets["G54"] = {100, 0, 0};
  MacroRun r = runWl4({{"main.wl4", "%P\nG54 G0 X0 Y0 Z0\nG94G38G1Y100F200\n"
                                    "#30=#1001 #31=#1011 #32=#1021 #33=#1010\nG0 X5\nM2\n%\n"}},
                      "main.wl4", s, {30, 31, 32, 33});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,0", "L 100,100,0 F200", "L 100,0,0 F200", "R 105,0,0", "END"}));
  EXPECT_EQ(r.vars[30].number, 100); // machine Y of the (assumed) touch point: the end point
  EXPECT_EQ(r.vars[31].number, 100); // work Y
  EXPECT_EQ(r.vars[32].number, 100); // from the block's start
  EXPECT_EQ(r.vars[33].number, 0);   // work X
  ASSERT_EQ(r.warnings.size(), 1u) << r.rendered;
  EXPECT_NE(r.warnings[0].find(":3:4 GCXW24"), std::string::npos) << r.warnings[0];
}

TEST(Wl4Motion_3_8, G38OnAnArcReturnsAlongTheSameArc) {
  MacroRun r = runWl4("%P\nG17 G0 X0 Y0\nG94G38G2X200Y0R100F200\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"CW 200,0,0 C100,0 r100 θ180", "CCW 0,0,0 C100,0 r100 θ180", "END"}));
}

TEST(Wl4Calls_6_7, M99InTheMainProgramIsAnError) {
  MacroRun r = runWl4("%P\nG0 X1\nG0 X2 M99\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"3:7 GCX067"})) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 2,0,0"})) << r.rendered; // the block's motion ran
}

} // namespace
} // namespace gcx::test
