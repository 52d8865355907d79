// WL4 programs with hand-written LinuxCNC twins (tests/differential/wl4: NN.wl4 and NN.ngc,
// optionally NN.setup.json for the machine, such as a work offset):
//  * the twin: rs274 on the hand-written RS274/NGC program moves like gcx on the WL4 program;
//  * the contract: rs274 on gcx's canonical output reproduces gcx's path (1e-4 mm).
#include <gtest/gtest.h>

#include "differential/twin_driver.h"
#include "machine/setup.h"
#include "oracle/rs274.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

fs::path folder() {
  return sourceDir() / "tests" / "differential" / "wl4";
}

machine::Setup setupOf(const std::string& name) {
  return setupFileOrDefault(folder() / (name + ".setup.json"), "wl4");
}

MacroRun runProgram(const std::string& name) {
  return runWl4(readFile(folder() / (name + ".wl4")), setupOf(name));
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(folder(), {".wl4"}))
    out.push_back(p.stem().string());
  return out;
}

class Wl4Differential : public testing::TestWithParam<std::string> {};

TEST_P(Wl4Differential, TheHandWrittenTwinMovesTheSameOnRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectTwinMovesTheSame(ours.events, readFile(folder() / (GetParam() + ".ngc")));
}

TEST_P(Wl4Differential, Rs274ReproducesTheCanonicalOutput) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectRs274ReproducesTheCanonicalOutput(ours.events);
}

TEST_P(Wl4Differential, PrintedBackAsWl4ItMovesTheSame) {
  // parse -> gcx fmt's WL4 text -> parse: the same motion (the round trip of the printer)
  const std::string text = readFile(folder() / (GetParam() + ".wl4"));
  std::string printed;
  for (const std::string& line : printedWl4(parseWl4(text)))
    printed += line + "\n";
  MacroRun a = runWl4(text, setupOf(GetParam()));
  MacroRun b = runWl4(printed, setupOf(GetParam()));
  ASSERT_TRUE(a.errors.empty()) << a.rendered;
  ASSERT_TRUE(b.errors.empty()) << b.rendered << printed;
  EXPECT_EQ(a.all(), b.all()) << printed;
}

INSTANTIATE_TEST_SUITE_P(Wl4, Wl4Differential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           return twinTestName(p.param);
                         });

TEST(Wl4DifferentialCorpus, HasAtLeastTwentyProgramsEachWithItsTwin) {
  const std::vector<std::string> programs = names();
  EXPECT_GE(programs.size(), 20u);
  for (const std::string& n : programs)
    EXPECT_TRUE(fs::exists(folder() / (n + ".ngc"))) << n;
}

} // namespace
} // namespace gcx::test
