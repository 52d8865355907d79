// motion::appendDecimal prints through an integer fast path where it can prove the text equal to
// std::to_chars' correctly rounded one; these tests hold the two paths to the same bytes.
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <random>

#include "motion/decimal.h"

namespace gcx::motion {
namespace {

std::string fast(double v, int decimals) {
  std::string s;
  appendDecimal(s, v, decimals);
  return s;
}

std::string exact(double v, int decimals) {
  std::string s;
  appendDecimalExact(s, v, decimals);
  return s;
}

TEST(Decimal, TypicalValues) {
  EXPECT_EQ(fast(0, 6), "0");
  EXPECT_EQ(fast(-0.0, 6), "0");
  EXPECT_EQ(fast(1, 6), "1");
  EXPECT_EQ(fast(-1.5, 6), "-1.5");
  EXPECT_EQ(fast(99.25, 6), "99.25");
  EXPECT_EQ(fast(0.1, 6), "0.1");
  EXPECT_EQ(fast(1.0 / 3.0, 6), "0.333333");
  EXPECT_EQ(fast(2.0 / 3.0, 6), "0.666667");
  EXPECT_EQ(fast(-2.0 / 3.0, 3), "-0.667");
  EXPECT_EQ(fast(-4e-7, 6), "0"); // rounds to zero: no "-0"
  EXPECT_EQ(fast(-6e-7, 6), "-0.000001");
  EXPECT_EQ(fast(123456.7, 0), "123457");
  EXPECT_EQ(fast(1200, 6), "1200");
  EXPECT_EQ(fast(1e15, 6), "1000000000000000"); // beyond the fast path
  EXPECT_EQ(fast(NAN, 6), "null");
  EXPECT_EQ(fast(INFINITY, 6), "null");
}

TEST(Decimal, NearHalfFallsBackToExactRounding) {
  // 0.0000005 is stored slightly below the half, 2.5e-6 exactly representable halves are rare:
  // whichever way the binary value lies, the text must be to_chars' correctly rounded one.
  for (double v : {5e-7, 1.5e-6, 2.5e-6, 0.1234565, 1.0000005, -0.0000015, 1234.5675})
    for (int d = 0; d <= 9; ++d)
      EXPECT_EQ(fast(v, d), exact(v, d)) << v << " at " << d << " decimals";
}

TEST(Decimal, FastPathEqualsToCharsOnRandomValues) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-9, 13), decimals(0, 12);
  for (int i = 0; i < 300000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    const int d = decimals(rng);
    ASSERT_EQ(fast(v, d), exact(v, d)) << v << " at " << d << " decimals";
  }
}

TEST(Decimal, FastPathEqualsToCharsOnGridValues) {
  // CAM output: values written with three or four decimals, and sums of them
  for (std::int64_t k = -200000; k <= 200000; k += 7) {
    const double v = static_cast<double>(k) / 1000.0;
    ASSERT_EQ(fast(v, 6), exact(v, 6)) << v;
    ASSERT_EQ(fast(v * 0.1 + 0.0005, 6), exact(v * 0.1 + 0.0005, 6)) << v;
  }
}

TEST(Decimal, WordIsBlankLetterAndTheNumbersText) {
  auto word = [](char letter, double v, int d) {
    std::string s = "G1";
    appendWord(s, letter, v, d);
    return s;
  };
  EXPECT_EQ(word('X', -1.5, 6), "G1 X-1.5");
  EXPECT_EQ(word('Y', 0.0000004, 6), "G1 Y0");
  EXPECT_EQ(word('Z', 99.25, 3), "G1 Z99.25");
  EXPECT_EQ(word('F', 1e13, 6), "G1 F10000000000000"); // beyond the integer path
  EXPECT_EQ(word('X', std::nan(""), 6), "G1 Xnull");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> value(-1000.0, 1000.0);
  for (int i = 0; i < 20000; ++i) {
    const double v = value(rng);
    ASSERT_EQ(word('X', v, 6), "G1 X" + fast(v, 6)) << v;
  }
}

} // namespace
} // namespace gcx::motion
