// The cache of each letter's last word text: a hit only for the same letter and the same bits.
#include "emit/repeated_words.h"

#include <gtest/gtest.h>
#include <string>

namespace gcx::emit {
namespace {

// Stores the word as putWord writes it, as the canonical emitter does.
void storeWord(RepeatedWords& words, char letter, double v) {
  char text[motion::kWordRoom] = {};
  char* end = motion::putWord(text, letter, v);
  ASSERT_NE(end, nullptr);
  words.store(letter, v, text, end);
}

// The repeated text, or "(none)".
std::string repeated(const RepeatedWords& words, char letter, double v) {
  char to[motion::kWordRoom];
  const char* end = words.repeat(to, letter, v);
  return end ? std::string(static_cast<const char*>(to), end) : "(none)";
}

TEST(RepeatedWords, NothingBeforeTheFirstStore) {
  const RepeatedWords words;
  EXPECT_EQ(repeated(words, 'X', 0), "(none)");
  EXPECT_EQ(repeated(words, 'A', 0), "(none)");
}

TEST(RepeatedWords, TheSameLetterAndNumberCopyTheText) {
  RepeatedWords words;
  storeWord(words, 'Z', -1.25);
  storeWord(words, 'F', 1200);
  EXPECT_EQ(repeated(words, 'Z', -1.25), " Z-1.25");
  EXPECT_EQ(repeated(words, 'F', 1200), " F1200");
}

TEST(RepeatedWords, AnotherNumberIsNotRepeated) {
  RepeatedWords words;
  storeWord(words, 'X', 99.25);
  EXPECT_EQ(repeated(words, 'X', 99.5), "(none)");
  EXPECT_EQ(repeated(words, 'X', 99.250000001), "(none)"); // the bits differ, the text may not
  storeWord(words, 'X', 99.5);                             // the last store is the one kept
  EXPECT_EQ(repeated(words, 'X', 99.25), "(none)");
  EXPECT_EQ(repeated(words, 'X', 99.5), " X99.5");
}

TEST(RepeatedWords, AnotherLetterIsNotRepeated) {
  RepeatedWords words;
  storeWord(words, 'Y', 3);
  EXPECT_EQ(repeated(words, 'Z', 3), "(none)");
  EXPECT_EQ(repeated(words, 'y', 3), "(none)"); // 'y' shares Y's entry: the letter is compared
}

TEST(RepeatedWords, NegativeZeroIsItsOwnNumber) {
  RepeatedWords words;
  storeWord(words, 'Z', -0.0);
  EXPECT_EQ(repeated(words, 'Z', 0.0), "(none)");
  EXPECT_EQ(repeated(words, 'Z', -0.0), " Z0");
}

} // namespace
} // namespace gcx::emit
