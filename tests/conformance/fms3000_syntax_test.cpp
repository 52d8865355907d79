// FMS-3000 program format (fms3000.md §1.1, §1.2, §6.3): what the front end reads, the IR it
// builds (the shapes of tests/ir/fms3000_grammar_test.cpp) and the errors it reports.
#include <gtest/gtest.h>

#include "ir/dump.h"
#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

std::string dump(const ir::Block& b) {
  return ir::toJson(b, false).dump();
}

TEST(Fms3000Syntax_1_1, CrLfAndBareLfBothEndABlock) {
  const Parsed p = parseFms("G1X1F100\r\nX2\nX3\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(printedFms(p), (V{"G1 X1 F100", "X2", "X3"}));
  EXPECT_EQ(p.blocks[2].range.begin.line, 3u);
}

TEST(Fms3000Syntax_1_1, RemLineIsACommentToTheLineEnd) {
  const Parsed p = parseFms("  rem ROUGH PROFILE (no bracket)\r\nG0X1\r\n");
  EXPECT_EQ(p.errors(), V{});
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(
      dump(p.blocks[0]),
      R"x({"comments":[{"to-line-end":"ROUGH PROFILE (no bracket)"}],"kind":"comment-line"})x");
  EXPECT_EQ(printedFms(p)[0], "rem ROUGH PROFILE (no bracket)");
}

TEST(Fms3000Syntax_1_1, RemKeepsCyrillicText) {
  const Parsed p = parseFms("rem \u0427\u0438\u0441\u0442\u043e\u0432\u043e\u0439\r\nM30\r\n");
  EXPECT_EQ(p.errors(), V{});
  ASSERT_EQ(p.blocks.size(), 2u);
  ASSERT_EQ(p.blocks[0].comments.size(), 1u);
  EXPECT_EQ(p.blocks[0].comments[0].text, "\u0427\u0438\u0441\u0442\u043e\u0432\u043e\u0439");
}

TEST(Fms3000Syntax_1_1, EndcontLineEndsTheContour) {
  const Parsed p = parseFms("endcont\r\n  endcont  \r\nM30\r\n");
  EXPECT_EQ(p.errors(), V{});
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(dump(p.blocks[0]), R"({"kind":"contour-end"})");
  EXPECT_EQ(dump(p.blocks[1]), R"({"kind":"contour-end"})");
}

TEST(Fms3000Syntax_1_1, OtherLowerCaseLinesAreTheUndocumentedMacroLanguage) {
  EXPECT_EQ(parseFms("G0X0\r\n  while 1 do\r\n").errors(), V{"2:3 FMSX01"});
  EXPECT_EQ(parseFms("remark\r\n").errors(), V{"1:1 FMSX01"});
  EXPECT_EQ(parseFms("#1=5\r\n").errors(), V{"1:1 FMSX01"}); // §8 negative vector
  EXPECT_EQ(parseFms("G1X#1\r\n").errors(), V{"1:4 FMSX01"});
}

TEST(Fms3000Syntax_1_1, CaseIsKeptSoLowerCaseAddressesAreErrors) {
  EXPECT_EQ(parseFms("G1x10\r\n").errors(), V{"1:3 2064"});
}

TEST(Fms3000Syntax_1_1, BlockOf254CharactersWithCrLfIsTheLongestAllowed) {
  const std::string ok = "G1" + std::string(248, ' ') + "X1"; // 252 + CR LF = 254
  EXPECT_EQ(parseFms(ok + "\r\n").errors(), V{});
  EXPECT_EQ(parseFms(ok + " \r\n").errors(), V{"1:1 GCX005"});
}

TEST(Fms3000Syntax_1_1, BlockSkipBracketCommentsAndPercentAreUnknownCharacters) {
  EXPECT_EQ(parseFms("/N10X1\r\n").errors(), V{"1:1 2064"}); // §8 negative vector
  EXPECT_EQ(parseFms("G1X1 (A)\r\n").errors(), V{"1:6 2064"});
  EXPECT_EQ(parseFms("%\r\n").errors(), V{"1:1 2064"});
}

TEST(Fms3000Syntax_1_1, WordOrderIsFreeAndBlanksBetweenWordsAreAllowed) {
  const Parsed a = parseFms("N10 G1 X10 Y20 F100 S500 M3\r\n");
  const Parsed b = parseFms("N10F100G1X10Y20M3S500\r\n");
  EXPECT_EQ(b.errors(), V{});
  EXPECT_EQ(a.blocks[0].find('X')->number, b.blocks[0].find('X')->number);
  EXPECT_EQ(printedFms(b), V{"N10 F100 G1 X10 Y20 M3 S500"});
}

TEST(Fms3000Syntax_1_1, BlanksInsideANumberAreRejected) {
  EXPECT_EQ(parseFms("G1X1 0\r\n").errors(), V{"1:6 2064"});
}

TEST(Fms3000Syntax_1_1, SeveralGCodesOfOneGroupTheLastWins) {
  // no error (001:1083-1087); the machine takes the last
  const Parsed p = parseFms("G0 G1 X10 F100\r\n");
  EXPECT_EQ(p.errors(), V{});
}

TEST(Fms3000Syntax_1_2, NumbersWithoutAPointAreMillimetres) {
  const Parsed p = parseFms("X100 Y100. Z+100.000 A.5 B-.5\r\n");
  EXPECT_EQ(p.errors(), V{});
  const ir::Block& b = p.blocks[0];
  EXPECT_EQ(b.words[0].number, 100);
  EXPECT_EQ(b.words[1].number, 100);
  EXPECT_EQ(b.words[2].number, 100);
  EXPECT_EQ(b.words[2].text, "+100.000");
  EXPECT_EQ(b.words[3].number, 0.5);
  EXPECT_EQ(b.words[4].number, -0.5);
}

TEST(Fms3000Syntax_1_2, NoExponentX1E3IsX1AndAnUnusedE) {
  const Parsed p = parseFms("X1E3\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(p.warnings(), V{"1:3 GCXW10"}); // §8 negative vector: warn
  EXPECT_EQ(printedFms(p), V{"X1 E3"});
  EXPECT_EQ(parseFms("G04E25\r\n").warnings(), V{});
  EXPECT_EQ(parseFms("G81U2Z-10E5\r\n").warnings(), V{});
}

TEST(Fms3000Syntax_1_2, SequenceNumberOfUpToSevenDigits) {
  const Parsed p = parseFms("N9999999X1\r\nN0X2\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(p.blocks[0].sequence, 9999999);
  EXPECT_EQ(p.blocks[1].sequence, 0);
  EXPECT_EQ(parseFms("N12345678X1\r\n").errors(), V{"1:1 2002"});
}

TEST(Fms3000Syntax_1_2, BareNIsTolerated) {
  // `NG90X40Y70` (001:611-619, §10 Q12): written, but no number
  const Parsed p = parseFms("NG90X40Y70\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_FALSE(p.blocks[0].sequence);
  EXPECT_EQ(p.blocks[0].sequenceText, "");
  EXPECT_EQ(printedFms(p), V{"G90 X40 Y70"});
}

TEST(Fms3000Syntax_1_2, MultiLetterAddressesByLongestMatch) {
  const Parsed p = parseFms("G96 LIMS2000 DR5 DX-.707 DY+0.707 DZ0 D3\r\n");
  EXPECT_EQ(p.errors(), V{});
  const ir::Block& b = p.blocks[0];
  ASSERT_EQ(b.words.size(), 7u);
  EXPECT_EQ(b.words[1].address, "LIMS");
  EXPECT_EQ(b.words[2].address, "DR");
  EXPECT_EQ(b.words[3].address, "DX");
  EXPECT_EQ(b.words[3].number, -0.707);
  EXPECT_EQ(b.words[4].text, "+0.707");
  EXPECT_EQ(b.words[5].address, "DZ");
  EXPECT_EQ(b.find('D')->number, 3);
}

TEST(Fms3000Syntax_1_2, PKeepsItsDigitStringSoP07IsNotP7) {
  const Parsed p = parseFms("P7\r\nP07\r\nX1000P019\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(p.blocks[0].words[0].text, "7");
  EXPECT_EQ(p.blocks[1].words[0].text, "07");
  EXPECT_EQ(printedFms(p), (V{"P7", "P07", "X1000 P019"}));
  EXPECT_EQ(parseFms("P12345\r\n").errors(), V{"1:1 2002"});
  EXPECT_EQ(parseFms("P1.5\r\n").errors(), V{"1:1 2002"});
}

TEST(Fms3000Syntax_6_3, PAfterACycleCodeIsAParameter) {
  const Parsed p = parseFms("G156U1Z-20V8W1P0.5Q1F50\r\nG164Q1.5F0.5G0P1D0.5\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(p.blocks[0].find('P')->number, 0.5);
}

TEST(Fms3000Syntax_6_3, GAndGgWordsTakeOneToThreeDigitsUpTo255) {
  const Parsed p = parseFms("GG1 G081 X100\r\nG255\r\n");
  EXPECT_EQ(p.errors(), V{});
  EXPECT_EQ(p.blocks[0].words[0].address, "GG");
  EXPECT_FALSE(p.blocks[0].words[0].is('G'));
  EXPECT_EQ(p.blocks[0].words[1].text, "081");
  EXPECT_EQ(p.blocks[0].words[1].number, 81);
  EXPECT_EQ(parseFms("G256\r\n").errors(), V{"1:1 2002"});
  EXPECT_EQ(parseFms("G0001\r\n").errors(), V{"1:1 2002"});
  EXPECT_EQ(parseFms("G1.5\r\n").errors(), V{"1:1 2002"});
}

TEST(Fms3000Syntax_6_3, CycleBlockKeepsWordsInSourceOrder) {
  // the words before the cycle code run first, those after it are its parameters (§5.1)
  const Parsed p = parseFms("N40 X10 Y20 G81 Z-5 U2 F100\r\n");
  EXPECT_EQ(p.errors(), V{});
  V order;
  for (const ir::Word& w : p.blocks[0].words)
    order.push_back(w.address);
  EXPECT_EQ(order, (V{"X", "Y", "G", "Z", "U", "F"}));
  EXPECT_LT(p.blocks[0].words[1].order, p.blocks[0].words[2].order);
}

TEST(Fms3000Syntax_6_2, G25TakesLAsTheLastWordOfItsBlock) {
  EXPECT_EQ(parseFms("G91 G25 L3\r\nG1X10F100\r\nM25\r\n").errors(), V{});
  EXPECT_EQ(parseFms("G25 L\r\n").errors(), V{"1:5 2004"}); // §8 negative vector
  EXPECT_EQ(parseFms("G25\r\n").errors(), V{"1:1 2004"});
  EXPECT_EQ(parseFms("G25 L3 X1\r\n").errors(), V{"1:5 2064"});
  EXPECT_EQ(parseFms("L3 G25\r\n").errors(), V{"1:1 2064"});
}

TEST(Fms3000Syntax_9, FanucHabitsAreWarnedWithTheirLikelyIntent) {
  Parsed p = parseFms("G10 L2 P1 X0 Y0\r\n");
  EXPECT_EQ(p.warnings(), V{"1:1 GCXW11"});
  EXPECT_EQ(p.errors(), V{"1:5 2064"}); // L belongs to G25
  p = parseFms("M98 P1000\r\n");
  EXPECT_EQ(p.warnings(), V{"1:1 GCXW11"});
  EXPECT_EQ(p.errors(), V{"1:5 FMSX03"}); // the call and the end: no documented order
  p = parseFms("G04 P500\r\n");
  EXPECT_EQ(p.warnings(), V{"1:5 GCXW11"});
  p = parseFms("G99 G81 U1 Z-5 R2 F100\r\n");
  EXPECT_EQ(p.warnings(), (V{"1:1 GCXW11", "1:1 GCX013"}));
  // the FMS-3000 spellings draw no warning
  EXPECT_EQ(
      parseFms("G17 G03 G10 X10 Y0 I-10 Z-6 K-2 F100\r\nG04 E5\r\nP1000\r\nM98\r\n").warnings(),
      V{});
}

// §9 and issue 12: each Fanuc spelling runs with its FMS-3000 meaning or stops at a located
// error, and its warning names what the Fanuc habit meant.
TEST(Fms3000Syntax_9, EachFanucTrapRunsAsFms3000OrStopsWithItsIntentNamed) {
  struct Trap {
    const char* program;
    V errors, warnings;
    const char* intent; // what the warning must say the Fanuc spelling meant
  };
  const Trap traps[] = {
      // G10 L2 P1 (Fanuc: set offset data): G10 is a helix; L belongs to G25
      {"G10 L2 P1 X0 Y0\r\nM30\r\n",
       {"main.fms:1:5 2064"},
       {"main.fms:1:1 GCXW11"},
       "Fanuc's data setting G10 L_ P_"},
      // M98 P1000 (Fanuc: call program 1000): M98 ends the program, P1000 alone calls
      {"M98 P1000\r\n",
       {"main.fms:1:5 FMSX03"},
       {"main.fms:1:1 GCXW11"},
       "the Fanuc call 'M98 P1000' is written 'P1000' alone"},
      // G04 P500 (Fanuc: dwell 0.5 s): the dwell is E; P500 calls a program
      {"G04 P500\r\nM30\r\n",
       {"main.fms:1:1 2004"},
       {"main.fms:1:5 GCXW11"},
       "P500 is the Fanuc dwell"},
      // G81 ... R2 (Fanuc: the R level) and G98/G99 (Fanuc: the return level)
      {"G0 Z10\r\nG81 U1 Z-5 R2 F100\r\nM30\r\n",
       {"main.fms:2:1 2004"},
       {"main.fms:2:12 GCXW11"},
       "'R2' is a Fanuc cycle word"},
      {"G0 Z10\r\nG98 G81 U1 Z-5 F100\r\nM30\r\n",
       {"main.fms:2:1 GCX031"},
       {"main.fms:2:1 GCXW11", "main.fms:2:1 GCX013"},
       "'G98' is a Fanuc cycle word"},
  };
  for (const Trap& t : traps) {
    const MacroRun r = runFms(t.program);
    EXPECT_EQ(r.errors, t.errors) << t.program << r.rendered;
    EXPECT_EQ(r.warnings, t.warnings) << t.program << r.rendered;
    EXPECT_NE(r.rendered.find(t.intent), std::string::npos) << t.program << r.rendered;
  }
  // written the FMS-3000 way they mean what the manual says: a program call, a dwell, levels
  const MacroRun r =
      runFms({{"main.fms", "G04 E5\r\nP1000\r\nG0 Z10\r\nG81 U2 Z-5 F100\r\nM30\r\n"},
              {"1000.fms", "G91 G1 X5 F100\r\nG90 M99\r\n"}});
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  EXPECT_EQ(r.warnings, V{}) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"DW 0.5s", "L 5,0,0 F100", "R 5,0,10", "R 5,0,2", "L 5,0,-5 F100",
                           "R 5,0,2", "END"}));
}

} // namespace
} // namespace gcx::test
