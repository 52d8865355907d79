// gcx translate --to <another dialect> (docs/translation.md): the executed motion in the target's
// syntax with each code chosen by its meaning, proven equivalent before it is written; what the
// target cannot express is a located error and no file.
#include <gtest/gtest.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

class TranslateDialects : public testing::Test {
protected:
  fs::path write(const std::string& name, const std::string& bytes) {
    return folder_.write(name, bytes);
  }
  CliResult gcx(const std::string& args) { return folder_.gcx(args); }
  std::string read(const std::string& name) { return readFile(dir_ / name); }

  CliFolder folder_{"translate-dialects"};
  const fs::path& dir_ = folder_.path();
};

// A program with no cycle, call, loop or variable: the note names only the frame.
constexpr const char* kNote =
    "machine frame, offsets and tool lengths in the coordinates, run without a setup";

// The note in comment lines of at most 60 characters, in each dialect's comment syntax.
std::string noteLines(const std::string& before, const std::string& after) {
  std::string out;
  for (const char* line :
       {"machine frame, offsets and tool lengths in the coordinates,", "run without a setup"})
    out += before + line + after;
  return out;
}

TEST_F(TranslateDialects, NctToFms3000WritesTheDwellInTenthsOfASecond) {
  write("A.nct", "G90 G0 X10 Y5\nG4 P0.5\nG1 X20 F100\nM30\n");
  const CliResult r = gcx("translate A.nct --to fms3000 -o A.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("A.fms"), "rem translated from A.nct (nct) by gcx\r\n" +
                               noteLines("rem ", "\r\n") +
                               "G90 G94 G17\r\nG00 X10 Y5 Z0\r\nG04 E5\r\nG01 X20 Y5 Z0 F100\r\n"
                               "M30\r\n");
  EXPECT_EQ(r.err, std::string("gcx: note: A.nct: ") + kNote +
                       "\ngcx: A.nct -> A.fms: verified, moves the tool like the source within "
                       "0.001 mm\n");
}

// FMS-3000 G04 E5 is half a second, and M98 ends the program: NCT G4 P0.5 and M2.
TEST_F(TranslateDialects, Fms3000ToNctWritesTheDwellInSecondsAndM98AsTheEnd) {
  write("B.fms", "G90 G00 X10 Y5\nG04 E5\nG01 X20 F100\nM98\n");
  const CliResult r = gcx("translate B.fms --to nct -o B.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("B.nct"), "O1\n(translated from B.fms [fms3000] by gcx)\n" +
                               noteLines("(", ")\n") +
                               "G90 G94 G17 G21\nG0 X10 Y5 Z0\nG4 P0.5\nG1 X20 Y5 Z0 F100\nM2\n");
}

TEST_F(TranslateDialects, Fms3000ToWl4WritesAProgramUnitWithTheDwellInSeconds) {
  write("B.fms", "G90 G00 X10 Y5\nG04 E5\nG01 X20 F100\nM98\n");
  const CliResult r = gcx("translate B.fms --to wl4 -o B.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("B.wl4"), "%B\n$translated from B.fms (fms3000) by gcx\n" + noteLines("$", "\n") +
                               "G90 G94 G17\nG0 X10 Y5 Z0\nG4 E0.5\nG1 X20 Y5 Z0 F100\nM2\n%\n");
}

// FMS-3000 has no G-code helix without G10: the pitch, travel per turn, goes in K; NCT's turn
// count L becomes one block per turn (FMS-3000 L is G25's repeat count).
TEST_F(TranslateDialects, NctHelixToFms3000IsG10WithItsPitchPerTurn) {
  write("H.nct", "G90 G0 X0 Y0 Z0\nG17 G3 X0 Y0 Z-6 I5 J0 L3 F200\nM30\n");
  const CliResult r = gcx("translate H.nct --to fms3000 -o H.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = read("H.fms");
  EXPECT_EQ(text.substr(text.find("G90")),
            "G90 G94 G17\r\nG03 X0 Y0 Z-2 I5 J0 G10 K-2 F200\r\nG03 X0 Y0 Z-4 I5 J0 G10 K-2 "
            "F200\r\nG03 X0 Y0 Z-6 I5 J0 G10 K-2 F200\r\nM30\r\n");
}

// Centres written absolute in the source (FMS-3000 N3021 = 1) are incremental in NCT.
TEST_F(TranslateDialects, AbsoluteFms3000CentresBecomeIncrementalNctCentres) {
  write("C.fms", "G90 G00 X10 Y0\nG02 X0 Y10 I0 J0 F100\nM30\n");
  write("C.setup.json", R"({"parameters": {"N3021": 1}})");
  const CliResult r = gcx("translate C.fms --setup C.setup.json --to nct -o C.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = read("C.nct");
  EXPECT_EQ(text.substr(text.find("G0 ")), "G0 X10 Y0 Z0\nG2 X0 Y10 Z0 I-10 J0 F100\nM30\n");
}

TEST_F(TranslateDialects, ADwellFms3000CannotHoldIsALocatedError) {
  write("C.wl4", "%P\nG0 X1\nG4 E0.55\nM30\n%\n");
  const CliResult r = gcx("translate C.wl4 --to fms3000 -o C.fms");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(fs::exists(dir_ / "C.fms"));
  EXPECT_EQ(r.err, "C.wl4:3:1: error: FMS-3000 writes a dwell in units of 0.1 s as a whole number "
                   "of E: 5.5 is not one [GCX081]\n  G4 E0.55\n  ^\n");
}

// NCT's coolant and tool change reach FMS-3000 as the ГОСТ codes its machines take.
TEST_F(TranslateDialects, NctCoolantAndToolChangeToFms3000AreTheGostCodes) {
  write("D.nct", "T3 M6\nM8\nG0 X1\nM9\nM30\n");
  const CliResult r = gcx("translate D.nct --to fms3000 -o D.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = read("D.fms");
  EXPECT_EQ(text.substr(text.find("G90")),
            "G90 G94 G17\r\nT3 M06\r\nM08\r\nG00 X1 Y0 Z0\r\nM09\r\nM30\r\n");
}

// The pitch is the travel per turn: half a turn down 5 mm is a pitch of 10 mm.
TEST_F(TranslateDialects, APartialTurnHelixToFms3000HasItsPitchPerFullTurn) {
  write("P.nct", "G90 G0 X10 Y0 Z0\nG3 X-10 Y0 Z-5 I-10 J0 F100\nM30\n");
  const CliResult r = gcx("translate P.nct --to fms3000 -o P.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = read("P.fms");
  EXPECT_EQ(text.substr(text.find("G90")),
            "G90 G94 G17\r\nG00 X10 Y0 Z0\r\nG03 X-10 Y0 Z-5 I-10 J0 "
            "G10 K-10 F100\r\nM30\r\n");
}

// Spindle, coolant and tool change by meaning; a dwell under G95 stays in revolutions.
TEST_F(TranslateDialects, NctMachineCodesAndARevolutionDwellToWl4) {
  write("M.nct", "T3 M6\nS1200 M4\nM7\nG95 G1 X2 F0.1\nG4 P3\nM9\nM5\nM30\n");
  const CliResult r = gcx("translate M.nct --to wl4 -o M.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string text = read("M.wl4");
  EXPECT_EQ(text.substr(text.find("G90")),
            "G90 G94 G17\nT3 M6\nS1200 M4\nM7\nG95\nG1 X2 Y0 Z0 F0.1\n"
            "G4 E3\nM9\nS1200 M5\nM30\n%\n");
}

TEST_F(TranslateDialects, ASpeedAboveFms3000sRangeIsALocatedError) {
  write("S.wl4", "%S\nS12000 M3\nG0 X1\nM30\n%\n");
  const CliResult r = gcx("translate S.wl4 --to fms3000 -o S.fms");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(fs::exists(dir_ / "S.fms"));
  EXPECT_EQ(r.err, "S.wl4:2:1: error: FMS-3000 S12000 for the spindle speed is outside S's range 0 "
                   "to 9999 [GCX081]\n  S12000 M3\n  ^\n");
}

// --from names the source's dialect only: the proof reads the translation in the target's
// (found by the translate_nct fuzz target: both were read as NCT, and every proof failed).
TEST_F(TranslateDialects, FromNamesTheSourceDialectNotTheTranslations) {
  write("A.txt", "G90 G0 X10 Y5\nG1 X20 F100\nM30\n");
  for (const char* to : {"fms3000", "wl4"}) {
    const std::string out = std::string("A.") + (to == std::string("wl4") ? "wl4" : "fms");
    const CliResult r = gcx(std::string("translate A.txt --from nct --to ") + to + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << to << ": " << r.err;
    EXPECT_NE(r.err.find("verified, moves the tool like the source"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / out)) << to;
  }
}

// A WL4 program is written in KOI8-R, its media code (wl4.md §1.1): the comments a structured
// translation keeps read back as written. A character KOI8-R lacks keeps no structure; the flat
// motion is written instead, and the note says why.
TEST_F(TranslateDialects, Wl4IsWrittenInKoi8r) {
  write("O0001.nct", "G90 G0 X0 Y0 Z5 (\u041F\u041E\u0414\u0412\u041E\u0414)\nM98 P2\nM30\n");
  write("O0002.nct", "G1 X10 F100\nM99\n");
  const CliResult r = gcx("translate O0001.nct --to wl4 -o A.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(read("A.wl4").find("\nG90 G0 X0 Y0 Z5 $\xF0\xEF\xE4\xF7\xEF\xE4\nL02\n"),
            std::string::npos)
      << read("A.wl4");
  write("O0003.nct", "G0 X1 (5 \u20AC)\nM98 P2\nM30\n");
  const CliResult e = gcx("translate O0003.nct --to wl4 -o B.wl4");
  EXPECT_EQ(e.exitCode, 0) << e.err;
  EXPECT_NE(e.err.find("structure not kept: its text holds U+20AC, which koi8-r has no code for; "
                       "run out into motion: subprogram calls (O0003.nct:2)"),
            std::string::npos)
      << e.err;
}

// A batch across dialects: every program of the tree to WL4, each proven.
TEST_F(TranslateDialects, ABatchTranslatesEveryDialectToWl4) {
  write("in/A.nct", "G90 G0 X10 Y5\nG4 P0.5\nG1 X20 F100\nM30\n");
  write("in/sub/B.fms", "G90 G00 X10 Y5\nG04 E5\nG01 X20 F100\nM98\n");
  const CliResult r = gcx("translate in --to wl4 -o out --jobs 2");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = read("out/report.csv");
  EXPECT_NE(csv.find("\nA.nct,out/A.wl4,verified,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nsub/B.fms,out/sub/B.wl4,verified,0,"), std::string::npos) << csv;
  const std::string a = read("out/A.wl4");
  EXPECT_EQ(a.substr(a.find("G90")),
            "G90 G94 G17\nG0 X10 Y5 Z0\nG4 E0.5\nG1 X20 Y5 Z0 F100\nM30\n%\n");
}

} // namespace
} // namespace gcx::test
