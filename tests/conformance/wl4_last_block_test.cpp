// #130-#138 and #140, the words of the last blocks (wl4.md §6.2, §10.12; 002:1816-1874): the
// absolute target and the increment of the last block with axis words, whatever block that is
// (not only an open cycle's), the last I J K and P; and §7 example 7, the G38 probe check that
// reads #132.
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4SystemVariables_6_2, TheLastBlockWithAxisWordsGivesItsTargetAndIncrements) {
  MacroRun r = runWl4(
      {{"main.wl4", "%P\nG90 G17 G0 X10 Y20 Z5\n"
                    "#30=#130 #31=#131 #32=#132 #33=#133 #34=#134 #35=#135\n"
                    "G91 G1 X5 W-2 F100\n"
                    "#36=#130 #37=#131 #38=#132 #39=#133 #40=#134 #41=#135\n"
                    "G4 X2\nS100\n#42=#130 #43=#131\n"
                    "G90 G2 X25 Y20 I5 J0\nG1 X30\n#44=#136 #45=#137 #46=#138 #47=#130\n"
                    "M2\n%\n"}},
      "main.wl4", {}, {30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  const double first[] = {10, 10, 20, 20, 5, 5}; // from the power-on position 0
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(r.vars[30 + i].number, first[i]) << "#" << 130 + i;
  // G91 in the block itself: X5 is an increment; Y is not written: its target is where it is
  const double second[] = {15, 5, 20, 0, 3, -2};
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(r.vars[36 + i].number, second[i]) << "#" << 130 + i;
  EXPECT_EQ(r.vars[42].number, 15); // G4 X2 is a dwell, S100 no axis word: still G91 X5's
  EXPECT_EQ(r.vars[43].number, 5);
  EXPECT_EQ(r.vars[44].number, 5); // the last I written, kept by the G1 after the arc
  EXPECT_EQ(r.vars[45].number, 0);
  EXPECT_EQ(r.vars[46].number, 0); // no K written yet
  EXPECT_EQ(r.vars[47].number, 30);
}

TEST(Wl4SystemVariables_6_2, OnALatheTheXTargetAndIncrementAreDiameters) {
  machine::Setup s;
  s.parameters["lathe"] = 1;
  MacroRun r = runWl4({{"main.wl4", "%P\nG18 G90 G0 X40 Z2\nG1 U-10 F0.2\n"
                                    "#30=#130 #31=#131 #32=#134 #33=#135\nM2\n%\n"}},
                      "main.wl4", s, {30, 31, 32, 33});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 20,0,2", "L 15,0,2 F0.2", "END"}));
  EXPECT_EQ(r.vars[30].number, 30);
  EXPECT_EQ(r.vars[31].number, -10);
  EXPECT_EQ(r.vars[32].number, 2);
  EXPECT_EQ(r.vars[33].number, 0);
}

// §7 example 7 (002:946-952): probe in Y; if the touch point #1011 differs from the programmed
// end #132, set Y zero 6.54 from it, else stop. gcx has no probe model: the probe runs to its
// end point (no touch), #1011 = #132 = 100, so the program stops at N05.
TEST(Wl4Examples_7, Example7_WithoutATouchTheProbeCheckStopsAtN05) {
  MacroRun r = runWl4("%P\nG94G38G1Y100F200\nIF (ABS(#132-#1011)>0.01) N010\nN05 M0 N05\n"
                      "N010 G92 Y(#1011+6.54)\nG0 Y0\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"4:1 GCX064"})) << r.rendered;
  EXPECT_NE(r.rendered.find("a program stop that jumps to itself"), std::string::npos)
      << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 0,100,0 F200", "L 0,0,0 F200", "EV M0"})) << r.rendered;
}

TEST(Wl4Examples_7, Example7_AnEndPointApartFromTheTouchPointTakesTheSetBranch) {
  // a move after the probe makes #132 the new target (50): the check sees 50 against 100
  MacroRun r = runWl4("%P\nG94G38G1Y100F200\nG1 Y50\nIF (ABS(#132-#1011)>0.01) N010\n"
                      "N05 M0 N05\nN010 G92 Y(#1011+6.54)\nG0 Y0\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // G92 Y106.54 at Y50: the work zero is 56.54 below; G0 Y0 goes to machine Y -56.54
  EXPECT_EQ(r.motion(),
            (V{"L 0,100,0 F200", "L 0,0,0 F200", "L 0,50,0 F200", "R 0,-56.54,0", "END"}))
      << r.rendered;
}

} // namespace
} // namespace gcx::test
