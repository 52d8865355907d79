// Malformed inputs: each file's sidecar .expect names the first error (LINE:COL CODE).
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace gcx::test {
namespace {

std::vector<fs::path> badFiles() {
  std::vector<fs::path> all;
  for (const char* dir : {"bad", "spec-errors"})
    for (auto& p : filesUnder(sourceDir() / "tests" / "corpus" / "nct" / dir, {".nct"}))
      all.push_back(p);
  return all;
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  std::string n = info.param.parent_path().filename().string() + "_" + info.param.stem().string();
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

class BadInput : public testing::TestWithParam<fs::path> {};

TEST_P(BadInput, FirstErrorHasTheExpectedCodeAndLocation) {
  fs::path expectFile = GetParam();
  expectFile.replace_extension(".expect");
  std::string expected = readFile(expectFile);
  while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r'))
    expected.pop_back();
  Parsed p = parseNctFile(GetParam());
  auto errors = p.errors();
  ASSERT_FALSE(errors.empty()) << "no error reported for " << GetParam();
  EXPECT_EQ(errors.front(), expected) << p.rendered();
}

INSTANTIATE_TEST_SUITE_P(Nct, BadInput, testing::ValuesIn(badFiles()), testName);

TEST(BadInputCorpus, HasAtLeastFortyCases) {
  EXPECT_GE(badFiles().size(), 40u);
}

} // namespace
} // namespace gcx::test
