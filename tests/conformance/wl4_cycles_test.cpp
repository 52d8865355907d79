// The user canned cycles G81-G89 (wl4.md §5.1, §5.2): the programs %81-%89 WL4 ships, called
// after every block with axis words until G80 with a copy of the locals, on the same engine as
// user programs; a user's own %8n beside the program overrides the shipped one. TV10-TV12.
#include <gtest/gtest.h>

#include "dialects/wl4/system_programs.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4Cycles_8, TV10_G81DrillsAfterEveryBlockWithAxisWordsUntilG80) {
  MacroRun r = runWl4("%TV10\nG90 G17 G0 X0 Y0 Z50\nG81 #2=2 #3=-10 F100\nX10 Y10\nX20\nG80\n"
                      "G0 Z50\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,50", "R 10,10,50", "R 10,10,2", "L 10,10,-10 F100", "R 10,10,2",
                           "R 20,10,2", "L 20,10,-10 F100", "R 20,10,2", "R 20,10,50", "END"}));
}

TEST(Wl4Cycles_8, TV11_G83PecksByTheRestoredProgram) {
  MacroRun r = runWl4("%TV11\nG90 G17 G0 X0 Y0 Z50\nG83 #2=1 #3=-17 #5=5 F100\nG90G0X100Y200\n"
                      "G80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,50", "R 100,200,50", "R 100,200,1", "L 100,200,-4 F100",
                           "R 100,200,1", "R 100,200,-3", "L 100,200,-9 F100", "R 100,200,1",
                           "R 100,200,-8", "L 100,200,-14 F100", "R 100,200,1", "R 100,200,-13",
                           "L 100,200,-17 F100", "R 100,200,1", "END"}));
}

TEST(Wl4Cycles_8, TV12_G84TapsWithTheSpindleReversedAtTheBottom) {
  MacroRun r = runWl4("%TV12\nG90 G17 G0 X0 Y0 Z20 S500 M3\nG84 #2=3 #3=-15 F750\nX30 Y40\n"
                      "G80 M2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"EV S500 M3", "R 0,0,20", "R 30,40,20", "R 30,40,3", "L 30,40,-15 F750",
                           "EV S500 M4", "L 30,40,3 F750", "EV S500 M3", "END"}));
}

TEST(Wl4Cycles_5_2, G82DwellsAtTheBottomByItsG4X) {
  MacroRun r = runWl4("%P\nG90 G0 X0 Y0 Z10\nG82 #2=1 #3=-5 #4=2.5 F100\nX5\nG80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 0,0,10", "R 5,0,10", "R 5,0,1", "L 5,0,-5 F100", "DW 2.5s", "R 5,0,1", "END"}));
}

TEST(Wl4Cycles_5_1, AUserDwellG4XDwellsAndCallsNoCycle) {
  // G4 X2 has an axis letter but is no move: it dwells 2 s, %81 does not run (§5.1, §3.9)
  MacroRun r = runWl4("%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-5 F100\nX5\nG4 X2\nG80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 0,0,10", "R 5,0,10", "R 5,0,1", "L 5,0,-5 F100", "R 5,0,1", "DW 2s", "END"}));
}

TEST(Wl4Cycles_5_1, G92AndAMirrorWithAxisWordsCallNoCycle) {
  MacroRun r =
      runWl4("%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-5 F100\nG92 X0 Y0\nG51 X-1\nG80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,10", "END"}));
}

TEST(Wl4Cycles_5_1, AUsersOwnProgramBesideTheMainOverridesTheShippedCycle) {
  // %81 in a file 81.wl4 beside the program: a single rapid to #3 instead of the drilling
  MacroRun r = runWl4({{"main.wl4", "%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-5\nX5\nG80\nM2\n%\n"},
                       {"81.wl4", "%81\nG0 Z#3\nM99\n%\n"}},
                      "main.wl4");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,10", "R 5,0,10", "R 5,0,-5", "END"}));
}

TEST(Wl4Cycles_5_1, AUnitOfTheSameFileOverridesTheShippedCycleToo) {
  MacroRun r = runWl4("%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-5\nX5\nG80\nM2\n%\n"
                      "%81\nG0 Z#2\nM99\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,10", "R 5,0,10", "R 5,0,1", "END"}));
}

TEST(Wl4Cycles_5_1, ABlockWithoutAxisWordsOnlySelectsTheCycle) {
  // G81 alone, then a block without axis words: no call; the cycle's copy of #2 is the caller's
  MacroRun r = runWl4("%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-5 F50\nF60\n#2=3\nX5\nG80\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,10", "R 5,0,10", "R 5,0,3", "L 5,0,-5 F60", "R 5,0,3", "END"}));
}

TEST(Wl4Cycles_5_1, ANewCycleReplacesTheOneInForceAndG80EndsIt) {
  // G81 then G83: the hole at X5 is drilled by %83 only; after G80 nothing drills
  MacroRun r = runWl4("%P\nG90 G0 X0 Y0 Z10\nG81 #2=1 #3=-2 #5=5 F100\nG83\nX5\nG80\nX9\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 0,0,10", "R 5,0,10", "R 5,0,1", "L 5,0,-2 F100", "R 5,0,1", "R 9,0,1", "END"}));
}

TEST(Wl4Cycles_Examples, TheFlangeDrillsSixHolesOnItsBoltCircle) {
  MacroRun r = runWl4(readFile(sourceDir() / "examples" / "wl4" / "FLANGE.wl4"));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.rendered, ""); // no warning either
  V holes;
  for (const std::string& m : r.motion())
    if (m.rfind("L ", 0) == 0) holes.push_back(m);
  EXPECT_EQ(holes, (V{"L 90,50,-12 F90", "L 70,84.641,-12 F90", "L 30,84.641,-12 F90",
                      "L 10,50,-12 F90", "L 30,15.359,-12 F90", "L 70,15.359,-12 F90"}));
}

TEST(Wl4Cycles_Examples, ThePlateRunsCleanly) {
  MacroRun r = runWl4(readFile(sourceDir() / "examples" / "wl4" / "PLATE.wl4"));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.rendered, "");
  EXPECT_EQ(r.motion().back(), "END");
}

TEST(Wl4Cycles_5_2, EveryShippedProgramReadsCleanlyAsTheUnitItIsCalled) {
  std::vector<std::string> units;
  for (const wl4::SystemProgramText& p : wl4::systemProgramTexts()) {
    Parsed parsed = parseWl4(p.text);
    EXPECT_TRUE(parsed.errors().empty() && parsed.warnings().empty()) << parsed.rendered();
    ASSERT_FALSE(parsed.blocks.empty());
    EXPECT_EQ(parsed.blocks.front().programName, p.unit);
    units.push_back(p.unit);
  }
  EXPECT_EQ(units, (V{"1", "81", "82", "83", "84", "85", "86", "87", "88", "89"}));
}

} // namespace
} // namespace gcx::test
