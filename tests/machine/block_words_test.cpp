// The interpreter's sorted words of a block (machine/block_words.h), kept between blocks by
// ReusedBlockWords: a block run inside another gets words of its own, and sorting a block
// leaves nothing of the one sorted before.
#include <gtest/gtest.h>

#include "dialects/nct/profile.h"
#include "machine/reused_block_words.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

TEST(BlockWords, ABlockRunInsideAnotherSortsIntoWordsOfItsOwn) {
  const Parsed p = parseNct("G1 G17 M3 M8 X1\nY2\n");
  ASSERT_EQ(p.blocks.size(), 2u) << p.rendered();
  machine::ReusedBlockWords outer;
  ASSERT_EQ(machine::sortWords(p.blocks[0], nct::profile(), outer.words()), nullptr);
  const machine::BlockWords* inner = nullptr;
  {
    machine::ReusedBlockWords nested;
    inner = &nested.words();
    EXPECT_NE(inner, &outer.words());
    ASSERT_EQ(machine::sortWords(p.blocks[1], nct::profile(), nested.words()), nullptr);
    EXPECT_EQ(nested.words().axis[1], &p.blocks[1].words[0]);
  }
  const machine::BlockWords& w = outer.words();
  ASSERT_EQ(w.gWords.size(), 2u);
  EXPECT_EQ(w.gWords[1]->number, 17);
  ASSERT_EQ(w.m.size(), 2u);
  EXPECT_EQ(w.axis[0], &p.blocks[0].words[4]);
  // the nested one is free again: the next block inside takes the same words
  machine::ReusedBlockWords again;
  EXPECT_EQ(&again.words(), inner);
}

TEST(BlockWords, SortingABlockForgetsTheBlockSortedBefore) {
  const Parsed p = parseNct("G1 G17 M3 X1 F100\nY2\n");
  ASSERT_EQ(p.blocks.size(), 2u) << p.rendered();
  machine::ReusedBlockWords reused;
  machine::BlockWords& w = reused.words();
  ASSERT_EQ(machine::sortWords(p.blocks[0], nct::profile(), w), nullptr);
  EXPECT_TRUE(w.has(GAction::PlaneXY));
  ASSERT_EQ(machine::sortWords(p.blocks[1], nct::profile(), w), nullptr);
  EXPECT_TRUE(w.gWords.empty());
  EXPECT_TRUE(w.gCodes.empty());
  EXPECT_TRUE(w.m.empty());
  EXPECT_TRUE(w.other.empty());
  EXPECT_FALSE(w.has(GAction::PlaneXY));
  EXPECT_EQ(w.axis[0], nullptr);
  EXPECT_EQ(w.f, nullptr);
  EXPECT_EQ(w.letter('X'), nullptr);
  EXPECT_EQ(w.axis[1], &p.blocks[1].words[0]);
}

} // namespace
} // namespace gcx::test
