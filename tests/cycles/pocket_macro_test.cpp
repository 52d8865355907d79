// The NCT pocket-milling macro cycle G65 P9999 (cycles.md §5, §7, §8 TV-32 E9/E10, Q-19): the
// MACRO ERROR 1/2 argument checks (alarms 4001/4002, docs/pocket-macro.md), the missing-macro
// error, and the inlining of a supplied O9999 (a stand-in written for these tests).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/run_support.h"

namespace gcx::test {
namespace {

using testing::HasSubstr;
using V = std::vector<std::string>;

const fs::path& corpus() {
  static const fs::path dir = sourceDir() / "tests" / "corpus" / "nct" / "spec";
  return dir;
}

std::string file(const std::string& folder, const std::string& name) {
  return readFile(corpus() / folder / name);
}

machine::Setup toolD1(double radius) {
  machine::Setup s;
  s.tools[1].radius = radius;
  return s;
}

// the TV-32 preamble, one call block, M30; the call is line 2
MacroRun call(const std::string& block, double radius = 5, const std::string& before = "",
              std::map<std::string, std::string> more = {}) {
  more["O0001.nct"] = "G17 G90 G0 X0 Y0 Z20\n" + before + block + "\nM30\n";
  return runMacro(more, "O0001.nct", {}, toolD1(radius));
}

std::string firstError(const MacroRun& r) {
  return r.errors.empty() ? "none" : r.errors.front();
}

// ---------------------------------------------------------------- §8 TV-32

TEST(CyclesSpec_8, TV32_E9_NoDepthNoQ_MacroError1) {
  const MacroRun r =
      runMacro({{"O0001.nct", file("cycles-s8-tv32-e9", "O0001.nct")}}, "O0001.nct", {}, toolD1(5));
  EXPECT_EQ(firstError(r), "O0001.nct:2:1 4001") << r.rendered;
  EXPECT_THAT(r.rendered, HasSubstr("MACRO ERROR 1: the depth Z and the depth of cut Q not given"));
  EXPECT_EQ(r.motion(), V{"R 0,0,20"}); // stops at the call
}

TEST(CyclesSpec_8, TV32_E10_WidthBelowTwiceCornerRadius_MacroError2) {
  const MacroRun r = runMacro({{"O0001.nct", file("cycles-s8-tv32-e10", "O0001.nct")}}, "O0001.nct",
                              {}, toolD1(5));
  EXPECT_EQ(firstError(r), "O0001.nct:2:15 4002") << r.rendered; // at Y10
  EXPECT_THAT(r.rendered,
              HasSubstr("MACRO ERROR 2: pocket width Y10 is less than twice the corner radius R8"));
}

// The checks come before the call also when O9999 is supplied.
TEST(CyclesSpec_8, TV32_E9_E10_CheckedBeforeASuppliedMacro) {
  const std::string standIn = file("cycles-s5-pocket-standin", "O9999.nct");
  for (const char* folder : {"cycles-s8-tv32-e9", "cycles-s8-tv32-e10"}) {
    const MacroRun r = runMacro({{"O0001.nct", file(folder, "O0001.nct")}, {"O9999.nct", standIn}},
                                "O0001.nct", {}, toolD1(5));
    EXPECT_EQ(firstError(r),
              std::string(folder).ends_with("e9") ? "O0001.nct:2:1 4001" : "O0001.nct:2:15 4002")
        << r.rendered;
    EXPECT_EQ(r.motion(), V{"R 0,0,20"});
  }
}

// ---------------------------------------------------------------- §7 MACRO ERROR 1 and 2

struct ErrorCase {
  const char* name;
  const char* block; // line 2, or line 3 after `before`
  double radius;     // of tool register 1, mm
  const char* before;
  const char* expected; // first error "FILE:LINE:COL CODE"
  const char* message;  // part of its text
};

const ErrorCase errorCases[] = {
    // MACRO ERROR 1 (000:15782-15785), at the G65 word
    {"Error1_NoToolRadiusRegisterD", "G65 P9999 X40 Y30 Z5 K2 Q2", 5, "", "O0001.nct:2:1 4001",
     "MACRO ERROR 1: the tool radius register D not given"},
    {"Error1_NoDepthOfCutQ", "G65 P9999 X40 Y30 Z5 K2 D1", 5, "", "O0001.nct:2:1 4001",
     "MACRO ERROR 1: the depth of cut Q not given"},
    {"Error1_AllThreeInOneError", "G65 P9999 X40 Y30", 5, "", "O0001.nct:2:1 4001",
     "the depth Z, the tool radius register D and the depth of cut Q not given"},
    // a vacant bare reference leaves its argument vacant (nct-macro.md §2.5 rule 6)
    {"Error1_VacantVariableIsNotGiven", "G65 P9999 X40 Y30 Z#1 D1 Q2", 5, "", "O0001.nct:2:1 4001",
     "the depth Z not given"},
    // the depth follows the plane (000:15693-15702)
    {"Error1_G18DepthIsY", "G65 P9999 X40 Z30 D1 Q2", 5, "G18\n", "O0001.nct:3:1 4001",
     "the depth Y not given (G18"},
    {"Error1_G19DepthIsX", "G65 P9999 Y40 Z30 D1 Q2", 5, "G19\n", "O0001.nct:3:1 4001",
     "the depth X not given (G19"},
    // MACRO ERROR 2 (000:15787-15797), at the offending word
    {"Error2_LengthBelowTwiceCornerRadius", "G65 P9999 X10 Y8 Z5 R6 D1 Q2", 2, "",
     "O0001.nct:2:11 4002", "pocket length X10 is less than twice the corner radius R6"},
    {"Error2_WidthBelowToolDiameter", "G65 P9999 X40 Y8 Z5 R2 D1 Q2", 5, "", "O0001.nct:2:15 4002",
     "pocket width Y8 is less than the tool diameter 10 (D1)"},
    // no width: width = 2R (000:15765-15766), located at R
    {"Error2_WidthFromCornerRadius", "G65 P9999 X40 Z5 R3 D1 Q2", 5, "", "O0001.nct:2:18 4002",
     "pocket width 2R = 6 is less than the tool diameter 10"},
    // only R: a circular pocket of radius R (000:15774-15775)
    {"Error2_CircleBelowToolDiameter", "G65 P9999 Z5 R4 D1 Q2", 5, "", "O0001.nct:2:14 4002",
     "pocket circle diameter 2R = 8 is less than the tool"},
    {"Error2_StepoverZero", "G65 P9999 X40 Y30 Z5 D1 E0 Q2", 5, "", "O0001.nct:2:25 4002",
     "MACRO ERROR 2: the stepover E is 0"},
    {"Error2_ToolDiameterZero", "G65 P9999 X40 Y30 Z5 D1 Q2", 0, "", "O0001.nct:2:22 4002",
     "the tool diameter in register D1 is 0"},
    {"Error2_RegisterNotInTheTable", "G65 P9999 X40 Y30 Z5 D2 Q2", 5, "", "O0001.nct:2:22 4002",
     "the tool diameter in register D2 is 0"},
    {"Error2_DepthOfCutZero", "G65 P9999 X40 Y30 Z5 D1 Q0", 5, "", "O0001.nct:2:25 4002",
     "MACRO ERROR 2: the depth of cut Q is 0"},
    // G20: inch sizes against the tool radius of the table in mm (5 mm = 0.19685 in)
    {"Error2_InchSizes", "G65 P9999 X0.5 Y0.3 Z0.2 D1 Q0.1", 5, "G20\n", "O0001.nct:3:16 4002",
     "pocket width Y0.3 is less than twice the corner radius 0.1969 (the tool radius, no R)"},
    {"InchSizesThatFit", "G65 P9999 X0.5 Y0.4 Z0.2 D1 Q0.1", 5, "G20\n",
     "O0001.nct:3:5 CYC-POCKET-MACRO-MISSING", "O9999.nct was not found"},
};

class CyclesSpec_7_PocketErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(CyclesSpec_7_PocketErrors, StopsWithTheManualsMacroError) {
  const ErrorCase& c = GetParam();
  const MacroRun r = call(c.block, c.radius, c.before);
  EXPECT_EQ(firstError(r), c.expected) << r.rendered;
  EXPECT_THAT(r.rendered, HasSubstr(c.message));
  EXPECT_EQ(r.motion(), V{"R 0,0,20"}); // nothing runs after the call
}

std::string caseName(const testing::TestParamInfo<ErrorCase>& p) {
  return p.param.name;
}

INSTANTIATE_TEST_SUITE_P(Pocket, CyclesSpec_7_PocketErrors, testing::ValuesIn(errorCases),
                         caseName);

// ---------------------------------------------------------------- §5, Q-19: O9999 missing

TEST(CyclesSpec_5_Q19, MissingMacroAfterTheChecks) {
  const MacroRun r = call("G65 P9999 X40 Y30 Z5 K2 D1 Q2");
  EXPECT_EQ(r.errors, V{"O0001.nct:2:5 CYC-POCKET-MACRO-MISSING"}) << r.rendered;
  EXPECT_THAT(r.rendered, HasSubstr("G65 P9999 is the pocket-milling cycle; its macro program "
                                    "O9999.nct was not found in "));
  EXPECT_THAT(r.rendered, HasSubstr("SystemMacros/Channel1"));
  EXPECT_EQ(r.motion(), V{"R 0,0,20"});
}

// no length, width or R: the cycle drills (000:15777-15778), nothing to check but D, Q, depth
TEST(CyclesSpec_5_Q19, DrillingCaseIsNotAnError2) {
  const MacroRun r = call("G65 P9999 Z5 K2 D1 Q2");
  EXPECT_EQ(firstError(r), "O0001.nct:2:5 CYC-POCKET-MACRO-MISSING") << r.rendered;
}

TEST(CyclesSpec_5_Q19, MissingMacroNamesTheLibraryFolders) {
  const MacroRun r = runMacro({{"main/O0001.nct", "G65 P9999 X40 Y30 Z5 D1 Q2\nM30\n"}},
                              "main/O0001.nct", {}, toolD1(5), 100000, {"lib"});
  EXPECT_EQ(firstError(r), "O0001.nct:1:5 CYC-POCKET-MACRO-MISSING");
  EXPECT_THAT(r.rendered, HasSubstr("/lib, "));
  EXPECT_THAT(r.rendered, HasSubstr("with --lib"));
}

// only P9999 has the cycle's error: another missing program stays NCTX07
TEST(CyclesSpec_5_Q19, OtherProgramsKeepTheGenericError) {
  const MacroRun r = call("G65 P9998 X40 Y30 K2");
  EXPECT_EQ(r.errors, V{"O0001.nct:2:5 NCTX07"}) << r.rendered;
}

// ---------------------------------------------------------------- §5: O9999 supplied

const V standInMotion{"R 50,40,2",         "L 50,40,-2.5 F100", "L 30,25,-2.5 F200",
                      "L 70,25,-2.5 F200", "L 70,55,-2.5 F200", "L 30,55,-2.5 F200",
                      "L 30,25,-2.5 F200", "L 50,40,-2.5 F200", "L 50,40,-5 F100",
                      "L 30,25,-5 F200",   "L 70,25,-5 F200",   "L 70,55,-5 F200",
                      "L 30,55,-5 F200",   "L 30,25,-5 F200",   "L 50,40,-5 F200",
                      "R 50,40,2",         "R 50,40,20",        "END"};

TEST(CyclesSpec_5, StandInMacroIsInlinedWithItsArguments) {
  const std::string dir = "cycles-s5-pocket-standin";
  const MacroRun r = runMacro(
      {{"O0001.nct", file(dir, "O0001.nct")}, {"O9999.nct", file(dir, "O9999.nct")}}, "O0001.nct",
      {100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111}, toolD1(5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // X #24, Y #25, Z #26, R #18, D #7, E #8, Q #17, I #4, J #5, K #6, F #9, M #13
  const V expected{"40", "30", "5", "6", "1", "60", "2.5", "0.5", "0.25", "2", "200", "8"};
  for (int n = 100; n <= 111; ++n) {
    ASSERT_TRUE(r.vars.count(n) && !r.vars.at(n).vacant) << n;
    EXPECT_EQ(n4(r.vars.at(n).number), expected[n - 100]) << "#" << n;
  }
  EXPECT_EQ(r.motion(), standInMotion);
}

TEST(CyclesSpec_5, StandInMacroFoundInALibraryFolder) {
  const std::string dir = "cycles-s5-pocket-standin";
  const MacroRun r = runMacro(
      {{"main/O0001.nct", file(dir, "O0001.nct")}, {"lib/O9999.nct", file(dir, "O9999.nct")}},
      "main/O0001.nct", {}, toolD1(5), 100000, {"lib"});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), standInMotion);
}

} // namespace
} // namespace gcx::test
