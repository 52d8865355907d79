// Malformed WL4 programs: each file's sidecar .expect names the first error (LINE:COL CODE),
// found while reading (front end, static checks) or while running (labels, calls, values).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

std::vector<fs::path> badFiles() {
  return filesUnder(sourceDir() / "tests" / "corpus" / "wl4" / "bad", {".wl4"});
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  std::string n = info.param.stem().string();
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

class Wl4BadInput : public testing::TestWithParam<fs::path> {};

TEST_P(Wl4BadInput, FirstErrorHasTheExpectedCodeAndLocation) {
  fs::path expectFile = GetParam();
  expectFile.replace_extension(".expect");
  std::string expected = readFile(expectFile);
  while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r'))
    expected.pop_back();
  MacroRun r = runWl4(readFile(GetParam()));
  const std::vector<std::string> errors = errorsAt(r);
  ASSERT_FALSE(errors.empty()) << "no error reported for " << GetParam();
  EXPECT_EQ(errors.front(), expected) << r.rendered;
}

INSTANTIATE_TEST_SUITE_P(Wl4, Wl4BadInput, testing::ValuesIn(badFiles()), testName);

TEST(Wl4BadInputCorpus, HasAtLeastThirtyCases) {
  EXPECT_GE(badFiles().size(), 30u);
}

} // namespace
} // namespace gcx::test
