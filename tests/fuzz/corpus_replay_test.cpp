// The fuzz targets' entry points in the normal build: the committed fuzz corpus replays without a
// crash, a broken property or unbounded output, and the harness itself does what it claims.
#include <gtest/gtest.h>

#include <algorithm>

#include "dialect/dialect.h"
#include "fuzz/entry_points.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using fuzz::Bounds;
using fuzz::Outcome;
using fuzz::runTarget;

fs::path corpusOf(const std::string& target) {
  return sourceDir() / "tests" / "fuzz" / "corpus" / target;
}

TEST(FuzzCorpus, EveryTargetHasCommittedInputs) {
  for (const std::string& target : fuzz::targetNames()) {
    ASSERT_TRUE(fs::is_directory(corpusOf(target))) << target;
    EXPECT_GE(std::distance(fs::directory_iterator(corpusOf(target)), fs::directory_iterator{}), 10)
        << target;
  }
}

TEST(FuzzCorpus, EveryInputReplaysWithinBounds) {
  std::size_t replayed = 0;
  for (const std::string& target : fuzz::targetNames()) {
    if (!fs::is_directory(corpusOf(target))) continue;
    for (const auto& entry : fs::directory_iterator(corpusOf(target))) {
      const Outcome out = runTarget(target, readFile(entry.path()));
      const std::string name = target + "/" + entry.path().filename().string();
      EXPECT_EQ(out.violation, "") << name;
      EXPECT_LE(out.errors, Bounds::maxErrors) << name;
      // the cap is checked per event, so one event's text may pass it
      EXPECT_LE(out.outputBytes, Bounds::maxOutputBytes + 4096) << name;
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0u);
}

// FMS-3000 wants M02 or M30 at the end (fms3000.md §2.2): the error points at the last block
// even when no block reached the machine (found by expand_fms3000: it had no location).
TEST(FuzzHarness, Fms3000EndWithoutM30PointsAtTheLastBlock) {
  const Outcome out = runTarget("expand_fms3000", "G25 L 2");
  EXPECT_EQ(out.firstError, "1:1 GCX038");
  EXPECT_EQ(out.violation, "");
}

// The targets come from the dialect registry: a dialect added later is fuzzed too.
TEST(FuzzHarness, EveryDialectOfTheRegistryHasItsThreeTargets) {
  const std::vector<std::string>& names = fuzz::targetNames();
  for (const std::string& d : dialectNames())
    for (const char* kind : {"check_", "expand_", "fmt_"})
      EXPECT_NE(std::find(names.begin(), names.end(), kind + d), names.end()) << kind << d;
  EXPECT_EQ(names.size(), 3 * dialectNames().size() + 2); // and translate_nct, setup_json
}

TEST(FuzzHarness, Wl4CheckTargetReportsTheLocatedError) {
  const Outcome out = runTarget("check_wl4", "%P\nG0 X1\nL7\nM30\n%\n");
  EXPECT_EQ(out.errors, 1u);
  EXPECT_EQ(out.firstError.substr(0, 4), "3:1 ");
  EXPECT_EQ(out.violation, "");
}

// A plain program translates to fms3000, wl4, canonical and ngc, each proven and written.
TEST(FuzzHarness, TranslateTargetProvesEveryTranslation) {
  const Outcome out = runTarget("translate_nct", "G90 G0 X10 Y5\nG1 X20 F100\nM30\n");
  EXPECT_EQ(out.errors, 0u);
  EXPECT_EQ(out.violation, "");
  // a program that does not read fails every translation and writes no file: no violation
  const Outcome bad = runTarget("translate_nct", "G1 X1.2.3 F100\nM30\n");
  EXPECT_EQ(bad.errors, 4u);
  EXPECT_EQ(bad.firstError, "refused: fms3000");
  EXPECT_EQ(bad.violation, "");
}

TEST(FuzzHarness, CheckTargetReportsTheLocatedError) {
  const Outcome out = runTarget("check_nct", "G0 X0 Y0\nG1 X1.2.3 F100\nM30\n");
  EXPECT_EQ(out.errors, 1u);
  EXPECT_EQ(out.firstError, "2:8 2064");
  EXPECT_EQ(out.violation, "");
}

TEST(FuzzHarness, ExpandTargetCallsTheFilesAfterSeparators) {
  const Outcome split = runTarget("expand_nct", "M98 P9001\nM30\n@@\nG0 X1 Y2\nM99\n");
  const Outcome inline_ = runTarget("expand_nct", "G0 X1 Y2\nM30\n");
  EXPECT_EQ(split.firstError, "");
  EXPECT_FALSE(split.capped);
  EXPECT_GT(inline_.outputBytes, 0u);
  EXPECT_EQ(split.outputBytes, inline_.outputBytes);
}

TEST(FuzzHarness, ExpandTargetStartsEachRunWithAnEmptyFolder) {
  (void)runTarget("expand_nct", "M30\n@@\nG0 X1\nM99\n");
  const Outcome out = runTarget("expand_nct", "M98 P9001\nM30\n");
  EXPECT_EQ(out.firstError, "1:5 NCTX07");
}

// The move limit bounds what a block adds beyond its first move (docs/limits.md): here the
// holes of a drilling cycle's L count
TEST(FuzzHarness, ExpandTargetStopsARunawayAtItsMoveLimit) {
  const Outcome out =
      runTarget("expand_nct", "G0 X0 Y0 Z10\nG81 X1 Y1 Z-1 R1 F100 L99999999\nM30\n");
  EXPECT_FALSE(out.capped);
  EXPECT_EQ(out.firstError, "2:1 GCX043");
}

TEST(FuzzHarness, ExpandTargetCapsEventsThatAreNotMoves) {
  const Outcome out = runTarget(
      "expand_nct", "WHILE[1EQ1]DO1\nG4 P0.001\nM3 S100\nM8\nM9\nM5\nG4 P0.001\nEND1\nM30\n");
  EXPECT_TRUE(out.capped);
  EXPECT_EQ(out.errors, 0u);
}

TEST(FuzzHarness, ExpandTargetStopsALoopWithoutMotionAtItsJumpLimit) {
  const Outcome out = runTarget("expand_nct", "WHILE[1EQ1]DO1\n#1=#1+1\nEND1\nM30\n");
  EXPECT_FALSE(out.capped);
  EXPECT_EQ(out.firstError, "3:1 GCX040");
}

TEST(FuzzHarness, FmtTargetRoundTripsExpressions) {
  const Outcome out = runTarget("fmt_nct", "#1=[1+2]*SIN[30]\nG1 X#1 Y-[#1/2] F100\nM30\n");
  EXPECT_EQ(out.errors, 0u);
  EXPECT_EQ(out.violation, "");
  EXPECT_GT(out.outputBytes, 0u);
}

TEST(FuzzHarness, FmtTargetTakesMinusZeroAsZero) {
  const Outcome out = runTarget("fmt_nct", "G0 X-0 Y1\nM30\n");
  EXPECT_EQ(out.errors, 0u);
  EXPECT_EQ(out.violation, "");
  EXPECT_EQ(runTarget("fmt_nct", "C9 G!0\n").firstError, "1:4 2002");
}

TEST(FuzzHarness, SetupTargetLocatesAJsonSyntaxError) {
  const Outcome out = runTarget("setup_json", "{\n  \"work_offsets\": [\n}");
  EXPECT_EQ(out.errors, 1u);
  EXPECT_EQ(out.violation, "");
  EXPECT_EQ(out.firstError.substr(0, 2), "3:");
}

} // namespace
} // namespace gcx::test
