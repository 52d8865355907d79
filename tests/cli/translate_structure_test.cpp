// gcx translate between dialects keeps a program's structure (docs/translation.md, "Structure
// across dialects"): subprograms as the target's calls and files, loops as its loops (or its
// repeats when the count is known), variables as its variables, each written by meaning and the
// whole proven by the equivalence engine; what the target cannot keep leaves the flat motion,
// with the reason in the note. One test per pair of dialects and structure kind, each asserting
// the exact text written.
#include <gtest/gtest.h>

#include <cstdlib>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

class TranslateStructure : public testing::Test {
protected:
  void write(const std::string& name, const std::string& bytes) { folder_.write(name, bytes); }
  CliResult gcx(const std::string& args) { return folder_.gcx(args); }
  std::string read(const std::string& name) { return readFile(folder_.path() / name); }
  bool exists(const std::string& name) { return fs::exists(folder_.path() / name); }

  CliFolder folder_{"translate-structure"};
};

// --- NCT as the source -------------------------------------------------------------------------

constexpr const char* kNctCall = "G90 G0 X0 Y0 Z5\n"
                                 "M98 P20 L2\n"
                                 "G0 Z50\n"
                                 "M30\n";
constexpr const char* kNctSub = "O0020\n"
                                "G91 G1 Y5 F100\n"
                                "G90\n"
                                "M99\n";
// a counter that only counts: three passes
constexpr const char* kNctLoop = "G90 G0 X0 Y0 Z5\n"
                                 "#1=0\n"
                                 "WHILE [#1 LT 3] DO1\n"
                                 "G91 G1 X10 F100\n"
                                 "G90\n"
                                 "#1=#1+1\n"
                                 "END1\n"
                                 "M30\n";
constexpr const char* kNctVariables = "G90 G0 X0 Y0 Z5\n"
                                      "#1=2.5\n"
                                      "#101=[#1*2]\n"
                                      "G1 X#101 Y[#1+1] F100\n"
                                      "M30\n";

// M98 P20 L2 is WL4's L nnpp: program 20, twice; the subprogram joins the file as %20 (wl4.md
// §1.2, §6.7).
TEST_F(TranslateStructure, Wl4Spec_6_7_NctM98RepeatsBecomeOneLCall) {
  write("S.nct", kNctCall);
  write("O0020.nct", kNctSub);
  const CliResult r = gcx("translate S.nct --to wl4 -o S.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.wl4"), "%S\n"
                           "$translated from S.nct (nct) by gcx\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "L2002\n"
                           "G0 Z50\n"
                           "M30\n"
                           "%\n"
                           "%20\n"
                           "G91 G1 Y5 F100\n"
                           "G90\n"
                           "M99\n"
                           "%\n");
  EXPECT_EQ(r.err, "gcx: note: S.nct: kept as wl4 structure: subprogram calls (S.nct:2); program "
                   "frame: runs on the same setup as its source\n"
                   "gcx: S.nct -> S.wl4: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// NCT's WHILE tests first: WL4 jumps past the loop when the condition fails, and back to the top
// while it holds; NCT's locals, shared with its M98 subprograms, become WL4's globals #30-#99
// (wl4.md §6.1, §6.6).
TEST_F(TranslateStructure, Wl4Spec_6_6_NctWhileBecomesLabelsAndIfJumps) {
  write("L.nct", kNctLoop);
  const CliResult r = gcx("translate L.nct --to wl4 -o L.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("L.wl4"), "%L\n"
                           "$translated from L.nct (nct) by gcx\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#30=0\n"
                           "IF(#30>=3) N9001\n"
                           "N09000\n"
                           "G91 G1 X10 F100\n"
                           "G90\n"
                           "#30=#30+1\n"
                           "IF(#30<3) N9000\n"
                           "N09001\n"
                           "M30\n"
                           "%\n");
}

// #1 (local) and #101 (common) both become WL4 globals; the expressions keep their operators.
TEST_F(TranslateStructure, Wl4Spec_6_1_NctVariablesBecomeWl4Globals) {
  write("V.nct", kNctVariables);
  const CliResult r = gcx("translate V.nct --to wl4 -o V.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("V.wl4"), "%V\n"
                           "$translated from V.nct (nct) by gcx\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#30=2.5\n"
                           "#31=(#30*2)\n"
                           "G1 X#31 Y(#30+1) F100\n"
                           "M30\n"
                           "%\n");
}

// NCT's FIX truncates toward zero, WL4's rounds down: WL4 chooses FIX or FUP by the sign. WL4
// evaluates + and >= on one level left to right, so #2+1 on the right of a comparison keeps its
// parentheses (wl4.md §6.3).
TEST_F(TranslateStructure, Wl4Spec_6_3_NctFixAndComparisonsKeepTheirMeaning) {
  write("E.nct", "G90 G0 X0 Y0 Z5\n"
                 "#1=0\n"
                 "#2=2\n"
                 "WHILE [#1 LT #2+1] DO1\n"
                 "G1 X[FIX[#1*1.5]] F100\n"
                 "#1=#1+1\n"
                 "END1\n"
                 "M30\n");
  const CliResult r = gcx("translate E.nct --to wl4 -o E.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("E.wl4"),
            "%E\n"
            "$translated from E.nct (nct) by gcx\n"
            "G90 G0 X0 Y0 Z5\n"
            "#30=0\n"
            "#31=2\n"
            "IF(#30>=(#31+1)) N9001\n"
            "N09000\n"
            "G1 X((FIX((#30*1.5))*((#30*1.5)>=0)+FUP((#30*1.5))*((#30*1.5)<0))) F100\n"
            "#30=#30+1\n"
            "IF(#30<(#31+1)) N9000\n"
            "N09001\n"
            "M30\n"
            "%\n");
}

// FMS-3000's P has no repeat count: two runs are a G25 L2 ... M25 repeat of the call; the
// subprogram is the file 20.fms beside the result (fms3000.md §1.3, §6.2).
TEST_F(TranslateStructure, Fms3000Spec_6_2_NctM98RepeatsBecomeAG25RepeatOfAPCall) {
  write("S.nct", kNctCall);
  write("O0020.nct", kNctSub);
  const CliResult r = gcx("translate S.nct --to fms3000 -o S.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.fms"), "rem translated from S.nct (nct) by gcx\r\n"
                           "G90 G00 X0 Y0 Z5\r\n"
                           "G25 L2\r\n"
                           "P20\r\n"
                           "M25\r\n"
                           "G00 Z50\r\n"
                           "M30\r\n");
  EXPECT_EQ(read("20.fms"), "G91 G01 Y5 F100\r\n"
                            "G90\r\n"
                            "M99\r\n");
  EXPECT_EQ(r.err, "gcx: note: S.nct: kept as fms3000 structure: subprogram calls (S.nct:2); "
                   "program frame: runs on the same setup as its source; subprograms written as "
                   "20.fms\n"
                   "gcx: S.nct -> S.fms: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// A WHILE whose counter only counts (0, 1, 2: three passes) is FMS-3000's G25 L3 ... M25; the
// counter goes, FMS-3000 has no variables.
TEST_F(TranslateStructure, Fms3000Spec_6_2_NctCountedWhileBecomesG25Repeat) {
  write("L.nct", kNctLoop);
  const CliResult r = gcx("translate L.nct --to fms3000 -o L.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("L.fms"), "rem translated from L.nct (nct) by gcx\r\n"
                           "G90 G00 X0 Y0 Z5\r\n"
                           "G25 L3\r\n"
                           "G91 G01 X10 F100\r\n"
                           "G90\r\n"
                           "M25\r\n"
                           "M30\r\n");
}

// FMS-3000 has no variables: the program is written as the motion it makes, and the note says so.
TEST_F(TranslateStructure, Fms3000Spec_1_2_NctVariablesAreRunOutWithTheReason) {
  write("V.nct", kNctVariables);
  const CliResult r = gcx("translate V.nct --to fms3000 -o V.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("V.fms"), "rem translated from V.nct (nct) by gcx\r\n"
                           "rem structure not kept: V.nct:2: #1: the target has no\r\n"
                           "rem variables; run out into motion: variables (V.nct:2, 3, 4);\r\n"
                           "rem machine frame, offsets and tool lengths in the coordinates,\r\n"
                           "rem run without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z5\r\n"
                           "G01 X5 Y3.5 Z5 F100\r\n"
                           "M30\r\n");
}

// --- WL4 as the source -------------------------------------------------------------------------

constexpr const char* kWl4Call = "%S\n"
                                 "G90 G0 X0 Y0 Z5\n"
                                 "L0702\n"
                                 "G0 Z50\n"
                                 "M30\n"
                                 "%\n"
                                 "%07\n"
                                 "G91 G1 Y5 F100\n"
                                 "G90\n"
                                 "M99\n"
                                 "%\n";
// a label, the counter stepped down after the NC part, a jump back while it holds
constexpr const char* kWl4Loop = "%L\n"
                                 "G90 G0 X0 Y0 Z5\n"
                                 "#1=3\n"
                                 "N010 G91 G1 X10 F100\n"
                                 "G90 #1=(#1-1)\n"
                                 "IF (#1>0) N10\n"
                                 "M30\n"
                                 "%\n";
// #2 is never written: 0 in WL4, so NCT sets it first
constexpr const char* kWl4Variables = "%V\n"
                                      "G90 G0 X0 Y0 Z5\n"
                                      "#1=2.5 #30=(#1*2)\n"
                                      "G1 X#30 Y(#1+#2) F100\n"
                                      "IF (#30>4) N20\n"
                                      "G1 X0\n"
                                      "N020 M30\n"
                                      "%\n";

// L0702 is M98 P7 L2; %07 becomes O0007.nct beside the result (nct.md §5.1).
TEST_F(TranslateStructure, NctSpec_5_1_Wl4LCallBecomesM98WithItsRepeats) {
  write("S.wl4", kWl4Call);
  const CliResult r = gcx("translate S.wl4 --to nct -o S.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.nct"), "O1\n"
                           "(translated from S.wl4 [wl4] by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "M98 P7 L2\n"
                           "G0 Z50\n"
                           "M30\n");
  EXPECT_EQ(read("O0007.nct"), "O7\n"
                               "G91 G1 Y5 F100\n"
                               "G90\n"
                               "M99\n");
  EXPECT_EQ(r.err, "gcx: note: S.wl4: kept as nct structure: subprogram calls (S.wl4:3); program "
                   "frame: runs on the same setup as its source; subprograms written as "
                   "O0007.nct\n"
                   "gcx: S.wl4 -> S.nct: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// A WL4 label is an NCT block number, the IF jump an IF [..] GOTO; WL4's variables start at 0,
// NCT's vacant, so #1 is set to 0 first (nct-macro.md §4.1, wl4.md §6.1).
TEST_F(TranslateStructure, NctMacroSpec_4_1_Wl4LabelsAndIfJumpsBecomeGoto) {
  write("L.wl4", kWl4Loop);
  const CliResult r = gcx("translate L.wl4 --to nct -o L.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("L.nct"), "O1\n"
                           "(translated from L.wl4 [wl4] by gcx)\n"
                           "#1=0\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#1=3\n"
                           "N10 G91 G1 X10 F100\n"
                           "G90\n"
                           "#1=[#1-1]\n"
                           "IF[#1 GT 0] GOTO 10\n"
                           "M30\n");
}

// Locals stay locals, WL4's globals #30-#99 are NCT's commons from #100; a variable the program
// reads before writing (#2) is set to 0 first, as WL4 starts it.
TEST_F(TranslateStructure, NctMacroSpec_2_1_Wl4VariablesKeepTheirValuesInNct) {
  write("V.wl4", kWl4Variables);
  const CliResult r = gcx("translate V.wl4 --to nct -o V.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("V.nct"), "O1\n"
                           "(translated from V.wl4 [wl4] by gcx)\n"
                           "#1=0\n"
                           "#2=0\n"
                           "#100=0\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#1=2.5\n"
                           "#100=[#1*2]\n"
                           "G1 X#100 Y[#1+#2] F100\n"
                           "IF[#100 GT 4] GOTO 20\n"
                           "G1 X0\n"
                           "N20 M30\n");
}

// wl4.md §6.5: a false IF drops the rest of its block, a true one runs it after the words
// before it (the later Z wins), so NCT jumps around the two forms of the block; X**2 with a
// literal exponent is a product and 7 MOD 3 a constant, which NCT writes as such.
TEST_F(TranslateStructure, Wl4Spec_6_5_AnIfInsideABlockBecomesTwoBranchesInNct) {
  write("I.wl4", "%I\nG90 G0 X0 Y0 Z0\n#1=0\nN010 #1=(#1+1) G1 X(#1*10) Y(#1**2) F100\n"
                 "IF (#1<4) N10\n#2=(7 MOD 3)\nG1 Z(-#2) IF (#2==1) Z-2\nM2\n%\n");
  const CliResult r = gcx("translate I.wl4 --to nct -o I.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("I.nct"), "O1\n(translated from I.wl4 [wl4] by gcx)\n#1=0\n#2=0\n"
                           "G90 G0 X0 Y0 Z0\n#1=0\nN10 #1=[#1+1]\nG1 X[#1*10] Y[[#1*#1]] F100\n"
                           "IF[#1 LT 4] GOTO 10\n#2=[1]\nIF[#2 NE 1] GOTO 9000\nG1 Z-2\n"
                           "GOTO 9001\nN9000 G1 Z[-#2]\nN9001\nM2\n");
}

// L0702 to FMS-3000: program 07 (its leading zero kept, P07 is not P7), twice by G25.
TEST_F(TranslateStructure, Fms3000Spec_1_3_Wl4LCallBecomesPCallOfItsDigits) {
  write("S.wl4", kWl4Call);
  const CliResult r = gcx("translate S.wl4 --to fms3000 -o S.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.fms"), "rem translated from S.wl4 (wl4) by gcx\r\n"
                           "G90 G00 X0 Y0 Z5\r\n"
                           "G25 L2\r\n"
                           "P07\r\n"
                           "M25\r\n"
                           "G00 Z50\r\n"
                           "M30\r\n");
  EXPECT_EQ(read("07.fms"), "G91 G01 Y5 F100\r\n"
                            "G90\r\n"
                            "M99\r\n");
}

// The counter set to 3, stepped down by 1 after each pass and tested after it: three passes, a
// G25 L3 repeat; the G90 of the step's block stays in the body.
TEST_F(TranslateStructure, Fms3000Spec_6_2_Wl4CountedJumpLoopBecomesG25Repeat) {
  write("L.wl4", kWl4Loop);
  const CliResult r = gcx("translate L.wl4 --to fms3000 -o L.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("L.fms"), "rem translated from L.wl4 (wl4) by gcx\r\n"
                           "G90 G00 X0 Y0 Z5\r\n"
                           "G25 L3\r\n"
                           "G91 G01 X10 F100\r\n"
                           "G90\r\n"
                           "M25\r\n"
                           "M30\r\n");
}

TEST_F(TranslateStructure, Fms3000Spec_1_2_Wl4VariablesAreRunOutWithTheReason) {
  write("V.wl4", kWl4Variables);
  const CliResult r = gcx("translate V.wl4 --to fms3000 -o V.fms");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("V.fms"), "rem translated from V.wl4 (wl4) by gcx\r\n"
                           "rem structure not kept: V.wl4:3: #1: the target has no\r\n"
                           "rem variables; run out into motion: loops and jumps (V.wl4:5),\r\n"
                           "rem variables (V.wl4:3, 4, 5); machine frame, offsets and tool\r\n"
                           "rem lengths in the coordinates, run without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z5\r\n"
                           "G01 X5 Y2.5 Z5 F100\r\n"
                           "M30\r\n");
}

// --- FMS-3000 as the source (it has no variables) -----------------------------------------------

constexpr const char* kFmsCall = "G90 G00 X0 Y0 Z5\r\n"
                                 "P019\r\n"
                                 "G91 G00 Y10 P019\r\n"
                                 "G90 G00 Z50\r\n"
                                 "M30\r\n";
constexpr const char* kFmsSub = "G91 G01 Z-7 F100\r\n"
                                "G00 Z7\r\n"
                                "G90 M99\r\n";
constexpr const char* kFmsRepeat = "G90 G00 X0 Y0 Z5\r\n"
                                   "G25 L3\r\n"
                                   "G91 G01 X10 F100\r\n"
                                   "G90 M25\r\n"
                                   "M30\r\n";

// P019 after the block's motion is M98 P19 in the same block (NCT runs the block's words first,
// nct.md §1.4); 019.fms becomes O0019.nct.
TEST_F(TranslateStructure, NctSpec_1_4_FmsPCallBecomesM98AfterTheBlocksMotion) {
  write("S.fms", kFmsCall);
  write("019.fms", kFmsSub);
  const CliResult r = gcx("translate S.fms --to nct -o S.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.nct"), "O1\n"
                           "(translated from S.fms [fms3000] by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "M98 P19\n"
                           "G91 G0 Y10 M98 P19\n"
                           "G90 G0 Z50\n"
                           "M30\n");
  EXPECT_EQ(read("O0019.nct"), "O19\n"
                               "G91 G1 Z-7 F100\n"
                               "G0 Z7\n"
                               "G90 M99\n");
}

// G25 L3 ... M25: a counter in NCT's highest free local, counted down by a WHILE.
TEST_F(TranslateStructure, NctMacroSpec_4_5_FmsRepeatBecomesCountedWhile) {
  write("R.fms", kFmsRepeat);
  const CliResult r = gcx("translate R.fms --to nct -o R.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("R.nct"), "O1\n"
                           "(translated from R.fms [fms3000] by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#33=3\n"
                           "WHILE[#33 GT 0] DO1\n"
                           "G91 G1 X10 F100\n"
                           "G90\n"
                           "#33=#33-1\n"
                           "END1\n"
                           "M30\n");
  EXPECT_EQ(r.err, "gcx: note: R.fms: kept as nct structure: loops (R.fms:2); program frame: "
                   "runs on the same setup as its source\n"
                   "gcx: R.fms -> R.nct: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// P019 to WL4: program 19 (below 100, its value), called after the block's motion as L19 is.
TEST_F(TranslateStructure, Wl4Spec_6_7_FmsPCallBecomesLCall) {
  write("S.fms", kFmsCall);
  write("019.fms", kFmsSub);
  const CliResult r = gcx("translate S.fms --to wl4 -o S.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.wl4"), "%S\n"
                           "$translated from S.fms (fms3000) by gcx\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "L19\n"
                           "G91 G0 Y10 L19\n"
                           "G90 G0 Z50\n"
                           "M30\n"
                           "%\n"
                           "%19\n"
                           "G91 G1 Z-7 F100\n"
                           "G0 Z7\n"
                           "G90 M99\n"
                           "%\n");
}

// G25 L3 ... M25 in WL4: a counter set to 3, a label, the counter stepped down, a jump back
// while it is above 0.
TEST_F(TranslateStructure, Wl4Spec_6_6_FmsRepeatBecomesCounterAndJump) {
  write("R.fms", kFmsRepeat);
  const CliResult r = gcx("translate R.fms --to wl4 -o R.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("R.wl4"), "%R\n"
                           "$translated from R.fms (fms3000) by gcx\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#29=3\n"
                           "N09000\n"
                           "G91 G1 X10 F100\n"
                           "G90\n"
                           "#29=(#29-1)\n"
                           "IF(#29>0) N9000\n"
                           "M30\n"
                           "%\n");
}

// --- what is not kept --------------------------------------------------------------------------

// --expand subprograms runs the calls out, as before.
TEST_F(TranslateStructure, ExpandSubprogramsWritesTheFlatMotion) {
  write("S.nct", kNctCall);
  write("O0020.nct", kNctSub);
  const CliResult r = gcx("translate S.nct --to wl4 --expand subprograms -o S.wl4");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.wl4"), "%S\n"
                           "$translated from S.nct (nct) by gcx\n"
                           "$run out into motion: subprogram calls (S.nct:2); machine\n"
                           "$frame, offsets and tool lengths in the coordinates, run\n"
                           "$without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z5\n"
                           "G1 X0 Y5 Z5 F100\n"
                           "G1 X0 Y10 Z5 F100\n"
                           "G0 X0 Y10 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_FALSE(exists("O0020.wl4"));
}

// A WL4 callee writes its own copy of the caller's locals, an NCT M98 subprogram the caller's:
// the structure is not kept, and the note says where and why.
TEST_F(TranslateStructure, Wl4CalleeWritingItsLocalsIsRunOutForNct) {
  write("C.wl4", "%C\n"
                 "G90 G0 X0 Y0 Z0\n"
                 "#1=5\n"
                 "L07\n"
                 "G1 X#1 F100\n"
                 "M2\n"
                 "%\n"
                 "%07\n"
                 "#1=(#1*2)\n"
                 "G1 Y#1 F100\n"
                 "M99\n"
                 "%\n");
  const CliResult r = gcx("translate C.wl4 --to nct -o C.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("C.nct"), "O1\n"
                           "(translated from C.wl4 [wl4] by gcx)\n"
                           "(structure not kept: C.wl4:9: a local variable written in a)\n"
                           "(called program: the source's callee writes its own copy of)\n"
                           "(the caller's locals, the target's the caller's own; run out)\n"
                           "(into motion: subprogram calls [C.wl4:4], variables [C.wl4:3,)\n"
                           "(5, 9, 10]; machine frame, offsets and tool lengths in the)\n"
                           "(coordinates, run without a setup)\n"
                           "G90 G94 G17 G21\n"
                           "G1 X0 Y10 Z0 F100\n"
                           "G1 X5 Y10 Z0 F100\n"
                           "M2\n");
}

// An M99 ends an FMS-3000 unit run on its own (fms3000.md §2.2); in NCT it would restart the
// program, so the main program gets NCT's end instead.
TEST_F(TranslateStructure, Fms3000Spec_2_2_AReturnInTheMainProgramIsAnEndInNct) {
  write("9.fms", "G90 G00 X0 Y0 Z5\r\nP019\r\nM99\r\n");
  write("019.fms", kFmsSub);
  const CliResult r = gcx("translate 9.fms --to nct -o 9.nct");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("9.nct"), "O9\n"
                           "(translated from 9.fms [fms3000] by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "M98 P19\n"
                           "M2\n");
}

// --- LinuxCNC as the target of FMS-3000 and WL4 ----------------------------------------------

// LinuxCNC's reader (rs274) proves these: without it the structured file is not written.
class TranslateStructureNgc : public TranslateStructure {
protected:
  void SetUp() override {
    if (std::system("command -v rs274 >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs rs274";
  }
};

// P019 is an o-word subroutine defined before the main program (LinuxCNC finds a numbered one
// only in the calling file, defined before the call runs), called after its block's motion.
TEST_F(TranslateStructureNgc, FmsPCallsBecomeOWordSubroutines) {
  write("S.fms", kFmsCall);
  write("019.fms", kFmsSub);
  const CliResult r = gcx("translate S.fms --to ngc -o S.ngc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S.ngc"), "o<19> sub\n"
                           "G91 G1 Z-7 F100\n"
                           "G0 Z7\n"
                           "G90\n"
                           "o<19> endsub\n"
                           "(translated from S.fms fms3000 by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "o<19> call\n"
                           "G91 G0 Y10\n"
                           "o<19> call\n"
                           "G90 G0 Z50\n"
                           "M30\n");
  EXPECT_EQ(r.err, "gcx: note: S.fms: kept as LinuxCNC's own: subprogram calls (S.fms:2, 3)\n"
                   "gcx: S.fms -> S.ngc: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// G25 L3 ... M25: a counter in a parameter of the main program, counted down by o-word while.
TEST_F(TranslateStructureNgc, FmsRepeatBecomesOWordWhile) {
  write("R.fms", kFmsRepeat);
  const CliResult r = gcx("translate R.fms --to ngc -o R.ngc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("R.ngc"), "(translated from R.fms fms3000 by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#30 = 3\n"
                           "o<l1> while [#30 GT 0]\n"
                           "G91 G1 X10 F100\n"
                           "G90\n"
                           "#30 = [#30-1]\n"
                           "o<l1> endwhile\n"
                           "M30\n");
}

// A WL4 label with a jump back to it while a condition holds is LinuxCNC's do ... while; the
// variables stay parameters, the expressions in LinuxCNC's brackets.
TEST_F(TranslateStructureNgc, Wl4JumpBackToALabelBecomesDoWhile) {
  write("L.wl4", "%L\n"
                 "G90 G0 X0 Y0 Z5\n"
                 "#1=0\n"
                 "N010 G1 X(#1*10) F100\n"
                 "#1=(#1+1)\n"
                 "IF (#1<3) N10\n"
                 "M30\n"
                 "%\n");
  const CliResult r = gcx("translate L.wl4 --to ngc -o L.ngc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("L.ngc"), "(translated from L.wl4 wl4 by gcx)\n"
                           "G90 G0 X0 Y0 Z5\n"
                           "#1 = 0\n"
                           "o<l1> do\n"
                           "G1 X[#1*10] F100\n"
                           "#1 = [#1+1]\n"
                           "o<l1> while [#1 LT 3]\n"
                           "M30\n");
}

// WL4 G81 calling %81 with #2 #3: LinuxCNC's G99 G81, each hole written whole (LinuxCNC asks R
// again when the cycle code changes).
TEST_F(TranslateStructureNgc, Wl4CycleProgramsBecomeLinuxCncCycles) {
  write("C.wl4", "%C\n"
                 "G90 G0 X0 Y0 Z50\n"
                 "#2=2 #3=-10\n"
                 "G81 G0 X10 Y10 F100\n"
                 "X20\n"
                 "G80\n"
                 "G0 Z50\n"
                 "M30\n"
                 "%\n");
  const CliResult r = gcx("translate C.wl4 --to ngc -o C.ngc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("C.ngc"), "(translated from C.wl4 wl4 by gcx)\n"
                           "G90 G0 X0 Y0 Z50\n"
                           "#2 = 2\n"
                           "#3 = -10\n"
                           "G99 G81 X10 Y10 R2 Z-10 F100\n"
                           "G99 G81 X20 Y10 R2 Z-10 F100\n"
                           "G80\n"
                           "G0 Z50\n"
                           "M30\n");
}

// A WL4 callee starts with a copy of its caller's locals; a LinuxCNC subroutine with its own:
// the program is written flat, and the note says where and why.
TEST_F(TranslateStructureNgc, Wl4CalleeReadingItsCallersLocalsIsWrittenFlat) {
  write("K.wl4", "%K\n"
                 "G90 G0 X0 Y0 Z0\n"
                 "#1=5\n"
                 "L07\n"
                 "M2\n"
                 "%\n"
                 "%07\n"
                 "G1 X#1 F100\n"
                 "M99\n"
                 "%\n");
  const CliResult r = gcx("translate K.wl4 --to ngc -o K.ngc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("K.ngc"),
            "(written as plain G0-G3 motion: K.wl4:8: a caller's local variable read in a called "
            "program: the source's callee reads a copy of its caller's locals, the target's its "
            "own)\n"
            "(gcx canonical motion: machine frame, mm, absolute; offsets and tool lengths are in "
            "the coordinates)\n"
            "G21 G90 G94 G17 G40 G49 G80 G54\n"
            "G1 X5 Y0 Z0 F100\n"
            "M2\n");
}

} // namespace
} // namespace gcx::test
