// The open cycles G70-G75, G77, G78 run by the restored system program %1 (wl4.md §5.1, §5.3,
// §5.4): each test vector TV13-TV17 and each worked example of §5.5 with its exact motion (lathe
// programs: X is the diameter as written, Y stays 0), the error stops of %1, the system
// variables #100 and up, and the call nesting limit of §6.7.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

MacroRun lathe(const std::string& body) {
  return runWl4("%P\nG18 G90\n" + body + "M2\n%\n");
}

TEST(Wl4OpenCycles_8, TV13_G70LongitudinalPassWithTaperAndFacing) {
  MacroRun r = lathe("G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=10\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,5", "R 60,0,5", "L 60,0,-40 F0.2", "L 90,0,-50 F0.2",
                           "L 100,0,-50 F0.2", "R 100,0,5", "END"}));
}

TEST(Wl4OpenCycles_5_5, G71TransversePassWithTaper) {
  MacroRun r = lathe("G0 X100 Z5\nG71 X20 Z-5 F0.2 #1=10 #2=3\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,5", "R 100,0,-5", "L 30,0,-5 F0.2", "L 20,0,2 F0.2",
                           "L 20,0,5 F0.2", "R 100,0,5", "END"}));
}

TEST(Wl4OpenCycles_8, TV14_G72DeepGrooveByXPecks) {
  MacroRun r = lathe("G0 X50 Z-20\nG72 X30 W-5 F0.05 #1=6 #2=1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 50,0,-20", "L 44,0,-20 F0.05", "R 50,0,-20", "R 45,0,-20", "L 38,0,-20 F0.05",
               "R 50,0,-20", "R 39,0,-20", "L 32,0,-20 F0.05", "R 50,0,-20", "R 33,0,-20",
               "L 30,0,-20 F0.05", "R 50,0,-20", "R 50,0,-25", "END"}));
}

TEST(Wl4OpenCycles_5_5, G73DeepDrillingByZPecks) {
  MacroRun r = lathe("G0 X0 Z5\nG73 X0 Z-30 F0.1 #1=10 #2=1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,5", "L 0,0,-5 F0.1", "R 0,0,5", "R 0,0,-4", "L 0,0,-15 F0.1",
                           "R 0,0,5", "R 0,0,-14", "L 0,0,-25 F0.1", "R 0,0,5", "R 0,0,-24",
                           "L 0,0,-30 F0.1", "R 0,0,5", "END"}));
}

TEST(Wl4OpenCycles_8, TV15_G74FaceGrooves) {
  MacroRun r = lathe("G0 X80 Z2\nG74 X50 Z-5 F0.05 #1=8\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V expected{"R 80,0,2"};
  for (const char* x : {"80", "72", "64", "56", "50"}) {
    if (std::string(x) != "80") expected.push_back(fmt::format("R {},0,2", x));
    expected.push_back(fmt::format("L {},0,-5 F0.05", x));
    expected.push_back(fmt::format("R {},0,2", x));
  }
  expected.push_back("END");
  EXPECT_EQ(r.motion(), expected);
}

TEST(Wl4OpenCycles_5_5, G75CylindricalGrooves) {
  MacroRun r = lathe("G0 X60 Z-10\nG75 X40 Z-30 F0.05 #1=7\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V expected{"R 60,0,-10"};
  for (const char* z : {"-10", "-17", "-24", "-30"}) {
    if (std::string(z) != "-10") expected.push_back(fmt::format("R 60,0,{}", z));
    expected.push_back(fmt::format("L 40,0,{} F0.05", z));
    expected.push_back(fmt::format("R 60,0,{}", z));
  }
  expected.push_back("END");
  EXPECT_EQ(r.motion(), expected);
}

TEST(Wl4OpenCycles_8, TV16_G77LongitudinalRoughing) {
  MacroRun r = lathe("G0 X50 Z2\nG77 X40 Z-30 F0.3 #1=4 #2=2.5 #3=0.1\nG1 Z0\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(),
            (V{"R 50,0,2", "R 46,0,2", "L 46,0,-29 F0.3", "R 50,0,-25", "R 50,0,2", "R 42,0,2",
               "L 42,0,-28 F0.3", "R 46,0,-24", "R 46,0,2", "R 40,0,2", "L 40,0,-27.5 F0.1",
               "L 50,0,-30 F0.1", "R 50,0,2", "L 50,0,0 F0.3", "END"})); // F back to 0.3
}

TEST(Wl4OpenCycles_8, TV17_G78TransverseRoughing) {
  MacroRun r = lathe("G0 X52 Z0\nG78 X20 Z-6 F0.2 #1=2 #2=3 #3=0.1\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 52,0,0", "R 52,0,-2", "L 21,0,-2 F0.2", "R 23,0,0", "R 52,0,0",
                           "R 52,0,-4", "L 22,0,-4 F0.2", "R 24,0,-2", "R 52,0,-2", "R 52,0,-6",
                           "L 23,0,-6 F0.1", "L 20,0,0 F0.1", "R 52,0,0", "END"}));
}

TEST(Wl4OpenCycles_5_1, TheCycleBlocksOwnWordsRunAndItsLocalsAreACopy) {
  // F and #1/#2 of the block reach %1; the caller's #1 is unchanged afterwards (§5.1)
  MacroRun r = lathe("G0 X100 Z5\n#1=10 #2=10\nG70 X60 Z-50 F0.2\nG1 X#1 Z#2\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion().back(), "END");
  EXPECT_EQ(r.motion()[r.motion().size() - 2], "L 10,0,10 F0.2");
}

TEST(Wl4OpenCycles_5_1, AModalCannedCycleDoesNotRunInsidePercent1) {
  // G81 in force: %1's moves are blocks with axis words, yet no %81 runs inside it (§5.1)
  MacroRun r = lathe("G0 X100 Z5\nG81 #2=2 #3=-1\nG70 X60 Z-50 F0.2 #1=10 #2=10\nG80\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,0,5", "R 60,0,5", "L 60,0,-40 F0.2", "L 90,0,-50 F0.2",
                           "L 100,0,-50 F0.2", "R 100,0,5", "END"}));
}

TEST(Wl4OpenCycles_5_3, ABadParameterStopsAtTheCycleWithPercent1sMessage) {
  // #2 (10 + 50) exceeds the X travel of 40: %1 jumps to N07010, which loops on itself
  MacroRun r = lathe("G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=50\n");
  ASSERT_EQ(errorsAt(r), (V{"4:1 GCX064"})) << r.rendered;
  EXPECT_NE(r.rendered.find("error: ERROR IN G70 > PARAMETER #2 > Xrel (the error stop of %1)"),
            std::string::npos)
      << r.rendered;
}

TEST(Wl4OpenCycles_5_3, EachCyclesChecksStopWithTheirMessages) {
  struct Case {
    const char* block;
    const char* message;
  } cases[] = {
      // the manual's messages word for word (002:3527-3680)
      {"G71 X20 Z-5 F0.2 #1=-1 #2=3", "ERROR IN G71 > PARAMETER #1 < 0"},
      {"G72 X30 W-5 F0.05 #1=6 #2=7", "ERROR IN G72 > PARAMETER #1 > #2"},
      {"G73 X0 Z-30 F0.1 #1=0 #2=0", "ERROR IN G73 > PARAMETER #1 <= 0"},
      {"G74 X50 Z-5 F0.05 #1=80", "ERROR IN G74 > PARAMETER #1 > Xrel"},
      {"G75 X40 Z-5 F0.05 #1=8", "ERROR IN G75 > PARAMETER #1 > Zrel"},
      {"G77 X40 Z-30 F0.3 #1=4 #2=-1 #3=0.1", "ERROR IN G77 > PARAMETER #2 < 0"},
      // G78 checks #1 against the Z travel (8) and #2 against the X travel (30), but its
      // messages are G77's as the manual prints them (002:3677-3678)
      {"G78 X20 Z-6 F0.2 #1=10 #2=3 #3=0.1", "ERROR IN G78 > PARAMETER #1 > Xrel"},
      {"G78 X20 Z-6 F0.2 #1=2 #2=40 #3=0.1", "ERROR IN G78 > PARAMETER #2 > Zrel"},
  };
  for (const Case& c : cases) {
    MacroRun r = lathe(std::string("G0 X50 Z2\n") + c.block + "\n");
    EXPECT_EQ(errorsAt(r), (V{"4:1 GCX064"})) << c.block << "\n" << r.rendered;
    EXPECT_NE(r.rendered.find(c.message), std::string::npos) << c.block << "\n" << r.rendered;
  }
}

TEST(Wl4OpenCycles_5_3, G79IsAnUnknownCycleOfPercent1) {
  // %1 has no section for #108 = 79: its dispatch falls through to N010, which loops on itself
  MacroRun r = lathe("G0 X50 Z2\nG79 X40 Z-30 F0.3\n");
  ASSERT_EQ(errorsAt(r), (V{"4:1 GCX064"})) << r.rendered;
  EXPECT_NE(r.rendered.find("error: ERROR > UNKNOWN CYCLE IN RANGE G70-G79 (the error stop of %1)"),
            std::string::npos)
      << r.rendered;
  // the cycle's target is no move; %1's stop block runs its M0
  EXPECT_EQ(r.motion(), (V{"R 50,0,2", "EV M0"})) << r.rendered;
}

TEST(Wl4OpenCycles_5_1, G77WithPIsTheContourCycleNotPercent1) {
  // with P the block is the internal cycle (wl4.md §5.6): its contour N200-N202 is looked for,
  // and %1 is not called (tests/conformance/wl4_contour_cycles_test.cpp runs it)
  MacroRun r = lathe("G0 X50 Z2\nG77 P200 Q202 G1 X30 Z0 E2.5 F0.25\n");
  EXPECT_EQ(errorsAt(r), (V{"4:5 CYC-PQ-NOTFOUND"})) << r.rendered;
}

TEST(Wl4SystemVariables_6_2, ModalGroupsReadAsTheirCodes) {
  // #104 is G90/G91, #101 the motion group, #107 the canned cycle (§2.2); a block reads them
  // before its own G codes act (§1.9), so each is read in the block after
  MacroRun r = runWl4("%P\nG91 G1 F100\n#30=#104 #31=#101\nG90 G0 #35=#104\n#32=#104 #33=#101\n"
                      "G83\n#34=#107\nG80\nX#30 Y#31 Z#32\nX#33 Y#34 Z#35\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 91,1,90", "R 0,83,91", "END"})); // #35: G91 still, at its block
}

TEST(Wl4SystemVariables_6_1, AWriteToASystemVariableIsAnError) {
  MacroRun r = runWl4("%P\nG0 X1\n#104=91\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"3:1 GCX065"})) << r.rendered;
}

TEST(Wl4SystemVariables_6_2, AVariableGcxDoesNotModelIsALocatedError) {
  // #150 is none of §6.2's variables
  MacroRun r = runWl4("%P\nG0 X1 #1=#150\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"2:10 GCX065"})) << r.rendered;
}

TEST(Wl4Calls_6_7, TheMainProgramAndFiveLevelsNest) {
  // %01 calls %02 ... %05: five levels run; %06 would be the sixth
  std::map<std::string, std::string> files{{"main.wl4", "%P\nL01\nM2\n%\n"}};
  for (int k = 1; k <= 5; ++k)
    files.emplace(fmt::format("0{}.wl4", k),
                  fmt::format("%0{}\nG0 X{}\nL0{}\nM99\n%\n", k, k, k + 1));
  files.emplace("06.wl4", "%06\nG0 X6\nM99\n%\n");
  MacroRun five = runWl4(files, "main.wl4");
  EXPECT_EQ(errorsAt(five), (V{"3:1 NCTX03"})) << five.rendered; // %05 calls the sixth level
  files["05.wl4"] = "%05\nG0 X5\nM99\n%\n";
  MacroRun ok = runWl4(files, "main.wl4");
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(ok.motion(), (V{"R 1,0,0", "R 2,0,0", "R 3,0,0", "R 4,0,0", "R 5,0,0", "END"}));
}

} // namespace
} // namespace gcx::test
