// FMS-3000 malformed inputs: each file's sidecar .expect names the first error (LINE:COL CODE),
// as gcx check reports it.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

std::vector<fs::path> badFiles() {
  return filesUnder(sourceDir() / "tests" / "corpus" / "fms3000" / "bad", {".fms"});
}

class Fms3000BadInput : public testing::TestWithParam<fs::path> {};

TEST_P(Fms3000BadInput, FirstErrorHasTheExpectedCodeAndLocation) {
  fs::path expectFile = GetParam();
  expectFile.replace_extension(".expect");
  std::string expected = readFile(expectFile);
  while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r'))
    expected.pop_back();
  const Parsed p = parseFms(readFile(GetParam()));
  const auto errors = p.errors();
  ASSERT_FALSE(errors.empty()) << "no error reported for " << GetParam();
  EXPECT_EQ(errors.front(), expected) << p.rendered();
}

INSTANTIATE_TEST_SUITE_P(Corpus, Fms3000BadInput, testing::ValuesIn(badFiles()),
                         [](const testing::TestParamInfo<fs::path>& file) {
                           return file.param.stem().string();
                         });

TEST(Fms3000BadInputCorpus, HasAtLeastThirtyCases) {
  EXPECT_GE(badFiles().size(), 30u);
}

} // namespace
} // namespace gcx::test
