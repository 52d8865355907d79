// The sixteen-byte skip over plain text (front/plain_run.h) that the block reader starts with.
#include <gtest/gtest.h>

#include <string>

#include "front/plain_run.h"

namespace gcx::front {
namespace {

std::size_t endOf(const std::string& text, std::size_t from = 0) {
  return plainRunEnd(reinterpret_cast<const unsigned char*>(text.data()), from, text.size());
}

TEST(PlainRun, PlainBytesAreUpperCaseLettersDigitsBlankAndPlusMinusDotSlash) {
  std::string plain;
  for (unsigned c = 0; c < 256; ++c)
    if (isRunPlain(static_cast<unsigned char>(c))) plain += static_cast<char>(c);
  EXPECT_EQ(plain, " +-./0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ");
}

TEST(PlainRun, StopsAtTheFirstByteThatIsNotPlainWhereverItStands) {
  if constexpr (!kPlainRunsBySimd) GTEST_SKIP() << "without SSE2 nothing is skipped";
  for (unsigned c = 0; c < 256; ++c) {
    const auto byte = static_cast<char>(c);
    for (std::size_t at = 0; at < 32; ++at) {
      std::string text(40, 'G');
      text[at] = byte;
      const std::size_t expected = isRunPlain(static_cast<unsigned char>(c)) ? 32 : at;
      ASSERT_EQ(endOf(text), expected) << "byte " << c << " at " << at;
    }
  }
}

TEST(PlainRun, LeavesTheLastFifteenBytesToTheCaller) {
  if constexpr (!kPlainRunsBySimd) GTEST_SKIP() << "without SSE2 nothing is skipped";
  EXPECT_EQ(endOf("G1 X99.250 Y0.000 F1200\n"), 16u);         // 24 bytes: one block of 16
  EXPECT_EQ(endOf("G1 X1\n"), 0u);                            // too short to look at
  EXPECT_EQ(endOf("G1 X99.250 Y0.000 F1200\n", 10), 10u);     // 14 bytes left
  EXPECT_EQ(endOf("#1=2 G1 X1 Y2 Z3 F400\n"), 0u);            // '#' first
  EXPECT_EQ(endOf("G1 X1 Y2 Z3 (CUT) F400 S1000 M3\n"), 12u); // the comment's '('
  EXPECT_EQ(endOf("G1 X1 Y2 z3 F400 S1000 M3 T1 D1\n"), 9u);  // lower case
}

} // namespace
} // namespace gcx::front
