// The block reader driven by lexical rules other than NCT's: the forms FMS-3000 (fms3000.md §1.1)
// and WL4 (wl4.md §1.1, §1.3, §1.6) need, each rule given alone so its effect is visible.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sstream>

#include "dialects/nct/lexical_rules.h"
#include "front/block_reader.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

struct Cut {
  V lexTexts; // one per block
  std::vector<std::size_t> lineCommentAt;
  std::vector<bool> plain;
  V diagnostics; // "line:col CODE"
};

Cut cut(const std::string& text, const front::LexicalRules& rules) {
  SourceManager sm;
  diag::Engine diags;
  std::istringstream in(text);
  front::BlockReader reader(in, sm.addBuffer("t", text), diags, rules, rules.encoding);
  Cut c;
  front::RawBlock b;
  while (reader.next(b)) {
    c.lexTexts.push_back(b.lexText);
    c.lineCommentAt.push_back(b.lineCommentAt);
    c.plain.push_back(b.plain);
  }
  for (const diag::Diagnostic& d : diags.all())
    c.diagnostics.push_back(fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code));
  return c;
}

constexpr std::size_t npos = std::string::npos;

TEST(LexicalRules, NctCommentsSpanLinesAndLettersFold) {
  const Cut c = cut("g1 x!1 (a\nb) y2\nm30\n", nct::lexicalRules());
  EXPECT_EQ(c.lexTexts, (V{"G1 X-1 (a\nb) Y2", "M30"}));
  EXPECT_EQ(c.diagnostics, V{"1:5 GCXW01"});
}

TEST(LexicalRules, BlocksOfOnlyPlainBytesAndBlocksThatNeedWorkAreToldApart) {
  // the cutter counts the bytes normalize must look at: a block without any is taken as is,
  // a single lower-case letter, CR inside the block or comment keyword still gets its rule
  front::LexicalRules r = nct::lexicalRules();
  r.commentLineKeywords = {"REM"};
  const Cut c = cut("G1 X1\r\nG1 x1\r\nG1\rX1\nREM X1\nG1 (A) X1\n", r);
  EXPECT_EQ(c.lexTexts, (V{"G1 X1", "G1 X1", "G1 X1", "REM X1", "G1 (A) X1"}));
  EXPECT_EQ(c.plain, (std::vector<bool>{true, true, true, true, true}));
  EXPECT_EQ(c.lineCommentAt, (std::vector<std::size_t>{npos, npos, npos, 0, npos}));
  EXPECT_EQ(c.diagnostics, V{"3:3 GCXW04"});
}

TEST(LexicalRules, WithoutBracketCommentsAParenthesisIsText) {
  // WL4: `(` is a bracket of expressions; a LF inside it ends the block (wl4.md §1.6)
  front::LexicalRules r;
  const Cut c = cut("G1 X(1\nY2)\n", r);
  EXPECT_EQ(c.lexTexts, (V{"G1 X(1", "Y2)"}));
  EXPECT_EQ(c.diagnostics, V{});
}

TEST(LexicalRules, BracketCommentThatDoesNotSpanLinesEndsWithTheLine) {
  front::LexicalRules r;
  r.bracketComment = front::BracketComment{'(', ')', false};
  const Cut c = cut("G1 (open\nG2\n", r);
  EXPECT_EQ(c.lexTexts, (V{"G1 (open", "G2"}));
}

TEST(LexicalRules, LineCommentMarkerTakesTheRestOfTheLine) {
  // WL4 `$`: the rest of the line is comment, even a `(` that would open a spanning comment
  front::LexicalRules r = nct::lexicalRules();
  r.lineCommentMarkers = "$";
  const Cut c = cut("g1 x1 $ rest (not closed\n$ whole line\ng2\n", r);
  EXPECT_EQ(c.lexTexts, (V{"G1 X1 $ rest (not closed", "$ whole line", "G2"}));
  EXPECT_EQ(c.lineCommentAt, (std::vector<std::size_t>{6, 0, npos}));
  EXPECT_EQ(c.diagnostics, V{});
}

TEST(LexicalRules, CommentLineKeywordMakesTheLineAComment) {
  // FMS-3000 `rem` first on a line (fms3000.md §1.1); not inside a word, not later in the line
  front::LexicalRules r;
  r.letterCase = front::LetterCase::Keep;
  r.commentLineKeywords = {"rem"};
  const Cut c = cut("  rem G1 (x\nremark\nG1 rem\nrem\n", r);
  EXPECT_EQ(c.lineCommentAt, (std::vector<std::size_t>{2, npos, npos, 0}));
}

TEST(LexicalRules, LetterCaseKeepLeavesLowerCase) {
  front::LexicalRules r;
  r.letterCase = front::LetterCase::Keep;
  EXPECT_EQ(cut("g1 x1\n", r).lexTexts, V{"g1 x1"});
}

TEST(LexicalRules, LowerCaseOutsideCommentsIsAnErrorWhereTheDialectSaysSo) {
  // WL4: lower case only inside comments (wl4.md §1.1)
  front::LexicalRules r;
  r.letterCase = front::LetterCase::ErrorOutsideComments;
  r.lineCommentMarkers = "$";
  EXPECT_EQ(cut("G1 X1 $ lower case\n", r).diagnostics, V{});
  EXPECT_EQ(cut("G1 x1 $ lower case\nG1 Xy\n", r).diagnostics, (V{"1:4 2064", "2:5 2064"}));
}

TEST(LexicalRules, LowerCaseKeywordsStayAsWritten) {
  // FMS-3000 `endcont` is typed in small letters (fms3000.md §1.1)
  front::LexicalRules r;
  r.lowerCaseKeywords = {"endcont"};
  EXPECT_EQ(cut("endcont x1\nendcontx g1\nxendcont\n", r).lexTexts,
            (V{"endcont X1", "ENDCONTX G1", "XENDCONT"}));
  r.letterCase = front::LetterCase::ErrorOutsideComments;
  EXPECT_EQ(cut("endcont\nendcont x\n", r).diagnostics, V{"2:9 2064"});
}

TEST(LexicalRules, SignAliasesComeFromTheRules) {
  front::LexicalRules r;
  Cut c = cut("X!1 X\u22122\n", r);
  EXPECT_EQ(c.lexTexts, V{"X!1 X   2"});
  EXPECT_EQ(c.diagnostics, V{"1:6 2064"}); // U+2212 is no character of this dialect
  r.signAliases = {{U'!', '-', ""}, {U'\u2212', '-', ""}};
  c = cut("X!1 X\u22122\n", r);
  EXPECT_EQ(c.lexTexts, V{"X-1 X-  2"});
  EXPECT_EQ(c.diagnostics, (V{"1:2 GCXW01", "1:6 GCXW01"}));
}

TEST(LexicalRules, DialectBlockLengthLimitCountsCharacters) {
  // FMS-3000: at most 254 characters with CR LF; the line itself is counted, CR LF not
  front::LexicalRules r;
  r.bracketComment = front::BracketComment{};
  r.maxBlockChars = 10;
  const std::string cyrillic10 = "(\u0416\u0416\u0416\u0416\u0416\u0416\u0416\u0416)"; // 18 bytes
  EXPECT_EQ(cut("G1 X1 Y2 Z\r\n" + cyrillic10 + "\n", r).diagnostics, V{});
  const Cut c = cut("G1 X1 Y2 Z3\r\nG2\n", r);
  EXPECT_EQ(c.diagnostics, V{"1:1 GCX005"});
  EXPECT_EQ(c.lexTexts.size(), 2u); // the long block is reported as failed
}

TEST(LexicalRules, DialectBlockLengthWarning) {
  // WL4: 80 characters, a warning only (wl4.md §1.3)
  front::LexicalRules r;
  r.warnBlockChars = 5;
  const Cut c = cut("G1 X1\nG1 X10\n", r);
  EXPECT_EQ(c.diagnostics, V{"2:1 GCXW05"});
  EXPECT_EQ(c.lexTexts, (V{"G1 X1", "G1 X10"}));
}

} // namespace
} // namespace gcx::test
