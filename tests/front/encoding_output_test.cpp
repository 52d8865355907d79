// Text written in a dialect's encoding (front/encoding_output.h): UTF-8 converted on the way
// out, a character the encoding lacks refused with its line, a sequence cut at a chunk's end
// joined with its rest.
#include <gtest/gtest.h>

#include <sstream>

#include "front/encoding_output.h"

namespace gcx::test {
namespace {

using front::Encoding;

const std::string kUtf8Word = "\u041F\u0420\u0418\u0412\u0415\u0422"; // ПРИВЕТ
const std::string kKoi8Word = "\xF0\xF2\xE9\xF7\xE5\xF4";
const std::string kCp1251Word = "\xCF\xD0\xC8\xC2\xC5\xD2";

TEST(EncodingOutput, Utf8IsConvertedToTheEncoding) {
  std::string why;
  EXPECT_EQ(front::encodeText("$ " + kUtf8Word + "\n", Encoding::Koi8R, why),
            "$ " + kKoi8Word + "\n");
  EXPECT_EQ(front::encodeText("(" + kUtf8Word + ")", Encoding::Cp1251, why),
            "(" + kCp1251Word + ")");
  EXPECT_EQ(front::encodeText("(" + kUtf8Word + ")", Encoding::Utf8, why), "(" + kUtf8Word + ")");
  EXPECT_EQ(why, "");
}

TEST(EncodingOutput, ACharacterTheEncodingLacksIsRefusedWithItsLine) {
  std::string why;
  EXPECT_EQ(front::encodeText("G0 X1\n$ 5 \u20AC\n", Encoding::Koi8R, why), std::nullopt);
  EXPECT_EQ(why, "line 2 holds U+20AC, which koi8-r has no code for");
}

// The stream hands the converter 64 KB at a time: a two-byte letter split by that boundary is
// converted whole.
TEST(EncodingOutput, ALetterCutAtAChunksEndIsConvertedWhole) {
  const std::string text = std::string((1 << 16) - 1, 'A') + kUtf8Word + "\n";
  std::ostringstream out;
  front::EncodingOutput enc(out, Encoding::Koi8R);
  std::ostream in(&enc);
  for (char c : text)
    in.put(c);
  ASSERT_TRUE(enc.finish()) << enc.error();
  EXPECT_EQ(out.str(), std::string((1 << 16) - 1, 'A') + kKoi8Word + "\n");
}

} // namespace
} // namespace gcx::test
