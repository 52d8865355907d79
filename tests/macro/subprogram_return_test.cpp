// M99 P and M99 L (nct-macro.md §5.2 R4, R5 and the search order G5): where a subprogram
// returns to and how often it runs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "passes/macro/expander.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// a returning subprogram that went to the wrong block would call itself again forever
macro::Limits bounded() {
  macro::Limits l;
  l.maxBlocks = 1000;
  return l;
}

std::string value(const MacroRun& r, int n) {
  auto it = r.vars.find(n);
  if (it == r.vars.end() || it->second.vacant) return "vac";
  return fmt::format("{}", it->second.number);
}

TEST(MacroSpec_5_2, M99PSearchesFromTheBlockAfterTheCall) {
  // R4 with G5: N10 stands both before and after the calling block; the one after wins
  MacroRun r =
      runMacroLimited({{"O0001.nct", "N10 G0 X1\nN20 M98 P11\nN30 G0 X2\nN10 G0 X3\nM30\n"},
                       {"O0011.nct", "G0 Y5\nM99 P10\n"}},
                      "O0001.nct", bounded());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 1,5,0", "R 3,5,0", "END"}));
}

TEST(MacroSpec_5_2, M99PWrapsToTheStartWhenTheNumberIsOnlyBeforeTheCall) {
  // G5: after the calling block to the end, then from the first block: back to N10
  MacroRun r = runMacro({{"O0001.nct", "N10 #100=#100+1\nIF[#100GE3]GOTO40\nN20 M98 P11\n"
                                       "N30 #101=1\nN40 M30\n"},
                         {"O0011.nct", "M99 P10\n"}},
                        "O0001.nct", {100, 101});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 100), "3");
  EXPECT_EQ(value(r, 101), "vac");
}

TEST(MacroSpec_2_5, GotoSearchesFromTheNextBlockFirst) {
  // G5: GOTO10 finds the N10 after it, not the one before; the first N10 runs only once
  MacroRun r = runMacroLimited({{"O0001.nct", "N10 G91 G0 X1\nGOTO10\nG0 Y1\nN10 G0 Z1\nM30\n"}},
                               "O0001.nct", bounded());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 1,0,1", "END"}));
}

TEST(MacroSpec_5_2, M99PToAMissingNumberIsAlarm2125) {
  MacroRun r = runMacro({{"O0001.nct", "M98 P11\nM30\n"}, {"O0011.nct", "M99 P77\n"}}, "O0001.nct");
  EXPECT_EQ(r.errors, V{"O0011.nct:1:5 2125"});
}

TEST(MacroSpec_5_2, M99LAddsRunsToASingleCall) {
  // R5: M98 without L runs once; `M99 L2` in that run adds two more
  MacroRun r =
      runMacro({{"O0001.nct", "M98 P11\n#101=#100\nM30\n"},
                {"O0011.nct", "#100=#100+1\nG91 G0 X1\nIF[#100NE1]GOTO9\nM99 L2\nN9 M99\n"}},
               "O0001.nct", {100, 101});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 101), "3");
  EXPECT_EQ(r.program.x(), 3);
}

TEST(MacroSpec_5_2, M99L0EndsTheRepetitions) {
  // R5: `M98 P11 L5` with `M99 L0` in the second run: no further run, 2 in all
  MacroRun r = runMacro({{"O0001.nct", "M98 P11 L5\n#101=#100\nM30\n"},
                         {"O0011.nct", "#100=#100+1\nIF[#100NE2]GOTO9\nM99 L0\nN9 M99\n"}},
                        "O0001.nct", {100, 101});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 101), "2");
}

TEST(MacroSpec_5_2, M99PLTakesTheTargetFromTheLastRun) {
  // R5: the first run's `M99 P30 L1` only sets the count; the last run's `M99 P40` returns
  MacroRun r = runMacro({{"O0001.nct", "N10 M98 P11\nN20 #101=1\nN30 #102=1\nN40 #103=1\nM30\n"},
                         {"O0011.nct", "#100=#100+1\nIF[#100NE1]GOTO9\nM99 P30 L1\nN9 M99 P40\n"}},
                        "O0001.nct", {100, 101, 102, 103});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 100), "2");
  EXPECT_EQ(value(r, 101), "vac");
  EXPECT_EQ(value(r, 102), "vac");
  EXPECT_EQ(value(r, 103), "1");
}

TEST(MacroSpec_5_2, M98LRunsTheSubprogramLTimes) { // R1
  MacroRun r = runMacro({{"O0001.nct", "M98 P11 L4\nM30\n"}, {"O0011.nct", "G91 G0 X1\nM99\n"}},
                        "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 2,0,0", "R 3,0,0", "R 4,0,0", "END"}));
}

} // namespace
} // namespace gcx::test
