// FMS-3000 and WL4 radius compensation against LinuxCNC's rs274 compensating the same contour
// (tests/differential/comp/02_square_outside_g41.nct, tool radius 3): both dialects pass outer
// corners on arcs about the corner point, as LinuxCNC does, and here start-up and cancel are
// collinear, so the semantics coincide and the paths must be the same. (NCT parts from
// LinuxCNC at this contour's first outer corner: comp/expected.txt.)
#include <gtest/gtest.h>

#include "differential/oracle_run.h"
#include "machine/comp_support.h"
#include "oracle/compare.h"
#include "oracle/setup.h"
#include "support/fms3000_support.h"
#include "support/run_support.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

const char* kSquare = "G17 G90 G0 X0 Y-10 Z5\nG1 Z-1 F300\nG41 G1 X0 Y0 D1\nY30\nX30\nY0\nX0\n"
                      "G40 G1 X-10 Y0\nG0 Z5\n";

void expectSameAsRs274(const ProgramRun& ours) {
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  const fs::path dir = sourceDir() / "tests" / "differential" / "comp";
  const std::string program = readFile(dir / "02_square_outside_g41.nct");
  oracle::OracleSetup setup;
  std::string failure;
  ASSERT_TRUE(oracle::parseSetupJson(readFile(dir / "setup.json"), setup, failure)) << failure;
  oracle::Rs274Options options;
  oracle::applySetup(setup, options);
  const auto theirs = runOracle(program, options, failure);
  ASSERT_TRUE(failure.empty()) << failure;
  const oracle::CompareResult c = oracle::compareEvents(ours.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report;
}

TEST(CompFms3000Differential, OuterSquareAsRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  expectSameAsRs274(runFms(std::string(kSquare) + "M30\n", compSetup(3)));
}

TEST(CompWl4Differential, OuterSquareAsRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  expectSameAsRs274(runWl4(std::string("%T\n") + kSquare + "M2\n%\n", compSetup(3)));
}

} // namespace
} // namespace gcx::test
