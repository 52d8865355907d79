// ir::copyShort and ir::assignShort (ir/short_text.h): every length from 0 to 16 copies exactly
// its bytes, and touches none beyond them.
#include <gtest/gtest.h>

#include <string>

#include "ir/short_text.h"

namespace gcx::test {
namespace {

TEST(ShortText, EveryLengthCopiesItsBytesAndNoMore) {
  const std::string from = "0123456789abcdefXYZ";
  for (std::size_t n = 0; n <= 16; ++n) {
    std::string to(20, '.');
    ir::copyShort(to.data() + 2, from.data(), n);
    EXPECT_EQ(to, ".." + from.substr(0, n) + std::string(18 - n, '.')) << "length " << n;
  }
}

TEST(ShortText, AssignSetsTheLengthAndTheText) {
  std::string to = "-40.5";
  for (const std::string text : {"12.25", "7", "-1234.5678", "", "0000000000000012"}) {
    ir::assignShort(to, text.data(), text.size());
    EXPECT_EQ(to, text);
  }
}

} // namespace
} // namespace gcx::test
