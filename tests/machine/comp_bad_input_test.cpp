// The bad input of radius compensation (issue: radius larger than an inner arc, no
// intersection 2047, a plane change while compensating, a D without a register) through the
// command line: each program of tests/corpus/nct/comp-errors stops with the error its .expect
// names (LINE:COL CODE), exit code 1, and no output file.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fmt/format.h>
#include <sys/wait.h>

#include "support/run_support.h"

namespace gcx::test {
namespace {

fs::path folder() {
  return sourceDir() / "tests" / "corpus" / "nct" / "comp-errors";
}

class CompBadInput : public testing::TestWithParam<fs::path> {};

TEST_P(CompBadInput, LocatedCodedErrorAndNoOutputFile) {
  fs::path expectFile = GetParam();
  expectFile.replace_extension(".expect");
  std::string expected = readFile(expectFile);
  while (!expected.empty() && expected.back() == '\n')
    expected.pop_back();
  const std::string at = expected.substr(0, expected.find(' '));
  const std::string code = expected.substr(expected.find(' ') + 1);
  const fs::path out = fs::temp_directory_path() / ("gcx_comp_" + GetParam().stem().string());
  const fs::path err = fs::path(out).replace_extension(".err");
  fs::remove(out);
  const std::string cmd = fmt::format(
      "cd {} && {} expand {} --to canonical --setup setup.json -o {} 2>{}", folder().string(),
      GCX_BINARY, GetParam().filename().string(), out.string(), err.string());
  EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 1) << cmd;
  const std::string stderrText = readFile(err);
  fs::remove(err);
  EXPECT_NE(stderrText.find(GetParam().filename().string() + ":" + at + ": error:"),
            std::string::npos)
      << stderrText;
  EXPECT_NE(stderrText.find("[" + code + "]"), std::string::npos) << stderrText;
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(Programs, CompBadInput, testing::ValuesIn(filesUnder(folder(), {".nct"})),
                         [](const testing::TestParamInfo<fs::path>& p) {
                           return p.param.stem().string();
                         });

} // namespace
} // namespace gcx::test
