// The test vectors of wl4.md §8 that the machine model runs today, each with the exact motion
// the spec expects (work coordinates, the power-on state of §2.1, zero-length moves omitted).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4Vectors_8, TV4_UVWAreIncrementsInEveryMode) {
  MacroRun r =
      runWl4("%TV4\nG90 G17 G0 X10 Y10 Z5\nG1 U5 V-5 F200\nX30 W-10\nG91 X5 V5\nU-5\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 10,10,5", "L 15,5,5 F200", "L 30,5,-5 F200", "L 35,10,-5 F200",
                           "L 30,10,-5 F200", "END"}));
}

const char* const kTv5 =
    "%TV5\nG18 G90\nN20 G0 X0 Z0\nN21 G1 Z5 F100\nN22 X100\n"
    "/ N23 G0 Z100 M0 $ RUNS ONLY WITH THE FLAG\n/ N24 Z5\nN25 G1 Z20\nM2\n%\n";

TEST(Wl4Vectors_8, TV5_ConditionalBlocksAreSkippedWithTheFlagOff) {
  MacroRun r = runWl4(kTv5);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 0,0,5 F100", "L 100,0,5 F100", "L 100,0,20 F100", "END"}));
}

TEST(Wl4Vectors_8, TV5_ConditionalBlocksRunWithTheFlagOn) {
  machine::Setup on;
  on.blockSkip = {1};
  MacroRun r = runWl4(kTv5, on);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 0,0,5 F100", "L 100,0,5 F100", "R 100,0,100", "EV M0", "R 100,0,5",
                           "L 100,0,20 F100", "END"}));
}

TEST(Wl4Vectors_8, TV6_WordsBeforeAnAssignmentUseTheOldValue) {
  MacroRun r = runWl4({{"main.wl4", "%TV6\nN5 #1=10 #2=20 #3=30 #4=40\n"
                                    "N10 G90 G0 X#1 Z#2 #1=(#1+#3) #2=(#2+#4)\nN15 X#1 Z#2\n"
                                    "N20 #5=(#4/2+15*(#3>#4))\nN25 #5=(#4/2+15*(#3<#4))\n"
                                    "N30 X#1=(ABS(#3-#4) + #5=(40.78*#2))\nM2\n%\n"}},
                      "main.wl4", {}, {1, 5});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 10,0,20", "R 40,0,60", "R 2456.8,0,60", "END"}));
  EXPECT_DOUBLE_EQ(r.vars[5].number, 40.78 * 60);
  EXPECT_DOUBLE_EQ(r.vars[1].number, 10 + 40.78 * 60);
}

TEST(Wl4Vectors_8, TV7_ALabelAndAGuardedJumpLoop) {
  MacroRun r = runWl4("%TV7\nG90 G17 G0 X0 Y0 Z0\n#1=0\nN010 #1=(#1+1) G1 X(#1*10) F100\n"
                      "IF (#1<3) N10\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0,0 F100", "L 20,0,0 F100", "L 30,0,0 F100", "END"}));
}

TEST(Wl4Vectors_8, TV8_AFalseConditionDropsTheRestOfTheBlock) {
  MacroRun r = runWl4("%TV8\nG90 G0 X50 Z150\n#1=5 #2=3\nG1 X0 Z100 F500 IF ((#1-#2)>0) Z0\n"
                      "#1=1\nG1 X10 Z100 IF ((#1-#2)>0) Z0\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 50,0,150", "L 0,0,0 F500", "L 10,0,100 F500", "END"}));
}

TEST(Wl4Vectors_8, TV9_LCallsCopyTheLocalsAndShareTheGlobals) {
  MacroRun r = runWl4({{"main.wl4", "%MAIN\nG90 G17 G0 X0 Y0 Z0\n#1=5 #30=0\nL0702\n"
                                    "G1 X#1 Y#30 F100\nM2\n%\n"
                                    "%07\n#1=(#1*2) #30=(#30+#1)\nG91 G1 X#1 F200\nG90 M99\n%\n"}},
                      "main.wl4");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0,0 F200", "L 20,0,0 F200", "L 5,20,0 F100", "END"}));
}

TEST(Wl4Vectors_8, TV22_IfPrecisionRoundsTheComparison) {
  MacroRun r = runWl4("%TV22\n#1=1.0004 #2=1.0001\nIF3 (#1>#2) G1 X1 F100\n"
                      "IF (#1>#2) G1 X2 F100\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 2,0,0 F100", "END"}));
}

} // namespace
} // namespace gcx::test
