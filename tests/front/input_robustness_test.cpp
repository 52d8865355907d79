// Inputs that are not programs at all: located errors, no crash, no hang.
#include <gtest/gtest.h>

#include "support/test_support.h"

namespace gcx::test {
namespace {

TEST(InputRobustness, EmptyFileIsAnEmptyProgram) {
  Parsed p = parseNct("");
  EXPECT_EQ(p.errors(), std::vector<std::string>{"1:1 GCX002"});
}

TEST(InputRobustness, BlankLinesOnlyIsAnEmptyProgram) {
  Parsed p = parseNct("\n  \n\t\r\n");
  EXPECT_EQ(p.errors(), std::vector<std::string>{"1:1 GCX002"});
}

TEST(InputRobustness, LonePercentIsAnEmptyProgram) {
  Parsed p = parseNct("%\n");
  EXPECT_EQ(p.errors(), std::vector<std::string>{"1:1 GCX002"});
}

// Found by the fmt_nct fuzz target: such a line was an empty block, which `fmt` printed as a
// blank line, so the printed program had one block less.
TEST(InputRobustness, LineOfOnlyAStrayParenIsABlankLine) {
  Parsed p = parseNct("G0 X1\n)\nM30\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.warnings(), std::vector<std::string>{"2:1 GCXW03"});
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[1].range.begin.line, 3u);
}

TEST(InputRobustness, LineOfOnlyAByteOrderMarkIsABlankLine) {
  Parsed p = parseNct("\xEF\xBB\xBF\nG0 X1\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_EQ(p.blocks[0].range.begin.line, 2u);
}

TEST(InputRobustness, NulByteIsABinaryFile) {
  std::string text = "G0 X1\nG1 X2";
  text += '\0';
  text += "\x01\x02garbage\n";
  Parsed p = parseNct(text);
  EXPECT_EQ(p.errors(), std::vector<std::string>{"2:6 GCX003"});
}

TEST(InputRobustness, InvalidUtf8IsLocated) {
  Parsed p = parseNct("G0 X1\n(comment \xC3\x28 bad)\n");
  EXPECT_EQ(p.errors(), std::vector<std::string>{"2:10 GCX004"});
}

TEST(InputRobustness, CrOfACrLfIsNotPartOfTheBlock) {
  // nct.md §1.1: CR LF ends a line like LF; the block's range (diagnostics, --json) stops
  // before the CR
  Parsed p = parseNct("G2 X10 Y10 F100\r\nM30\r\n");
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].range.length, 15u);
  EXPECT_EQ(p.blocks[1].range.length, 3u);
}

TEST(InputRobustness, LoneCrInsideACrLfLineIsWarned) {
  // nct.md §1.1: blocks end at LF; a CR not followed by LF is reported where it stands (1:6),
  // even when the line itself ends with CR LF, whose CR is no part of the block
  Parsed p = parseNct("G0 X1\rY2\r\nM30\r\n");
  EXPECT_EQ(p.warnings(), std::vector<std::string>{"1:6 GCXW04"});
}

TEST(InputRobustness, Utf8InCommentsIsAccepted) {
  Parsed p = parseNct("G0 X1 (\xD1\x84\xD1\x80\xD0\xB5\xD0\xB7\xD0\xB0)\nM30\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].comments.at(0).text, "\xD1\x84\xD1\x80\xD0\xB5\xD0\xB7\xD0\xB0");
}

TEST(InputRobustness, TenMegabyteLineIsReportedAndSkipped) {
  std::string text = "G0 X1\nG1";
  text.append(10u << 20, ' ');
  text += "X2\nG1 X3\nM30\n";
  Parsed p = parseNct(text);
  EXPECT_EQ(p.errors(), std::vector<std::string>{"2:1 GCX005"});
  ASSERT_EQ(p.blocks.size(), 3u); // the blocks around it survive
  EXPECT_EQ(p.blocks[1].words.at(1).number, 3);
}

TEST(InputRobustness, TenMegabyteCommentLineIsFine) {
  std::string text = "G0 X1 (";
  text.append(10u << 20, 'a'); // longer than a block may be
  text += ")\nM30\n";
  Parsed p = parseNct(text);
  EXPECT_EQ(p.errors(), std::vector<std::string>{"1:1 GCX005"});
}

TEST(InputRobustness, UnterminatedCommentPointsAtTheParenthesis) {
  Parsed p = parseNct("G0 X1\nG1 X2 (no end\nG1 X3\nM30\n");
  EXPECT_EQ(p.errors(), std::vector<std::string>{"2:7 GCX006"});
}

TEST(InputRobustness, RandomBytesNeverCrash) {
  std::uint64_t state = 12345;
  auto next = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state;
  };
  const std::string alphabet = "GXYZIJKNM#[]()=+-*/.,<>%0123456789 \nIFGOTOWHILEDOEND";
  for (int round = 0; round < 2000; ++round) {
    std::string text;
    const std::size_t len = next() % 60;
    for (std::size_t i = 0; i < len; ++i)
      text += alphabet[next() % alphabet.size()];
    Parsed p = parseNct(text); // must return, with or without errors
    for (const auto& d : p.diags.all())
      if (d.severity == diag::Severity::Error) {
        EXPECT_TRUE(d.range.begin.valid()) << text;
      }
  }
}

} // namespace
} // namespace gcx::test
