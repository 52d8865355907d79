// wl4.md §6.1: a variable's value used as an address is converted to the address's type —
// integer addresses round half away from zero, dimension words and F E P R to 0.001 — while the
// variables themselves keep binary64 (002:1799-1803).
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4Spec_6_1, VariableValuesRoundToTheAddressType) {
  MacroRun r = runWl4({{"main.wl4", "%R\n#1=10.0004 #2=0.6 #3=90.4 #4=99.9996\n"
                                    "G#3 G#2 X#1 Y(#1+0.0006) F#4\nM2\n%\n"}},
                      "main.wl4", {}, {1});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,10.001,0 F100", "END"}));
  EXPECT_DOUBLE_EQ(r.vars[1].number, 10.0004); // the variable itself is not rounded
}

TEST(Wl4Spec_6_1, TiesRoundAwayFromZero) { // 62.5 and 0.5 are exact halves in binary64
  MacroRun r = runWl4("%R\n#1=-0.0625 #2=0.5\nG90 G#2 X#1 F100\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L -0.063,0,0 F100", "END"}));
}

} // namespace
} // namespace gcx::test
