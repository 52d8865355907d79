// gcx translate --to ngc (docs/translation.md, "ngc: what is kept"): NCT cycles, subprograms,
// loops and variables kept as LinuxCNC's where they mean the same there, each result proven by
// rs274 reading the structured file; what cannot be kept is written as flat motion with a note
// in the file and on stderr saying what and why.
#include <gtest/gtest.h>

#include <cstdlib>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

using Result = CliResult;

std::string firstLine(const std::string& text) {
  return text.substr(0, text.find('\n') + 1);
}

constexpr const char* kHeader =
    "(written by gcx translate --to ngc: the structure LinuxCNC gives the same meaning is kept)\n";
constexpr const char* kFlat = "(gcx canonical motion: machine frame, mm, absolute; offsets and "
                              "tool lengths are in the coordinates)\n";

class TranslateNgc : public testing::Test {
protected:
  void SetUp() override {
    // the structured file is proven by LinuxCNC's reader only
    if (std::system("command -v rs274 >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs rs274";
  }
  fs::path write(const std::string& name, const std::string& bytes) {
    return folder_.write(name, bytes);
  }
  Result gcx(const std::string& args) { return folder_.gcx(args); }
  // translates NAME.nct to NAME.ngc; the output file's text
  std::string translate(const std::string& name, Result& r, const std::string& extra = "") {
    r = gcx("translate " + name + ".nct --to ngc -o " + name + ".ngc" + extra);
    return fs::exists(dir_ / (name + ".ngc")) ? readFile(dir_ / (name + ".ngc")) : "";
  }
  // translates NAME.nct, which must come out as flat motion; the note on its first line
  std::string flatNote(const std::string& name) {
    Result r;
    const std::string text = translate(name, r);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(text.find(kFlat), std::string::npos) << text;
    return firstLine(text);
  }
  std::string verifiedLine(const std::string& name) {
    return "gcx: " + name + ".nct -> " + name +
           ".ngc: verified, moves the tool like the source within 0.001 mm\n";
  }

  CliFolder folder_{"translate-ngc"};
  const fs::path& dir_ = folder_.path();
};

// WHILE DO1 ... END1, #-variables with expressions, and a G81 kept as G81 with R repeated.
TEST_F(TranslateNgc, WhileLoopVariablesAndDrillingCycleAreKept) {
  write("LOOP.nct", "(BOLT CIRCLE)\n"
                    "G90 G17 G21 G94 G54\n"
                    "S2000 M3\n"
                    "G0 X0 Y0 Z50\n"
                    "#1=4\n"
                    "#5=0\n"
                    "WHILE[#5LT#1]DO1\n"
                    "#6=45+#5*360/#1\n"
                    "G99 G81 X[40*COS[#6]] Y[40*SIN[#6]] Z-15 R3 F220\n"
                    "#5=#5+1\n"
                    "END1\n"
                    "G80\n"
                    "G0 Z50 M5\n"
                    "M30\n");
  Result r;
  EXPECT_EQ(translate("LOOP", r), std::string(kHeader) +
                                      "(BOLT CIRCLE)\n"
                                      "G90 G17 G21 G94 G54\n"
                                      "S2000 M3\n"
                                      "G0 X0 Y0 Z50\n"
                                      "#1 = 4\n"
                                      "#5 = 0\n"
                                      "o<w1> while [#5 LT #1]\n"
                                      "#6 = [45+[[#5*360]/#1]]\n"
                                      "G99 G81 X[40*COS[#6]] Y[40*SIN[#6]] F220 R3 Z-15\n"
                                      "#5 = [#5+1]\n"
                                      "o<w1> endwhile\n"
                                      "G80 G98\n" // NCT's G80 brings G98 back, LinuxCNC's not
                                      "G0 Z50\n"
                                      "M5\n" // after the motion, as NCT
                                      "M30\n");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "gcx: note: LOOP.nct: kept as LinuxCNC's own: WHILE loops as o-word while, "
                   "canned cycle G81, variables and expressions\n" +
                       verifiedLine("LOOP"));
}

// In G19 the drilling axis is X: a cycle-code change repeats R and the X bottom, not Z.
TEST_F(TranslateNgc, ACycleCodeChangeRepeatsTheBottomOnThePlanesDrillingAxis) {
  write("G19.nct", "G90 G19 G21 G94\nG0 X10 Y0 Z0\nF120\nG98 G82 Y10 Z5 X-5 R2 P0.5\n"
                   "G85 Y20 R3\nG80\nM30\n");
  Result r;
  EXPECT_EQ(translate("G19", r), std::string(kHeader) +
                                     "G90 G19 G21 G94\nG0 X10 Y0 Z0\nF120\n"
                                     "G98 G82 Y10 Z5 P0.5 R2 X-5\nG85 Y20 R3 X-5\nG80\nM30\n");
  EXPECT_EQ(r.err, "gcx: note: G19.nct: kept as LinuxCNC's own: canned cycle G82, canned cycle "
                   "G85\n" +
                       verifiedLine("G19"));
}

// NCT's L on an arc counts its turns, LinuxCNC's P (nct-vs-linuxcnc.md); modal G2/G3 too.
TEST_F(TranslateNgc, ArcTurnsAreLinuxCncsP) {
  write("ARC.nct", "G90 G17 G21 G94\nG0 X0 Y0 Z0\nG2 X10 Y0 Z-5 I5 L2 F100\nX0 Z-10 I-5 L3\nM30\n");
  Result r;
  EXPECT_EQ(translate("ARC", r), std::string(kHeader) +
                                     "G90 G17 G21 G94\nG0 X0 Y0 Z0\nG2 X10 Y0 Z-5 I5 P2 F100\n"
                                     "X0 Z-10 I-5 P3\nM30\n");
  EXPECT_EQ(r.err, verifiedLine("ARC"));
}

// M98 P2001 L3 with the subprogram in its own file: an o2001 sub before the main program, called
// by a repeat; the I operator reads LinuxCNC's current position.
TEST_F(TranslateNgc, SubprogramWithRepeatsIsKeptAsAnOWordSub) {
  write("MAIN.nct", "G90 G17 G21 G94 G54\nS7000 M3\nG0 X20 Y30 Z2\nG1 Z0 F200\n"
                    "M98 P2001 L3\nG0 Z20\nM30\n");
  write("O2001.nct", "(ONE LEVEL)\nG1 X80 ZI-1 F400\nG1 X20 ZI-1\nM99\n");
  Result r;
  EXPECT_EQ(translate("MAIN", r), std::string(kHeader) + "o2001 sub\n"
                                                         "(ONE LEVEL)\n"
                                                         "G1 X80 Z[#5422-1] F400\n"
                                                         "G1 X20 Z[#5422-1]\n"
                                                         "o2001 endsub\n"
                                                         "G90 G17 G21 G94 G54\n"
                                                         "S7000 M3\n"
                                                         "G0 X20 Y30 Z2\n"
                                                         "G1 Z0 F200\n"
                                                         "o<r1> repeat [3]\n"
                                                         "o2001 call\n"
                                                         "o<r1> endrepeat\n"
                                                         "G0 Z20\n"
                                                         "M30\n");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "gcx: note: MAIN.nct: kept as LinuxCNC's own: subprogram O2001 as o2001 sub\n" +
                       verifiedLine("MAIN"));
}

// G65 A B C: LinuxCNC's positional #1 #2 #3; IF THEN as an o-word if.
TEST_F(TranslateNgc, MacroCallWithArgumentsIsKeptAsACallWithPositionalArguments) {
  write("MACRO.nct", "G90 G17 G21 G94 G54\nG0 X0 Y0 Z5\n"
                     "G65 P9010 A10 B20 C-2\nG65 P9010 A30 B20 C-3 L2\nM30\n");
  write("O9010.nct", "G0 X#1 Y#2\nG1 Z#3 F100\nIF[#3LT-2]THEN #100=#100+1\nG0 Z5\nM99\n");
  Result r;
  EXPECT_EQ(translate("MACRO", r), std::string(kHeader) + "o9010 sub\n"
                                                          "G0 X#1 Y#2\n"
                                                          "G1 Z#3 F100\n"
                                                          "o<if1> if [#3 LT -2]\n"
                                                          "#100 = [#100+1]\n"
                                                          "o<if1> endif\n"
                                                          "G0 Z5\n"
                                                          "o9010 endsub\n"
                                                          "G90 G17 G21 G94 G54\n"
                                                          "G0 X0 Y0 Z5\n"
                                                          "o9010 call [10] [20] [-2]\n"
                                                          "o<r2> repeat [2]\n"
                                                          "o9010 call [30] [20] [-3]\n"
                                                          "o<r2> endrepeat\n"
                                                          "M30\n");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "gcx: note: MACRO.nct: kept as LinuxCNC's own: IF THEN as o-word if, macro "
                   "O9010 as o9010 sub, variables and expressions\n" +
                       verifiedLine("MACRO"));
}

// GOTO has no LinuxCNC form: the program is written flat, the note says where and why.
TEST_F(TranslateNgc, GotoIsExpandedWithANote) {
  write("JUMP.nct", "G90 G0 X10 Y5\nG1 X20 F100\nGOTO5\nN5 M30\n");
  Result r;
  const std::string note =
      "written as plain G0-G3 motion: JUMP.nct:3: GOTO: LinuxCNC has no jump to a block number";
  EXPECT_EQ(translate("JUMP", r), "(" + note + ")\n" + kFlat +
                                      "G21 G90 G94 G17 G40 G49 G80 G54\n"
                                      "G0 X10 Y5 Z0\nG1 X20 Y5 Z0 F100\nM30\n");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "gcx: note: JUMP.nct: " + note + "\n" + verifiedLine("JUMP"));
}

// NCT's G84 reverses the spindle and returns to R; LinuxCNC's does not: expanded.
TEST_F(TranslateNgc, TappingCycleIsExpandedWithANote) {
  write("TAP.nct", "G90 G17 G21 G94 G54\nS500 M3\nG0 X10 Y10 Z20\nG98 G84 Z-10 R2 F500\n"
                   "G80\nM30\n");
  Result r;
  const std::string text = translate("TAP", r);
  const std::string note = "written as plain G0-G3 motion: TAP.nct:4: G84 cycle: NCT's floating "
                           "tap reverses the spindle and returns to R; LinuxCNC's G84 dwells and "
                           "feeds out to the clear level, and G74 has no LinuxCNC form";
  EXPECT_EQ(firstLine(text), "(" + note + ")\n");
  EXPECT_NE(text.find("S500 M4\nG1 X10 Y10 Z2 F500\n"), std::string::npos) << text;
  EXPECT_EQ(r.err, "gcx: note: TAP.nct: " + note + "\n" + verifiedLine("TAP"));
}

// An M98 subprogram sees its caller's #1-#33; a LinuxCNC call has its own: expanded.
TEST_F(TranslateNgc, SubprogramReadingItsCallersLocalsIsExpanded) {
  write("SHARE.nct", "G90 G0 X0 Y0\n#1=5\nM98 P3001\nM30\n");
  write("O3001.nct", "G1 X#1 F100\nM99\n");
  EXPECT_EQ(flatNote("SHARE"),
            "(written as plain G0-G3 motion: O3001.nct:1: X word value: an M98 subprogram shares "
            "its caller's local variables #1-#33; a LinuxCNC o-word call gives the subroutine its "
            "own)\n");
}

// A macro that reads an argument its call leaves vacant: LinuxCNC has no vacant value.
TEST_F(TranslateNgc, MacroReadingAVacantArgumentIsExpanded) {
  write("HOLE.nct", "G90 G0 X0 Y0 Z5\nG65 P9020 A10\nM30\n");
  write("O9020.nct", "G0 X#1 Y#2\nM99\n");
  EXPECT_EQ(flatNote("HOLE"),
            "(written as plain G0-G3 motion: HOLE.nct:2: G65 without the argument #2: O9020 reads "
            "it vacant; LinuxCNC has no vacant value)\n");
}

// The program's own G10 L2 P1-P6 under G90 is LinuxCNC's.
TEST_F(TranslateNgc, WorkOffsetsSetByTheProgramAreKept) {
  write("OFS.nct", "G90 G17 G21 G54\nG10 L2 P1 X100 Y50 Z-20\nG0 X10 Y10 Z5\n"
                   "G10 L2 P2 X[#500+1] Y0 Z0\nG55 G0 X1\nM30\n");
  Result r;
  EXPECT_EQ(translate("OFS", r), std::string(kHeader) +
                                     "G90 G17 G21 G54\nG10 L2 P1 X100 Y50 Z-20\nG0 X10 Y10 Z5\n"
                                     "G10 L2 P2 X[#500+1] Y0 Z0\nG55 G0 X1\nM30\n");
  EXPECT_EQ(r.err, "gcx: note: OFS.nct: kept as LinuxCNC's own: variables and expressions, work "
                   "offsets by G10 L2\n" +
                       verifiedLine("OFS"));
}

// --write-offsets: the setup's work offsets at the head of the program, so it runs on a machine
// whose own offsets are not set; rs274 with a setup of tools only moves like the source.
TEST_F(TranslateNgc, TheSetupsWorkOffsetsAreWrittenOnRequest) {
  write("setup.json", R"({"work_offsets": {"G54": [-412.5, -230, -380.25], "G55": [1, 2, 3]},
                          "tools": {"9": {"length": 80, "radius": 4.5}}})");
  write("tools.json", R"({"tools": {"9": {"length": 80, "radius": 4.5}}})");
  write("B.nct", "G90 G17 G21 G94 G54\nT9 M6\nG0 X10 Y10\nG43 Z30 H9\nG55 G0 X0 Y0\nM30\n");
  Result r;
  EXPECT_EQ(translate("B", r, " --setup setup.json --write-offsets"),
            std::string(kHeader) +
                "G10 L2 P1 X-412.5 Y-230 Z-380.25\nG10 L2 P2 X1 Y2 Z3\n"
                "G90 G17 G21 G94 G54\nT9 M6\nG0 X10 Y10\nG43 Z30 H9\nG55 G0 X0 Y0\nM30\n");
  EXPECT_EQ(r.err,
            "gcx: note: B.nct: kept as LinuxCNC's own: the setup's work offsets as G10 L2\n" +
                verifiedLine("B"));
  const Result e = gcx("equiv B.nct B.ngc --setup setup.json --setup-b tools.json");
  EXPECT_EQ(e.exitCode, 0) << e.out << e.err;
}

// A vacant variable makes NCT skip the word, LinuxCNC reads 0: the structured text is written,
// the proof finds the difference, and the flat motion is written instead.
TEST_F(TranslateNgc, AStructureTheProofRefutesIsExpanded) {
  write("VAC.nct", "G90 G0 X5 Y5\nG0 X#1 Y10\nM30\n");
  Result r;
  const std::string text = translate("VAC", r);
  const std::string note = "written as plain G0-G3 motion: the structured program did not move "
                           "the tool like the source: rapid end point X differs by 5.000 mm at "
                           "VAC.nct:1:1";
  EXPECT_EQ(text, "(" + note + ")\n" + kFlat +
                      "G21 G90 G94 G17 G40 G49 G80 G54\nG0 X5 Y5 Z0\nG0 X5 Y10 Z0\nM30\n");
  EXPECT_EQ(r.err, "gcx: note: VAC.nct: " + note + "\n" + verifiedLine("VAC"));
}

// rs274 on the structured files moves like gcx on the sources, also on a machine setup with a
// work offset and tool lengths (the program runs in the machine's own frame).
TEST_F(TranslateNgc, Rs274OnTheStructuredFileMovesLikeTheSource) {
  write("setup.json", R"({"work_offsets": {"G54": [-412.5, -230, -380.25]},
                          "tools": {"9": {"length": 80, "radius": 4.5}}})");
  write("BORE.nct", "G90 G17 G21 G94 G54\nT9 M6\nS900 M3\nG0 X10 Y10\nG43 Z30 H9\n#100=-8\n"
                    "G98 G82 X10 Y10 Z#100 R2 P0.5 F90 L1\nG91 G82 X15 Z-10 R-28 L3\nG90 G80\n"
                    "G98 G83 X5 Y40 Z-20 R2 Q6 E0.254 F100\nX25\nG81 X40 Y40\nG80\nM30\n");
  Result r;
  const std::string text = translate("BORE", r, " --setup setup.json");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(text.find("G98 G82 X10 Y10 P0.5 F90 L1 R2 Z#100\nG91 G82 X15 L3 R-28 Z-10\n"),
            std::string::npos)
      << text;
  // LinuxCNC asks R again when the cycle code changes
  EXPECT_NE(text.find("G98 G83 X5 Y40 Q6 F100 R2 Z-20\nX25\nG81 X40 Y40 R2 Z-20\n"),
            std::string::npos)
      << text;
  // the proof again, by the equivalence command on the written file
  const Result e = gcx("equiv BORE.nct BORE.ngc --setup setup.json");
  EXPECT_EQ(e.exitCode, 0) << e.out << e.err;
}

} // namespace
} // namespace gcx::test
