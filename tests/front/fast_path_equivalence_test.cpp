// The fast path must yield exactly the grammar's IR (locations included) on every block it
// accepts, and decline (so the grammar reports) every block it cannot parse.
#include <gtest/gtest.h>

#include "ir/dump.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

std::string randomBlock(std::uint64_t& state) {
  auto next = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state;
  };
  static const std::string letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  static const char* const pieces[] = {" ", "  ", "",   "-",   "+",   ".",  "I", "(c)",
                                       "/", "0",  "12", "3.5", ".25", "7.", "\t"};
  std::string b;
  if (next() % 8 == 0) b += next() % 2 ? "/" : "/3 ";
  const int words = 1 + static_cast<int>(next() % 7);
  for (int w = 0; w < words; ++w) {
    b += letters[next() % letters.size()];
    const int n = static_cast<int>(next() % 4);
    for (int k = 0; k < n; ++k)
      b += pieces[next() % (sizeof pieces / sizeof *pieces)];
    if (next() % 3) b += std::to_string(next() % 100000);
    if (next() % 4 == 0) b.append(".").append(std::to_string(next() % 1000));
    if (next() % 3) b += ' ';
  }
  return b;
}

TEST(FastPathEquivalence, GeneratedBlocksParseIdenticallyBothWays) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  std::size_t fastAccepted = 0;
  const int rounds = 20000; // 20000 files of 5 blocks = 100000 blocks
  for (int r = 0; r < rounds; ++r) {
    std::string text;
    for (int i = 0; i < 5; ++i)
      text += randomBlock(state) + "\n";
    Parsed fast = parseNct(text, {.fastPath = true, .staticChecks = false});
    Parsed slow = parseNct(text, {.fastPath = false, .staticChecks = false});
    fastAccepted += fast.fastPathBlocks;
    ASSERT_EQ(fast.errors(), slow.errors()) << text;
    ASSERT_EQ(fast.blocks.size(), slow.blocks.size()) << text;
    for (std::size_t i = 0; i < fast.blocks.size(); ++i)
      ASSERT_EQ(ir::toJson(fast.blocks[i], true).dump(), ir::toJson(slow.blocks[i], true).dump())
          << text;
  }
  EXPECT_GT(fastAccepted, static_cast<std::size_t>(rounds / 2)); // the fast path really ran
}

} // namespace
} // namespace gcx::test
