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

TEST(BlockWords, ClearForgetsEveryWord) {
  // a block that fills every member of BlockWords, then one with no words
  const Parsed p = parseNct("G1 G17 X1 Y2 Z3 U4 V5 W6 A7 B8 C9 I1 J2 K3 R4 F5 S6 T7 H8 D9 P1 Q2 "
                            "L3 E4 M3 ,C1 ,R2 ,A3 AX[1]=5\nN5\n",
                            {.staticChecks = false});
  ASSERT_EQ(p.blocks.size(), 2u) << p.rendered();
  machine::ReusedBlockWords reused;
  machine::BlockWords& w = reused.words();
  ASSERT_EQ(machine::sortWords(p.blocks[0], nct::profile(), w), nullptr);
  auto pointers = [](const machine::BlockWords& b) {
    std::vector<const ir::Word*> all{b.r, b.f, b.s, b.t,       b.h,        b.d,    b.p,
                                     b.q, b.l, b.e, b.chamfer, b.rounding, b.angle};
    for (const auto* list : {&b.axis, &b.uvw, &b.ijk})
      all.insert(all.end(), list->begin(), list->end());
    all.insert(all.end(), b.extra.begin(), b.extra.end());
    all.insert(all.end(), b.letters.begin(), b.letters.end());
    return all;
  };
  const std::vector<const ir::Word*> filled = pointers(w);
  // left empty: the letters N and O, and U V W either as incremental X Y Z or as axes of their own
  EXPECT_EQ(std::count(filled.begin(), filled.end(), nullptr), 5);
  EXPECT_FALSE(w.other.empty());
  EXPECT_NE(w.actionBits, (std::array<std::uint64_t, 4>{}));
  ASSERT_EQ(machine::sortWords(p.blocks[1], nct::profile(), w), nullptr);
  const std::vector<const ir::Word*> cleared = pointers(w);
  EXPECT_EQ(std::count(cleared.begin(), cleared.end(), nullptr),
            static_cast<std::ptrdiff_t>(cleared.size()));
  EXPECT_TRUE(w.gWords.empty() && w.gCodes.empty() && w.m.empty() && w.other.empty());
  EXPECT_EQ(w.actionBits, (std::array<std::uint64_t, 4>{}));
}

} // namespace
} // namespace gcx::test
