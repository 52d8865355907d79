// Expression nesting is bounded before the grammar recurses (GCX017): deep input gets a located
// error instead of exhausting the stack, at the column where the 65th level opens.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace gcx::test {
namespace {

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i)
    out += s;
  return out;
}

TEST(NestingDepth, SixtyFourBracketsParse) {
  const Parsed p = parseNct("#1=" + repeat("[", 64) + "1" + repeat("]", 64) + "\nM30\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
}

TEST(NestingDepth, FiveThousandBracketsStopAtTheSixtyFifth) {
  const Parsed p = parseNct("#1=" + repeat("[", 5000) + "1" + repeat("]", 5000) + "\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "1:68 GCX017") << p.rendered();
}

TEST(NestingDepth, HundredThousandUnaryMinusSigns) {
  const Parsed p = parseNct("#1=" + repeat("-", 100000) + "1\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "1:68 GCX017") << p.rendered();
}

TEST(NestingDepth, NestedSinCountsTheFunctionAndItsBracket) {
  // SIN[ is two levels: the function, then its bracket
  const Parsed p = parseNct("#1=" + repeat("SIN[", 5000) + "1" + repeat("]", 5000) + "\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "1:132 GCX017") << p.rendered();
}

TEST(NestingDepth, FunctionsWithoutBracketsCount) {
  const Parsed p = parseNct("#1=" + repeat("ABS", 10000) + "1\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "1:196 GCX017") << p.rendered();
}

TEST(NestingDepth, SignsInsideBracketsAddUp) {
  // each "-[" is two levels: inside the outer bracket the 32nd pair's bracket is the 65th
  const Parsed ok = parseNct("G0 X" + repeat("-[", 31) + "1" + repeat("]", 31) + "\nM30\n");
  EXPECT_TRUE(ok.errors().empty()) << ok.rendered();
  const Parsed p = parseNct("G0 X[" + repeat("-[", 40) + "1" + repeat("]", 41) + "\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "1:69 GCX017") << p.rendered();
}

TEST(NestingDepth, LongFlatExpressionIsNotDeep) {
  // a sum of 10 000 terms recurses once per term at most: no nesting error
  const Parsed p = parseNct("#1=1" + repeat("+[1]", 10000) + "\nM30\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
}

TEST(NestingDepth, EveryBlockIsChecked) {
  const Parsed p =
      parseNct("G0 X1\nIF[" + repeat("[", 70) + "1" + repeat("]", 70) + "EQ1]GOTO5\nM30\n");
  ASSERT_FALSE(p.errors().empty());
  EXPECT_EQ(p.errors().front(), "2:67 GCX017") << p.rendered();
}

} // namespace
} // namespace gcx::test
