// TV13-TV17 of wl4.md §8 (the open cycles of %1) on the lathe profile (§0.2, setup `lathe` = 1):
// the X words are diameters, so every X of the vector is a diameter and the motion holds its
// radius (half of it); the restored %1 reads #130/#131 as diameters (§5.4). A user's own %1
// overrides the shipped one (§5.1).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

MacroRun onALathe(const std::string& body) {
  machine::Setup s;
  s.parameters["lathe"] = 1;
  return runWl4("%P\nG18 G90\n" + body + "M2\n%\n", s);
}

TEST(Wl4LatheOpenCycles_8, TV13_G70WithXAsADiameter) {
  MacroRun r = onALathe("G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=10\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 50,0,5", "R 30,0,5", "L 30,0,-40 F0.2", "L 45,0,-50 F0.2",
                           "L 50,0,-50 F0.2", "R 50,0,5", "END"}));
}

TEST(Wl4LatheOpenCycles_8, TV14_G72WithXAsADiameter) {
  MacroRun r = onALathe("G0 X50 Z-20\nG72 X30 W-5 F0.05 #1=6 #2=1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 25,0,-20", "L 22,0,-20 F0.05", "R 25,0,-20", "R 22.5,0,-20", "L 19,0,-20 F0.05",
               "R 25,0,-20", "R 19.5,0,-20", "L 16,0,-20 F0.05", "R 25,0,-20", "R 16.5,0,-20",
               "L 15,0,-20 F0.05", "R 25,0,-20", "R 25,0,-25", "END"}));
}

TEST(Wl4LatheOpenCycles_8, TV15_G74WithXAsADiameter) {
  MacroRun r = onALathe("G0 X80 Z2\nG74 X50 Z-5 F0.05 #1=8\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // the diameters 80, 72, 64, 56, 50 as radii
  V expected{"R 40,0,2"};
  for (const char* x : {"40", "36", "32", "28", "25"}) {
    if (std::string(x) != "40") expected.push_back(fmt::format("R {},0,2", x));
    expected.push_back(fmt::format("L {},0,-5 F0.05", x));
    expected.push_back(fmt::format("R {},0,2", x));
  }
  expected.push_back("END");
  EXPECT_EQ(r.motion(), expected);
}

TEST(Wl4LatheOpenCycles_8, TV16_G77WithXAsADiameter) {
  MacroRun r = onALathe("G0 X50 Z2\nG77 X40 Z-30 F0.3 #1=4 #2=2.5 #3=0.1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 25,0,2", "R 23,0,2", "L 23,0,-29 F0.3", "R 25,0,-25", "R 25,0,2",
                           "R 21,0,2", "L 21,0,-28 F0.3", "R 23,0,-24", "R 23,0,2", "R 20,0,2",
                           "L 20,0,-27.5 F0.1", "L 25,0,-30 F0.1", "R 25,0,2", "END"}));
}

TEST(Wl4LatheOpenCycles_8, TV17_G78WithXAsADiameter) {
  MacroRun r = onALathe("G0 X52 Z0\nG78 X20 Z-6 F0.2 #1=2 #2=3 #3=0.1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 26,0,0", "R 26,0,-2", "L 10.5,0,-2 F0.2", "R 11.5,0,0", "R 26,0,0",
                           "R 26,0,-4", "L 11,0,-4 F0.2", "R 12,0,-2", "R 26,0,-2", "R 26,0,-6",
                           "L 11.5,0,-6 F0.1", "L 10,0,0 F0.1", "R 26,0,0", "END"}));
}

TEST(Wl4OpenCycles_5_1, AUsersOwnPercent1BesideTheProgramOverridesTheShippedOne) {
  // this %1 goes to the cycle's target (#130, #134) in one rapid: the shipped %1 would turn
  MacroRun r =
      runWl4({{"main.wl4", "%P\nG18 G90 G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=10\nM2\n%\n"},
              {"1.wl4", "%1\nG0 X#130 Z#134\nM99\n%\n"}},
             "main.wl4");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,5", "R 60,0,-50", "END"}));
}

TEST(Wl4OpenCycles_5_1, AUsersOwnPercent1InTheSameFileOverridesTheShippedOne) {
  // it reads the target first, as the shipped %1 does: its own G0 Z is a block with axis words
  MacroRun r = runWl4("%P\nG18 G90 G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=10\nM2\n%\n"
                      "%1\n#20=#130 #21=#134\nG0 Z#21\nG0 X#20\nM99\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,5", "R 100,0,-50", "R 60,0,-50", "END"}));
}

} // namespace
} // namespace gcx::test
