// front::decimalValue: the value of a decimal literal, equal to std::from_chars's correctly
// rounded double on every text, by its fast path or its fallback.
#include "front/decimal_text.h"

#include <charconv>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

#ifdef GCX_HAVE_RAPIDCHECK
#include <rapidcheck/gtest.h>
#endif

namespace gcx::front {
namespace {

double reference(const std::string& digits) {
  const std::string text = !digits.empty() && digits.front() == '.' ? "0" + digits : digits;
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

TEST(DecimalText, ShortNumbers) {
  EXPECT_EQ(decimalValue("12"), 12.0);
  EXPECT_EQ(decimalValue("12."), 12.0);
  EXPECT_EQ(decimalValue(".5"), 0.5);
  EXPECT_EQ(decimalValue("0.1"), 0.1);
  EXPECT_EQ(decimalValue("99.250"), 99.25);
  EXPECT_EQ(decimalValue("0007"), 7.0);
  EXPECT_EQ(decimalValue(""), 0.0);
  EXPECT_EQ(decimalValue("."), 0.0);
}

TEST(DecimalText, BeyondTheFastPathStillExact) {
  // a mantissa of 2^53 and more, or more than 22 decimals, takes the fallback
  for (const std::string d : {"9007199254740993", "123456789012345678901234567890",
                              "0.00000000000000000000001", "1.0000000000000000000000000001",
                              "179769313486231570000000000000000000000000000000000000000000000",
                              "0.1000000000000000055511151231257827021181583404541015625"})
    EXPECT_EQ(decimalValue(d), reference(d)) << d;
}

TEST(DecimalText, BeyondADoubleIsInfiniteTooSmallIsZero) {
  EXPECT_EQ(decimalValue(std::string(400, '9')), HUGE_VAL);
  EXPECT_EQ(decimalValue(std::string(400, '9') + ".5"), HUGE_VAL);
  EXPECT_EQ(decimalValue("0." + std::string(400, '0') + "1"), 0.0);
}

#ifdef GCX_HAVE_RAPIDCHECK
RC_GTEST_PROP(DecimalText, EqualsFromChars, ()) {
  const auto whole = *rc::gen::container<std::string>(
      *rc::gen::inRange(0, 25), rc::gen::inRange('0', static_cast<char>('9' + 1)));
  const auto fraction = *rc::gen::container<std::string>(
      *rc::gen::inRange(0, 30), rc::gen::inRange('0', static_cast<char>('9' + 1)));
  const bool point = *rc::gen::arbitrary<bool>();
  const std::string digits = point ? whole + "." + fraction : whole + fraction;
  RC_ASSERT(decimalValue(digits) == reference(digits));
}
#endif

} // namespace
} // namespace gcx::front
