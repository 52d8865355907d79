// gcx translate between dialects keeps drilling cycles as the target's own (docs/translation.md
// "Cycles across dialects"): each hole lifted from the motion its cycle ran, written with the
// target's cycle of the same meaning, proven by the equivalence engine; a hole the target's
// cycles cannot write is run out into motion, and the note says where and why.
#include <gtest/gtest.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

// NCT: a G99 hole, the same again modally, a G98 hole with a dwell.
constexpr const char* kNctHoles = "G90 G0 X0 Y0 Z50\n"
                                  "G99 G81 X10 Y10 R2 Z-10 F100\n"
                                  "X20\n"
                                  "G98 G82 X30 P0.5\n"
                                  "G80\n"
                                  "M30\n";

// FMS-3000: a hole, the same again by parameter memory, one more with its exit I at the start.
constexpr const char* kFmsHoles = "G90 G00 X0 Y0 Z50\n"
                                  "X10 Y10 G81 U2 Z-10 F100\n"
                                  "X20 G81\n"
                                  "X30 G81 I50\n"
                                  "G80\n"
                                  "M30\n";

// WL4: #2 #3, then two moves that each call %81.
constexpr const char* kWl4Holes = "%C\n"
                                  "G90 G0 X0 Y0 Z50\n"
                                  "#2=2 #3=-10\n"
                                  "G81 G0 X10 Y10 F100\n"
                                  "X20\n"
                                  "G80\n"
                                  "G0 Z50\n"
                                  "M30\n"
                                  "%\n";

// NCT G98 G85: feed in, feed out, then the initial level.
constexpr const char* kNctBores = "G90 G0 X0 Y0 Z50\n"
                                  "G98 G85 X10 Y10 R2 Z-10 F100\n"
                                  "X20\n"
                                  "G80\n"
                                  "M30\n";

class TranslateCycles : public testing::Test {
protected:
  void write(const std::string& name, const std::string& bytes) { folder_.write(name, bytes); }
  CliResult gcx(const std::string& args) { return folder_.gcx(args); }
  std::string read(const std::string& name) { return readFile(folder_.path() / name); }

  CliFolder folder_{"translate-cycles"};
};

// NCT G99 G81 / a modal hole / G98 G82 P: FMS-3000 positions by the words before G81, U is R, the
// G98 return an I at the initial level, the dwell E in tenths; a later hole writes only what
// changed.
TEST_F(TranslateCycles, Fms3000Spec_5_1_NctDrillingBecomesG81WithUZIAndItsParameterMemory) {
  write("A.nct", kNctHoles);
  const CliResult r = gcx("translate A.nct --to fms3000 -o A.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("A.fms"), "rem translated from A.nct (nct) by gcx\r\n"
                           "rem kept as fms3000 cycles: drilling (A.nct:2, 3), drilling with\r\n"
                           "rem dwell (A.nct:4); machine frame, offsets and tool lengths in\r\n"
                           "rem the coordinates, run without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z50\r\n"
                           "G00 X10 Y10 G81 U2 Z-10 F100\r\n"
                           "G00 X20 Y10 G81\r\n"
                           "G00 X30 Y10 G81 I50 E5\r\n"
                           "G80\r\n"
                           "M30\r\n");
  EXPECT_EQ(
      r.err,
      "gcx: note: A.nct: kept as fms3000 cycles: drilling (A.nct:2, 3), drilling with dwell "
      "(A.nct:4); machine frame, offsets and tool lengths in the coordinates, run without a setup\n"
      "gcx: A.nct -> A.fms: verified, moves the tool like the source within 0.001 mm\n");
}

// The same program to WL4: #2 R and #3 the bottom, the move of a G81 block calls %81; %82 dwells #4
// seconds. The stock cycles stay at #2, so the G98 hole is followed by G80 and a rapid to its
// level.
TEST_F(TranslateCycles, Wl4Spec_5_2_NctDrillingBecomesG81CallingPercent81WithItsLevelsInLocals) {
  write("A.nct", kNctHoles);
  const CliResult r = gcx("translate A.nct --to wl4 -o A.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("A.wl4"), "%A\n"
                           "$translated from A.nct (nct) by gcx\n"
                           "$kept as wl4 cycles: drilling (A.nct:2, 3), drilling with\n"
                           "$dwell (A.nct:4); machine frame, offsets and tool lengths in\n"
                           "$the coordinates, run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "#2=2 #3=-10\n"
                           "G81 G0 X10 Y10 F100\n"
                           "G0 X20 Y10\n"
                           "#4=0.5\n"
                           "G82 G0 X30 Y10 F100\n"
                           "G80\n"
                           "G0 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(
      r.err,
      "gcx: note: A.nct: kept as wl4 cycles: drilling (A.nct:2, 3), drilling with dwell (A.nct:4); "
      "machine frame, offsets and tool lengths in the coordinates, run without a setup\n"
      "gcx: A.nct -> A.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// FMS-3000 G81 without I ends at U: NCT G99; with I at the initial level: G98 on the later hole.
TEST_F(TranslateCycles, CyclesSpec_2_3_Fms3000LevelsBecomeG99OrG98ByWhereTheHoleEnds) {
  write("B.fms", kFmsHoles);
  const CliResult r = gcx("translate B.fms --to nct -o B.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("B.nct"), "O1\n"
                           "(translated from B.fms [fms3000] by gcx)\n"
                           "(kept as nct cycles: drilling [B.fms:2, 3, 4]; machine frame,)\n"
                           "(offsets and tool lengths in the coordinates, run without a)\n"
                           "(setup)\n"
                           "G90 G94 G17 G21\n"
                           "G0 X0 Y0 Z50\n"
                           "G99 G81 X10 Y10 R2 Z-10 F100\n"
                           "X20 Y10\n"
                           "G98 X30 Y10\n"
                           "G80\n"
                           "M30\n");
  EXPECT_EQ(r.err,
            "gcx: note: B.fms: kept as nct cycles: drilling (B.fms:2, 3, 4); machine frame, "
            "offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: B.fms -> B.nct: verified, moves the tool like the source within 0.001 mm\n");
}

// FMS-3000 to WL4: the exit I above U has no place in %81: G80 and a rapid after the hole.
TEST_F(TranslateCycles, Wl4Spec_5_2_Fms3000ExitAboveUBecomesG80AndARapid) {
  write("B.fms", kFmsHoles);
  const CliResult r = gcx("translate B.fms --to wl4 -o B.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("B.wl4"), "%B\n"
                           "$translated from B.fms (fms3000) by gcx\n"
                           "$kept as wl4 cycles: drilling (B.fms:2, 3, 4); machine frame,\n"
                           "$offsets and tool lengths in the coordinates, run without a\n"
                           "$setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "#2=2 #3=-10\n"
                           "G81 G0 X10 Y10 F100\n"
                           "G0 X20 Y10\n"
                           "G0 X30 Y10\n"
                           "G80\n"
                           "G0 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: B.fms: kept as wl4 cycles: drilling (B.fms:2, 3, 4); machine frame, "
            "offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: B.fms -> B.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// WL4 G81 with #2 #3: each move calls %81, which stays at #2: NCT G99 G81 R Z, then X Y. The
// program has variables, so it is written with its structure in the program's frame: #2 and #3
// stay (NCT's own variables now, read by nothing), the holes are the cycle's blocks.
TEST_F(TranslateCycles, CyclesSpec_2_3_Wl4CallsOfPercent81BecomeG99G81) {
  write("C.wl4", kWl4Holes);
  const CliResult r = gcx("translate C.wl4 --to nct -o C.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("C.nct"), "O1\n"
                           "(translated from C.wl4 [wl4] by gcx)\n"
                           "G90 G0 X0 Y0 Z50\n"
                           "#2=2\n"
                           "#3=-10\n"
                           "G99 G81 X10 Y10 R2 Z-10 F100\n"
                           "X20 Y10\n"
                           "G80\n"
                           "G0 Z50\n"
                           "M30\n");
  EXPECT_EQ(r.err, "gcx: note: C.wl4: kept as nct structure: variables (C.wl4:3), drilling "
                   "(C.wl4:4, 5); program frame: runs on the same setup as its source\n"
                   "gcx: C.wl4 -> C.nct: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// The same WL4 program to FMS-3000: G81 U Z, the second hole remembering them; #2 and #3 were
// read only by %81, and FMS-3000 has no variables: they go.
TEST_F(TranslateCycles, Fms3000Spec_5_1_Wl4CallsOfPercent81BecomeG81U) {
  write("C.wl4", kWl4Holes);
  const CliResult r = gcx("translate C.wl4 --to fms3000 -o C.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("C.fms"), "rem translated from C.wl4 (wl4) by gcx\r\n"
                           "G90 G00 X0 Y0 Z50\r\n"
                           "G00 X10 Y10 G81 U2 Z-10 F100\r\n"
                           "G00 X20 Y10 G81\r\n"
                           "G80\r\n"
                           "G00 Z50\r\n"
                           "M30\r\n");
  EXPECT_EQ(r.err, "gcx: note: C.wl4: kept as fms3000 structure: drilling (C.wl4:4, 5); "
                   "program frame: runs on the same setup as its source\n"
                   "gcx: C.wl4 -> C.fms: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// NCT G83 Q4 (clearance 1 mm, the setting): FMS-3000 G83 V4 W1, the G98 return as I.
TEST_F(TranslateCycles, Fms3000Spec_5_2_NctG83PecksBecomeG83WithVAndW) {
  write("P.nct", "G90 G0 X0 Y0 Z50\n"
                 "G98 G83 X10 Y10 R2 Z-10 Q4 F100\n"
                 "X20\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate P.nct --to fms3000 -o P.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("P.fms"), "rem translated from P.nct (nct) by gcx\r\n"
                           "rem kept as fms3000 cycles: peck drilling (P.nct:2, 3); machine\r\n"
                           "rem frame, offsets and tool lengths in the coordinates, run\r\n"
                           "rem without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z50\r\n"
                           "G00 X10 Y10 G83 U2 Z-10 I50 V4 W1 F100\r\n"
                           "G00 X20 Y10 G83\r\n"
                           "G80\r\n"
                           "M30\r\n");
  EXPECT_EQ(r.err,
            "gcx: note: P.nct: kept as fms3000 cycles: peck drilling (P.nct:2, 3); machine frame, "
            "offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: P.nct -> P.fms: verified, moves the tool like the source within 0.001 mm\n");
}

// FMS-3000 G83 with W1 is WL4 %83, which starts each peck 1 mm above the last: #5 the peck.
TEST_F(TranslateCycles, Wl4Spec_5_2_Fms3000G83BecomesPercent83WithThePeckInHash5) {
  write("Q.fms", "G90 G00 X0 Y0 Z50\n"
                 "X10 Y10 G83 U2 Z-10 V4 W1 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate Q.fms --to wl4 -o Q.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("Q.wl4"), "%Q\n"
                           "$translated from Q.fms (fms3000) by gcx\n"
                           "$kept as wl4 cycles: peck drilling (Q.fms:2); machine frame,\n"
                           "$offsets and tool lengths in the coordinates, run without a\n"
                           "$setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "#2=2 #3=-10 #5=4\n"
                           "G83 G0 X10 Y10 F100\n"
                           "G80\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: Q.fms: kept as wl4 cycles: peck drilling (Q.fms:2); machine frame, offsets "
            "and tool lengths in the coordinates, run without a setup\n"
            "gcx: Q.fms -> Q.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// A clearance of 0.5 mm has no %83: the hole is run out, the note says why.
TEST_F(TranslateCycles, Wl4Spec_5_2_APeckWithAnotherClearanceIsRunOutWithWhy) {
  write("R.nct", "G90 G0 X0 Y0 Z50\n"
                 "G99 G83 X10 Y10 R2 Z-10 Q4 E0.5 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate R.nct --to wl4 -o R.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("R.wl4"), "%R\n"
                           "$translated from R.nct (nct) by gcx\n"
                           "$run out into motion: the peck drilling cycle at R.nct:2: WL4\n"
                           "$%83 starts each peck 1 mm above the last depth, not 0.5 mm;\n"
                           "$machine frame, offsets and tool lengths in the coordinates,\n"
                           "$run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X10 Y10 Z2\n"
                           "G1 X10 Y10 Z-2 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z-1.5\n"
                           "G1 X10 Y10 Z-6 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z-5.5\n"
                           "G1 X10 Y10 Z-10 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: R.nct: run out into motion: the peck drilling cycle at R.nct:2: WL4 %83 "
            "starts each peck 1 mm above the last depth, not 0.5 mm; machine frame, offsets and "
            "tool lengths in the coordinates, run without a setup\n"
            "gcx: R.nct -> R.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// NCT G73 backs off E (the setting, 0.5 mm) after each peck: FMS-3000 G86 V4 W0.5.
TEST_F(TranslateCycles, Fms3000Spec_5_2_NctG73BecomesG86WithVAndW) {
  write("H.nct", "G90 G0 X0 Y0 Z50\n"
                 "G98 G73 X10 Y10 R2 Z-10 Q4 F100\n"
                 "X20\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate H.nct --to fms3000 -o H.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("H.fms"), "rem translated from H.nct (nct) by gcx\r\n"
                           "rem kept as fms3000 cycles: chip-breaking drilling (H.nct:2, 3);\r\n"
                           "rem machine frame, offsets and tool lengths in the coordinates,\r\n"
                           "rem run without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z50\r\n"
                           "G00 X10 Y10 G86 U2 Z-10 I50 V4 W0.5 F100\r\n"
                           "G00 X20 Y10 G86\r\n"
                           "G80\r\n"
                           "M30\r\n");
  EXPECT_EQ(r.err,
            "gcx: note: H.nct: kept as fms3000 cycles: chip-breaking drilling (H.nct:2, 3); "
            "machine frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: H.nct -> H.fms: verified, moves the tool like the source within 0.001 mm\n");
}

// WL4 has no chip-breaking program among %81-%89: each hole is run out, the note says why once.
TEST_F(TranslateCycles, Wl4Spec_5_2_AChipBreakingCycleIsRunOutWithWhy) {
  write("H.nct", "G90 G0 X0 Y0 Z50\n"
                 "G98 G73 X10 Y10 R2 Z-10 Q4 F100\n"
                 "X20\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate H.nct --to wl4 -o H.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("H.wl4"), "%H\n"
                           "$translated from H.nct (nct) by gcx\n"
                           "$run out into motion: the chip-breaking drilling cycle at\n"
                           "$H.nct:2, 3: WL4's stock programs %81-%89 have no\n"
                           "$chip-breaking cycle; machine frame, offsets and tool lengths\n"
                           "$in the coordinates, run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X10 Y10 Z2\n"
                           "G1 X10 Y10 Z-2 F100\n"
                           "G0 X10 Y10 Z-1.5\n"
                           "G1 X10 Y10 Z-6 F100\n"
                           "G0 X10 Y10 Z-5.5\n"
                           "G1 X10 Y10 Z-10 F100\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X20 Y10 Z50\n"
                           "G0 X20 Y10 Z2\n"
                           "G1 X20 Y10 Z-2 F100\n"
                           "G0 X20 Y10 Z-1.5\n"
                           "G1 X20 Y10 Z-6 F100\n"
                           "G0 X20 Y10 Z-5.5\n"
                           "G1 X20 Y10 Z-10 F100\n"
                           "G0 X20 Y10 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: H.nct: run out into motion: the chip-breaking drilling cycle at H.nct:2, "
            "3: WL4's stock programs %81-%89 have no chip-breaking cycle; machine frame, offsets "
            "and tool lengths in the coordinates, run without a setup\n"
            "gcx: H.nct -> H.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// FMS-3000 G86 V4 W0.5 without I ends at U: NCT G99 G73 Q4 E0.5.
TEST_F(TranslateCycles, CyclesSpec_2_4_Fms3000G86BecomesG73WithQAndE) {
  write("G.fms", "G90 G00 X0 Y0 Z50\n"
                 "X10 Y10 G86 U2 Z-10 V4 W0.5 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate G.fms --to nct -o G.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("G.nct"), "O1\n"
                           "(translated from G.fms [fms3000] by gcx)\n"
                           "(kept as nct cycles: chip-breaking drilling [G.fms:2];)\n"
                           "(machine frame, offsets and tool lengths in the coordinates,)\n"
                           "(run without a setup)\n"
                           "G90 G94 G17 G21\n"
                           "G0 X0 Y0 Z50\n"
                           "G99 G73 X10 Y10 R2 Z-10 Q4 E0.5 F100\n"
                           "G80\n"
                           "M30\n");
  EXPECT_EQ(r.err,
            "gcx: note: G.fms: kept as nct cycles: chip-breaking drilling (G.fms:2); machine "
            "frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: G.fms -> G.nct: verified, moves the tool like the source within 0.001 mm\n");
}

// whole, not its first peck taken for a hole.
TEST_F(TranslateCycles, APeckWhoseRapidRisesAboveRIsRunOutWhole) {
  write("K.nct", "G90 G0 X0 Y0 Z50\n"
                 "G99 G83 X10 Y10 R2 Z-3 Q1.5 E2 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate K.nct --to wl4 -o K.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("K.wl4"), "%K\n"
                           "$translated from K.nct (nct) by gcx\n"
                           "$run out into motion: cycles (K.nct:2): no single drilled\n"
                           "$hole that the target's cycles take; machine frame, offsets\n"
                           "$and tool lengths in the coordinates, run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X10 Y10 Z2\n"
                           "G1 X10 Y10 Z0.5 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z2.5\n"
                           "G1 X10 Y10 Z-1 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z1\n"
                           "G1 X10 Y10 Z-2.5 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z-0.5\n"
                           "G1 X10 Y10 Z-3 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: K.nct: run out into motion: cycles (K.nct:2): no single drilled hole that "
            "the target's cycles take; machine frame, offsets and tool lengths in the coordinates, "
            "run without a setup\n"
            "gcx: K.nct -> K.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// FMS-3000 I60 above the initial level 50: NCT returns to the initial level or R only.
TEST_F(TranslateCycles, AnExitNctCannotReturnToIsRunOutWithWhy) {
  write("E.fms", "G90 G00 X0 Y0 Z50\n"
                 "X10 Y10 G81 U2 Z-10 I60 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate E.fms --to nct -o E.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("E.nct"), "O1\n"
                           "(translated from E.fms [fms3000] by gcx)\n"
                           "(run out into motion: the drilling cycle at E.fms:2: NCT)\n"
                           "(leaves a hole at its initial level or at R, not at Z60;)\n"
                           "(machine frame, offsets and tool lengths in the coordinates,)\n"
                           "(run without a setup)\n"
                           "G90 G94 G17 G21\n"
                           "G0 X0 Y0 Z50\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X10 Y10 Z2\n"
                           "G1 X10 Y10 Z-10 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X10 Y10 Z60\n"
                           "M30\n");
  EXPECT_EQ(r.err,
            "gcx: note: E.fms: run out into motion: the drilling cycle at E.fms:2: NCT leaves a "
            "hole at its initial level or at R, not at Z60; machine frame, offsets and tool "
            "lengths in the coordinates, run without a setup\n"
            "gcx: E.fms -> E.nct: verified, moves the tool like the source within 0.001 mm\n");
}

// --expand cycles: today's flat motion; --verify is the default, named.
TEST_F(TranslateCycles, ExpandCyclesRunsEveryCycleOutAndVerifyIsTheDefaultNamed) {
  write("A.nct", kNctHoles);
  const CliResult r = gcx("translate A.nct --to wl4 --expand cycles,loops --verify -o X.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("X.wl4"), "%A\n"
                           "$translated from A.nct (nct) by gcx\n"
                           "$run out into motion: cycles (A.nct:2, 4) (--expand cycles);\n"
                           "$machine frame, offsets and tool lengths in the coordinates,\n"
                           "$run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "G0 X10 Y10 Z50\n"
                           "G0 X10 Y10 Z2\n"
                           "G1 X10 Y10 Z-10 F100\n"
                           "G0 X10 Y10 Z2\n"
                           "G0 X20 Y10 Z2\n"
                           "G1 X20 Y10 Z-10 F100\n"
                           "G0 X20 Y10 Z2\n"
                           "G0 X30 Y10 Z2\n"
                           "G1 X30 Y10 Z-10 F100\n"
                           "G4 E0.5\n"
                           "G0 X30 Y10 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: A.nct: run out into motion: cycles (A.nct:2, 4) (--expand cycles); machine "
            "frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: A.nct -> X.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// NCT G85 (feed out at F) is FMS-3000 G82 without H; G98 is I at the initial level.
TEST_F(TranslateCycles, Fms3000Spec_5_2_NctG85BecomesG82WithTheFeedOutAtF) {
  write("D.nct", kNctBores);
  const CliResult r = gcx("translate D.nct --to fms3000 -o D.fms");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("D.fms"), "rem translated from D.nct (nct) by gcx\r\n"
                           "rem kept as fms3000 cycles: boring with feed out (D.nct:2, 3);\r\n"
                           "rem machine frame, offsets and tool lengths in the coordinates,\r\n"
                           "rem run without a setup\r\n"
                           "G90 G94 G17\r\n"
                           "G00 X0 Y0 Z50\r\n"
                           "G00 X10 Y10 G82 U2 Z-10 I50 F100\r\n"
                           "G00 X20 Y10 G82\r\n"
                           "G80\r\n"
                           "M30\r\n");
  EXPECT_EQ(r.err,
            "gcx: note: D.nct: kept as fms3000 cycles: boring with feed out (D.nct:2, 3); machine "
            "frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: D.nct -> D.fms: verified, moves the tool like the source within 0.001 mm\n");
}

// NCT G85 to WL4 %85, feeding out to #2; G98 again G80 and a rapid after each hole.
TEST_F(TranslateCycles, Wl4Spec_5_2_NctG85BecomesPercent85) {
  write("D.nct", kNctBores);
  const CliResult r = gcx("translate D.nct --to wl4 -o D.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("D.wl4"), "%D\n"
                           "$translated from D.nct (nct) by gcx\n"
                           "$kept as wl4 cycles: boring with feed out (D.nct:2, 3);\n"
                           "$machine frame, offsets and tool lengths in the coordinates,\n"
                           "$run without a setup\n"
                           "G90 G94 G17\n"
                           "G0 X0 Y0 Z50\n"
                           "#2=2 #3=-10\n"
                           "G85 G0 X10 Y10 F100\n"
                           "G80\n"
                           "G0 Z50\n"
                           "G85 G0 X20 Y10 F100\n"
                           "G80\n"
                           "G0 Z50\n"
                           "M30\n"
                           "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: D.nct: kept as wl4 cycles: boring with feed out (D.nct:2, 3); machine "
            "frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: D.nct -> D.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// The line of report.csv that names `program`, from its reason on (seconds and RSS vary).
std::string reportTail(const std::string& csv, const std::string& program) {
  const std::size_t at = csv.find("\n" + program + ",");
  if (at == std::string::npos) return "missing";
  std::string line = csv.substr(at + 1, csv.find('\n', at + 1) - at - 1);
  for (int cell = 0; cell < 6; ++cell)
    line = line.substr(line.find(',') + 1);
  return line;
}

// A batch reports per program what its translation kept and what it ran out.
TEST_F(TranslateCycles, ABatchReportsTheKeptAndExpandedStructures) {
  write("in/A.nct", "G90 G0 X0 Y0 Z50\nG99 G81 X10 Y10 R2 Z-10 F100\nX20\nG80\nM30\n");
  write("in/P.nct", "G90 G0 X0 Y0 Z50\nG99 G83 X10 Y10 R2 Z-3 Q1.5 E2 F100\nG80\nM30\n");
  const CliResult r = gcx("translate in --to fms3000 -o out --jobs 2");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = read("out/report.csv");
  EXPECT_EQ(reportTail(csv, "A.nct"), ",\"drilling (A.nct:2, 3)\",");
  EXPECT_EQ(reportTail(csv, "P.nct"),
            ",,cycles (P.nct:2): no single drilled hole that the target's cycles take");
  EXPECT_NE(read("out/report.html").find("<td></td><td>drilling (A.nct:2, 3)</td><td></td></tr>"),
            std::string::npos);
}

// To its own dialect --expand cycles writes the flat motion in the machine frame, as across
// dialects.
TEST_F(TranslateCycles, ExpandCyclesToTheSameDialectWritesTheFlatMotion) {
  write("S.nct", "G90 G0 X0 Y0 Z50\n"
                 "G99 G81 X10 Y10 R2 Z-10 F100\n"
                 "G80\n"
                 "M30\n");
  const CliResult r = gcx("translate S.nct --to nct --expand cycles -o S2.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("S2.nct"), "O1\n"
                            "(translated from S.nct [nct] by gcx)\n"
                            "(run out into motion: cycles [S.nct:2] [--expand cycles];)\n"
                            "(machine frame, offsets and tool lengths in the coordinates,)\n"
                            "(run without a setup)\n"
                            "G90 G94 G17 G21\n"
                            "G0 X0 Y0 Z50\n"
                            "G0 X10 Y10 Z50\n"
                            "G0 X10 Y10 Z2\n"
                            "G1 X10 Y10 Z-10 F100\n"
                            "G0 X10 Y10 Z2\n"
                            "M30\n");
  EXPECT_EQ(r.err,
            "gcx: note: S.nct: run out into motion: cycles (S.nct:2) (--expand cycles); machine "
            "frame, offsets and tool lengths in the coordinates, run without a setup\n"
            "gcx: S.nct -> S2.nct: verified, moves the tool like the source within 0.001 mm\n");
}

// WL4 to WL4 prints the program as written; --expand runs it out through the expansion instead.
TEST_F(TranslateCycles, ExpandToWl4ItselfRunsTheProgramOutInsteadOfPrintingIt) {
  write("W.wl4", "%W\n"
                 "G90 G0 X0 Y0 Z5\n"
                 "#1=2\n"
                 "G1 X#1 F100\n"
                 "M30\n"
                 "%\n");
  const CliResult r = gcx("translate W.wl4 --to wl4 --expand loops -o W2.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(read("W2.wl4"), "%MAIN\n"
                            "G90 G0 X0 Y0 Z5\n"
                            "G1 X2 F100\n"
                            "M30\n"
                            "%\n");
  EXPECT_EQ(r.err,
            "gcx: note: W.wl4: cycles, subprograms, loops, variables and modal calls expanded into "
            "the blocks they run\n"
            "gcx: W.wl4 -> W2.wl4: verified, moves the tool like the source within 0.001 mm\n");
}

// An unknown --expand word is a usage error before anything runs.
TEST_F(TranslateCycles, ExpandRejectsAWordItDoesNotKnow) {
  write("A.nct", kNctHoles);
  const CliResult r = gcx("translate A.nct --to wl4 --expand cycles,macros -o A.wl4");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "--expand: 'macros' is none of cycles, subprograms, loops, variables, all\n"
                   "Run with --help for more information.\n");
}

} // namespace
} // namespace gcx::test
