// Programs that parse but cannot run: each file's sidecar .expect names the first error
// (LINE:COL CODE) the interpreter must report; execution stops there.
#include <gtest/gtest.h>

#include "support/run_support.h"

namespace gcx::test {
namespace {

std::vector<fs::path> files() {
  return filesUnder(sourceDir() / "tests" / "corpus" / "nct" / "run-errors", {".nct"});
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  return info.param.stem().string();
}

class RunError : public testing::TestWithParam<fs::path> {};

TEST_P(RunError, StopsWithTheExpectedCodeAndLocation) {
  fs::path expectFile = GetParam();
  expectFile.replace_extension(".expect");
  std::string expected = readFile(expectFile);
  while (!expected.empty() && expected.back() == '\n')
    expected.pop_back();
  ProgramRun r = runNct(readFile(GetParam()));
  ASSERT_FALSE(r.errors.empty()) << "no error for " << GetParam();
  EXPECT_EQ(r.errors.front(), expected) << r.rendered;
  EXPECT_EQ(r.errors.size(), 1u) << r.rendered;
  for (const motion::Event& e : r.events)
    EXPECT_NE(e.kind, motion::Kind::End);
}

INSTANTIATE_TEST_SUITE_P(Nct, RunError, testing::ValuesIn(files()), testName);

} // namespace
} // namespace gcx::test
