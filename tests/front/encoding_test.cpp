// Program files in KOI8-R and CP1251 (WL4's media code, and what shops' Windows editors write):
// decoded to UTF-8 by glibc's iconv while streaming, they read as their UTF-8 twins do.
#include <gtest/gtest.h>

#include <sstream>

#include "dialect/dialect.h"
#include "ir/dump.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using front::Encoding;
using V = std::vector<std::string>;

// "ПРИВЕТ" in each encoding
const std::string kUtf8Word = "\u041F\u0420\u0418\u0412\u0415\u0422";
const std::string kKoi8Word = "\xF0\xF2\xE9\xF7\xE5\xF4";
const std::string kCp1251Word = "\xCF\xD0\xC8\xC2\xC5\xD2";

std::string program(const std::string& word) {
  return "%\nO0001 (" + word + ")\nG0 X1 Y2 (" + word + " " + word + ")\n(" + word + "\n" + word +
         ") G1 X3 F100\nM30\n%\n";
}

std::vector<std::string> irOf(const Parsed& p) {
  std::vector<std::string> out;
  for (const ir::Block& b : p.blocks)
    out.push_back(ir::toJson(b, true).dump());
  return out;
}

TEST(Encoding, Koi8rFileGivesTheIrOfItsUtf8Twin) {
  const Parsed utf8 = parseNct(program(kUtf8Word));
  const Parsed koi8 = parseNct(program(kKoi8Word), {.encoding = Encoding::Koi8R});
  ASSERT_EQ(utf8.errors(), V{});
  ASSERT_EQ(koi8.errors(), V{}) << koi8.rendered();
  ASSERT_EQ(koi8.blocks.size(), 6u);
  EXPECT_EQ(koi8.blocks[1].comments.at(0).text, kUtf8Word);
  EXPECT_EQ(koi8.blocks[2].comments.at(0).text, kUtf8Word + " " + kUtf8Word);
  EXPECT_EQ(irOf(koi8), irOf(utf8));
}

TEST(Encoding, Cp1251FileGivesTheIrOfItsUtf8Twin) {
  const Parsed utf8 = parseNct(program(kUtf8Word));
  const Parsed cp = parseNct(program(kCp1251Word), {.encoding = Encoding::Cp1251});
  ASSERT_EQ(cp.errors(), V{}) << cp.rendered();
  EXPECT_EQ(cp.blocks.at(1).comments.at(0).text, kUtf8Word);
  EXPECT_EQ(irOf(cp), irOf(utf8));
}

TEST(Encoding, Koi8rBytesReadAsUtf8AreInvalidUtf8) {
  // the same bytes without --encoding: NCT's default is UTF-8
  EXPECT_EQ(parseNct(program(kKoi8Word)).errors(), V{"2:8 GCX004"});
}

TEST(Encoding, ByteInvalidInCp1251IsALocatedError) {
  // 0x98 is unassigned in CP1251; columns count the UTF-8 text, as for a UTF-8 file (Б = 2)
  const Parsed p = parseNct("G1 X1\nG1 X2 (A\xC1\x98)\nM30\n", {.encoding = Encoding::Cp1251});
  EXPECT_EQ(p.errors(), V{"2:11 GCX008"}) << p.rendered();
  EXPECT_EQ(p.blocks.size(), 1u); // reading stops at the byte
  EXPECT_NE(p.rendered().find("byte 0x98 is not valid cp1251 text"), std::string::npos);
}

TEST(Encoding, ColumnsAfterConvertedTextCountAsInTheUtf8Twin) {
  const std::string bad = "G0 X1 (%1) X1.2.3\n(%1\n%1) Y1.2.3\n";
  auto with = [&](const std::string& word) {
    std::string t = bad;
    for (std::size_t at; (at = t.find("%1")) != std::string::npos;)
      t.replace(at, 2, word);
    return t;
  };
  const Parsed utf8 = parseNct(with(kUtf8Word));
  const Parsed koi8 = parseNct(with(kKoi8Word), {.encoding = Encoding::Koi8R});
  EXPECT_EQ(utf8.errors(), (V{"1:26 2064", "3:19 2064"})); // the second `.`
  EXPECT_EQ(koi8.errors(), utf8.errors());
}

TEST(Encoding, DiagnosticShowsTheLineOfTheConvertedFile) {
  // SourceLoc::offset stays a file offset, so the renderer finds the line in the KOI8-R bytes
  const Parsed p =
      parseNct("(" + kKoi8Word + ")\n(" + kKoi8Word + "\n" + kKoi8Word + ") X1.2.3\nG1 X1.2.3\n",
               {.encoding = Encoding::Koi8R});
  ASSERT_EQ(p.errors(), (V{"3:19 2064", "4:8 2064"}));
  const std::string text = p.rendered();
  EXPECT_NE(text.find("test.nct:4:8: error: "), std::string::npos) << text;
  EXPECT_NE(text.find("\n  G1 X1.2.3\n         ^"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  " + kKoi8Word + ") X1.2.3\n"), std::string::npos) << text;
}

TEST(Encoding, LongConvertedFileStreamsAcrossChunks) {
  // many 64 KiB chunks: line numbers and file offsets stay right across chunk ends
  std::string text;
  const int lines = 60000;
  for (int i = 1; i < lines; ++i)
    text += "G1 X" + std::to_string(i) + " (" + kKoi8Word + ")\n";
  text += "G1 X1.2.3\n";
  const Parsed p = parseNct(text, {.staticChecks = false, .encoding = Encoding::Koi8R});
  EXPECT_EQ(p.blocks.size(), static_cast<std::size_t>(lines - 1));
  EXPECT_EQ(p.errors(), V{"60000:8 2064"});
  EXPECT_NE(p.rendered().find("\n  G1 X1.2.3\n"), std::string::npos) << p.rendered();
  EXPECT_EQ(p.blocks.back().comments.at(0).text, kUtf8Word);
}

TEST(Encoding, NamesOfTheCommandLine) {
  EXPECT_EQ(front::encodingNames(), (V{"utf-8", "koi8-r", "cp1251"}));
  EXPECT_EQ(front::encodingByName("koi8-r"), Encoding::Koi8R);
  EXPECT_EQ(front::encodingByName("KOI8-R"), std::nullopt);
  EXPECT_EQ(front::encodingName(Encoding::Cp1251), "cp1251");
}

TEST(Encoding, DialectOpensInTheEncodingItIsGiven) {
  Dialect nct = *findDialect("nct");
  nct.encoding = Encoding::Cp1251;
  SourceManager sm;
  diag::Engine diags;
  const std::string text = "G1 X1 (" + kCp1251Word + ")\n";
  std::istringstream in(text);
  std::unique_ptr<BlockSource> source = nct.open(in, sm.addBuffer("t.nct", text), diags);
  ir::Block b;
  ASSERT_TRUE(source->next(b));
  EXPECT_EQ(b.comments.at(0).text, kUtf8Word);
  EXPECT_EQ(diags.errorCount(), 0u);
}

} // namespace
} // namespace gcx::test
