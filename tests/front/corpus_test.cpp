// Every example and every transcribed spec test vector parses without error, prints back with
// `fmt` to the same IR, and parses identically with and without the fast path.
#include <gtest/gtest.h>

#include "dialects/nct/printer.h"
#include "ir/dump.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

std::vector<fs::path> corpus() {
  std::vector<fs::path> all = filesUnder(sourceDir() / "examples" / "nct", {".nct"});
  for (auto& p : filesUnder(sourceDir() / "tests" / "corpus" / "nct" / "spec", {".nct", ".prg"}))
    all.push_back(p);
  return all;
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  std::string rel = fs::relative(info.param, sourceDir()).string();
  for (char& c : rel)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return rel;
}

class Corpus : public testing::TestWithParam<fs::path> {};

TEST_P(Corpus, ParsesWithoutError) {
  Parsed p = parseNctFile(GetParam());
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_FALSE(p.blocks.empty());
}

TEST_P(Corpus, RoundTripThroughFmtGivesTheSameIr) {
  Parsed first = parseNctFile(GetParam());
  ASSERT_TRUE(first.errors().empty()) << first.rendered();
  std::string printed;
  for (const ir::Block& b : first.blocks)
    printed += nct::printBlock(b) + "\n";
  Parsed second = parseNct(printed);
  ASSERT_TRUE(second.errors().empty()) << second.rendered() << "\n--- printed:\n" << printed;
  ASSERT_EQ(first.blocks.size(), second.blocks.size()) << printed;
  for (std::size_t i = 0; i < first.blocks.size(); ++i)
    EXPECT_EQ(ir::toJson(first.blocks[i], false).dump(), ir::toJson(second.blocks[i], false).dump())
        << "block " << i << ": " << nct::printBlock(first.blocks[i]);
}

TEST_P(Corpus, FastPathYieldsTheGrammarsIr) {
  Parsed fast = parseNctFile(GetParam(), {.fastPath = true});
  Parsed slow = parseNctFile(GetParam(), {.fastPath = false});
  EXPECT_EQ(fast.errors(), slow.errors());
  ASSERT_EQ(fast.blocks.size(), slow.blocks.size());
  EXPECT_EQ(slow.fastPathBlocks, 0u);
  for (std::size_t i = 0; i < fast.blocks.size(); ++i)
    EXPECT_EQ(ir::toJson(fast.blocks[i], true).dump(), ir::toJson(slow.blocks[i], true).dump());
}

INSTANTIATE_TEST_SUITE_P(Nct, Corpus, testing::ValuesIn(corpus()), testName);

TEST(CorpusSize, HoldsTheExamplesAndEverySpecVector) {
  EXPECT_GE(filesUnder(sourceDir() / "examples" / "nct", {".nct"}).size(), 10u);
  EXPECT_GE(corpus().size(), 150u);
}

} // namespace
} // namespace gcx::test
