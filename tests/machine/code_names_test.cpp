// Messages name codes by the dialect's own numbers: the word as written or the profile's code
// of an action (machine/code_names.h), never numbers spelled in the core. Each case checks the
// whole message of one dialect; the FMS-3000 and WL4 cases name codes NCT does not have.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"
#include "support/run_support.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

// true when `rendered` holds a diagnostic with exactly this text
bool says(const std::string& rendered, const std::string& message) {
  return rendered.find(": " + message + "\n") != std::string::npos ||
         rendered.find(": " + message + " [") != std::string::npos;
}

TEST(CodeNames, NctNestingNamesTheScaleAndRotationCodes) {
  const ProgramRun r = runNct("G51 X0 Y0 P2\nG68 X0 Y0 R30\nG50\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G50 while G68 switched on after G51 is still active: "
                               "switch-offs must nest (nct.md §3.15)"))
      << r.rendered;
}

TEST(CodeNames, NctMirrorNamesThePlainState) {
  const ProgramRun r = runNct("G68 X0 Y0 R30\nG51.1 X0\nM30\n");
  EXPECT_TRUE(says(r.rendered, "mirror may only be switched on in G50 G69 state (nct.md §3.15)"))
      << r.rendered;
}

TEST(CodeNames, NctReferencePointCountIsTheProfiles) {
  const ProgramRun r = runNct("G30 P5 X0\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G30 needs P1 to P4 to name the reference point (nct.md Q15)"))
      << r.rendered;
}

TEST(CodeNames, NctSpindleCodesListTheProfilesExclusiveCodes) {
  const Parsed p = parseNct("M3 M19\n");
  EXPECT_TRUE(
      says(p.rendered(), "conflicting spindle M codes: M3, M4, M5 and M19 exclude each other"))
      << p.rendered();
}

TEST(CodeNames, Fms3000SpindleCodesHaveNoM19) {
  const Parsed p = parseFms("M3 M5\nM30\n");
  EXPECT_TRUE(says(p.rendered(), "conflicting spindle M codes: M3, M4 and M5 exclude each other"))
      << p.rendered();
}

TEST(CodeNames, NctDataRecordFormatIsTheProfiles) {
  const Parsed p = parseNct("G10 L52\nN10000 R1\nN1339 Q8 R1\nN1339 X1 R1\nN1339 P1\nG11\n");
  EXPECT_TRUE(says(p.rendered(), "parameter number 10000 is out of range 0-9999")) << p.rendered();
  EXPECT_TRUE(says(p.rendered(), "bit number Q must be 0-7")) << p.rendered();
  EXPECT_TRUE(says(p.rendered(), "address X is not allowed in a G10 L52 record")) << p.rendered();
  EXPECT_TRUE(says(p.rendered(), "parameter record without R value")) << p.rendered();
  EXPECT_EQ(p.errors().size(), 4u) << p.rendered();
}

TEST(CodeNames, Fms3000ProfileBlockListsTheProfilesWords) {
  const MacroRun r =
      runFms("G18 G90 G0 X20 Z2\nG164 Q4 V6 W1 F100\nG1 Z-20\nG94 X12 Z-10\nendcont\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G94 is not allowed in the profile of G164: only N X Z G1 G2 G3 "
                               "G90 G91 I J K R F (001:3287-3291, 001:3903-3909)"))
      << r.rendered;
}

TEST(CodeNames, Fms3000ProfileBlockAllowsARapidApproachOnly) {
  const MacroRun ok =
      runFms("G18 G90 G0 X20 Z2\nG164 Q4 V6 W1 F100\nG0 Z-20\nX12 Z-10\nendcont\nM30\n");
  EXPECT_TRUE(ok.errors.empty()) << ok.rendered;
  const MacroRun r =
      runFms("G18 G90 G0 X20 Z2\nG164 Q4 V6 W1 F100\nG1 Z-20\nG0 X12 Z-10\nendcont\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G0 is not allowed in the profile of G164: only N X Z G1 G2 G3 "
                               "G90 G91 I J K R F (001:3287-3291, 001:3903-3909)"))
      << r.rendered;
}

TEST(CodeNames, Fms3000LatheCycleNamesItsPlaneCode) {
  const MacroRun r = runFms("G17 G90 G0 X20 Z2\nG164 Q4 V6 W1 F100\nG1 Z-20\nendcont\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G164 turns in the lathe plane: G18 first (fms3000.md §5.3)"))
      << r.rendered;
}

TEST(CodeNames, Fms3000PolarNamesItsOwnCodes) {
  const MacroRun r = runFms("G90 G17 G0 X0 Y0\nG36 X50\nM30\n");
  EXPECT_TRUE(says(r.rendered, "G36 without the pole: write X and Y (fms3000.md §3.11)"))
      << r.rendered;
  const MacroRun plane = runFms("G90 G17 G0 X0 Y0\nG36 X50 Y50\nG18\nM30\n");
  EXPECT_TRUE(
      says(plane.rendered, "no plane change in polar coordinates: G35 first (fms3000.md §3.11)"))
      << plane.rendered;
}

TEST(CodeNames, Wl4MirrorBySignNamesItsCode) {
  const MacroRun r = runWl4("%P\nG51 X2\nM2\n%\n");
  EXPECT_TRUE(says(r.rendered, "G51 X2: an axis word of G51 is -1 (mirror on) or 1 (off) "
                               "(wl4.md §3.13)"))
      << r.rendered;
}

TEST(CodeNames, Wl4ThreadNamesItsCode) {
  const MacroRun r = runWl4("%P\nG90 G0 X0 Z0\nG33 X10 F2\nM2\n%\n");
  EXPECT_TRUE(says(r.rendered, "G33 without travel along Z: the canonical output's thread "
                               "(G33 K) leads along Z only"))
      << r.rendered;
}

TEST(CodeNames, Wl4ProbeWarningIsTheDialects) {
  const MacroRun r = runWl4("%P\nG90 G17 G0 X10 Y0 Z5\nG38 G1 Y40 F200\nM2\n%\n");
  EXPECT_TRUE(says(r.rendered, "G38: gcx has no probe model and assumes no touch (wl4.md §3.8): "
                               "the move runs to its end point and back, and #1000-#1027 hold "
                               "the end point"))
      << r.rendered;
}

} // namespace
} // namespace gcx::test
