// FMS-3000 programs with hand-written LinuxCNC twins (tests/differential/fms3000: NN_name.fms,
// NN_name.ngc, optionally NN_name.setup.json for the machine parameters such as N3021). The
// program units a P call finds (`19.fms`, `019.fms`: a stem of digits) sit beside them and are
// visible to every program. Checked by the shared twin driver (differential/twin_driver.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "differential/twin_driver.h"
#include "machine/setup.h"
#include "oracle/rs274.h"
#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

fs::path folder() {
  return sourceDir() / "tests" / "differential" / "fms3000";
}

bool isProgramUnit(const fs::path& p) {
  const std::string s = p.stem().string();
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(folder(), {".fms"}))
    if (!isProgramUnit(p)) out.push_back(p.stem().string());
  return out;
}

machine::Setup setupOf(const std::string& name) {
  return setupFileOrDefault(folder() / (name + ".setup.json"));
}

MacroRun runProgram(const std::string& name) {
  std::map<std::string, std::string> files{{"main.fms", readFile(folder() / (name + ".fms"))}};
  for (const fs::path& p : filesUnder(folder(), {".fms"}))
    if (isProgramUnit(p)) files[p.filename().string()] = readFile(p);
  return runFms(files, setupOf(name));
}

class Fms3000Differential : public testing::TestWithParam<std::string> {};

TEST(Fms3000Differential, AtLeastTwentyPrograms) {
  EXPECT_GE(names().size(), 20u);
}

TEST_P(Fms3000Differential, TheHandWrittenTwinMovesTheSameOnRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectTwinMovesTheSame(ours.events, readFile(folder() / (GetParam() + ".ngc")));
}

TEST_P(Fms3000Differential, Rs274ReproducesTheCanonicalOutput) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectRs274ReproducesTheCanonicalOutput(ours.events);
}

INSTANTIATE_TEST_SUITE_P(Fms3000, Fms3000Differential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           return twinTestName(p.param);
                         });

} // namespace
} // namespace gcx::test
