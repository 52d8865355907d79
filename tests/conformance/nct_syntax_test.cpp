// Conformance of the NCT front end to nct.md §0-§1 and nct-macro.md §1-§5, one test per rule,
// named after the spec section it checks.
#include <gtest/gtest.h>

#include "dialects/nct/printer.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

ir::Block only(const Parsed& p) {
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks.size(), 1u);
  return p.blocks.empty() ? ir::Block{} : p.blocks.front();
}

std::string printed(const std::string& text) {
  return nct::printBlock(only(parseNct(text, {.staticChecks = false})));
}

TEST(NctSpec_1_2, NumbersWithoutPointAreWholeUnits) {
  const ir::Block b = only(parseNct("G1 X325 B24.236 Z.032 Y5. F150"));
  EXPECT_EQ(b.words[1].number, 325);
  EXPECT_EQ(b.words[2].number, 24.236);
  EXPECT_EQ(b.words[3].number, 0.032);
  EXPECT_EQ(b.words[4].number, 5);
  EXPECT_EQ(b.words[5].number, 150);
}

TEST(NctSpec_1_2, IncrementalOperatorBindsToItsWordOnly) {
  const ir::Block b = only(parseNct("G90 G1 XI-40 Y50"));
  EXPECT_TRUE(b.words[2].incremental);
  EXPECT_EQ(b.words[2].number, -40);
  EXPECT_FALSE(b.words[3].incremental);
}

TEST(NctSpec_1_2, IncrementalOperatorWithAVariable) {
  EXPECT_EQ(printed("G0 XI-#24"), "G0 XI-#24");
  const ir::Block b = only(parseNct("G0 XI-#24"));
  EXPECT_TRUE(b.words[1].incremental);
  EXPECT_EQ(b.words[1].expr.kind, ir::ExprKind::Unary);
  EXPECT_EQ(b.words[1].expr.args[0].number, 24);
}

TEST(NctSpec_1_2, PlusSignIsDiscardedAndBlanksInsideWordsIgnored) {
  EXPECT_EQ(printed("G1 X+5 Y - 40 Z 1.5"), "G1 X5 Y-40 Z1.5");
}

TEST(NctSpec_1_2, MinusZeroPrintsAsZero) {
  EXPECT_EQ(printed("G1 X-0 Y-0.0 Z-0.5"), "G1 X0 Y0 Z-0.5");
}

TEST(NctSpec_1_2, WordsMayBeWrittenWithoutBlanks) {
  EXPECT_EQ(printed("G2X10Y0I20J-10"), "G2 X10 Y0 I20 J-10");
}

TEST(NctSpec_1_1, LettersAreCaseInsensitive) {
  EXPECT_EQ(printed("n10 g1 x10 (Keep Case)"), "N10 G1 X10 (Keep Case)");
}

TEST(NctSpec_1_5, CommentSpansLinesAndRemovesTheBlocksInside) {
  Parsed p = parseNct("#1=1\n(#1=2\n#1=3)\n#2=#1\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_TRUE(p.blocks[1].words.empty());
  EXPECT_TRUE(p.blocks[1].stmts.empty());
  EXPECT_EQ(p.blocks[1].comments.at(0).text, "#1=2\n#1=3");
  EXPECT_EQ(p.blocks[1].lastLine, 3u);
  EXPECT_EQ(p.blocks[2].range.begin.line, 4u);
}

TEST(NctSpec_1_5, CommentBetweenWords) {
  const ir::Block b = only(parseNct("N1339 (P1) R0.5"));
  EXPECT_EQ(b.words.size(), 1u);
  EXPECT_EQ(b.comments.at(0).text, "P1");
}

TEST(NctSpec_1_6, BlockSkipLevels) {
  EXPECT_EQ(only(parseNct("/ N1200 G0 X200")).skipLevel, 1);
  EXPECT_EQ(only(parseNct("/3 G0 X200")).skipLevel, 3);
  Parsed nine = parseNct("/9 G0 X1");
  EXPECT_EQ(nine.warnings(), std::vector<std::string>{"1:1 GCXW02"});
  EXPECT_EQ(parseNct("/0 G0 X1").errors(), std::vector<std::string>{"1:1 2002"});
}

TEST(NctSpec_1_7, FirstNIsTheBlockNumberASecondNIsAWord) {
  const ir::Block b = only(parseNct("N130 G65 P9101 X12.3 Y32.6 N250"));
  EXPECT_EQ(b.sequence, 130);
  EXPECT_EQ(b.words.back().address, "N");
  EXPECT_EQ(b.words.back().number, 250);
}

// One error, whichever parse path meets it first (the fast path leaves the block to the grammar).
TEST(NctSpec_1_7, AFractionalBlockNumberIsOneError) {
  EXPECT_EQ(parseNct("N1.5 G0 X1").errors(), std::vector<std::string>{"1:1 2064"});
}

// A `+` is discarded (§1.2 rule 3), so `N+100` is block number 100 on both parse paths, and
// `fmt` prints it back as `N100` without changing the block (found by the fmt round-trip fuzzer).
TEST(NctSpec_1_7, PlusSignedFirstNIsTheBlockNumber) {
  for (const char* text : {"N+100 G91 G0 X100", "N+100 G91 G0 X#1"}) { // fast path, grammar
    const ir::Block b = only(parseNct(text));
    EXPECT_EQ(b.sequence, 100) << text;
    EXPECT_EQ(b.sequenceRange.length, 5u) << text;
    EXPECT_EQ(b.words.front().address, "G") << text;
  }
  EXPECT_EQ(printed("N+100 G91 G0 X100"), "N100 G91 G0 X100");
  EXPECT_EQ(parseNct("N-100 G0 X1").errors(), std::vector<std::string>{"1:1 2002"});
}

TEST(NctSpec_1_8, PercentLineAndProgramNumber) {
  Parsed p = parseNct("%O0101\nG0 X1\nM30\n%\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].kind, ir::BlockKind::ProgramStart);
  EXPECT_EQ(p.blocks[0].programName, "O0101");
  EXPECT_EQ(parseNct("G0 X1\n%\nM30\n").errors(), std::vector<std::string>{"2:1 GCX007"});
}

TEST(NctSpec_1_9, SeveralGCodesOfDifferentGroups) {
  EXPECT_EQ(only(parseNct("G0 G90 G17 G54 X20 Y30 Z0 S2000 M3")).words.size(), 9u);
}

TEST(NctSpec_1_9, TwoGCodesOfOneGroupAreAnError) {
  EXPECT_EQ(parseNct("G0 G1 X1").errors(), std::vector<std::string>{"1:4 GCX012"});
  EXPECT_EQ(parseNct("G17 G18").errors(), std::vector<std::string>{"1:5 GCX012"});
  EXPECT_EQ(parseNct("G90 G91 X1").errors(), std::vector<std::string>{"1:5 GCX012"});
}

TEST(NctSpec_1_9, TwoPInOneBlockIsAnError) { // 000:3805-3808
  EXPECT_EQ(parseNct("G0 G54.1 P16 X100 Y20 M98 P1").errors(),
            std::vector<std::string>{"1:27 GCX011"});
}

TEST(NctSpec_1_9, SpindleMCodesExcludeEachOther) {
  EXPECT_EQ(parseNct("M3 M5").errors(), std::vector<std::string>{"1:4 GCX014"});
  EXPECT_TRUE(parseNct("M3 M8").errors().empty());
}

TEST(NctSpec_1_10, G10L52SwitchesToParameterRecords) {
  Parsed p = parseNct("G10 L52\nN1339 P1 R0.5\nN1746 Q1 R1\nG11\nN10 G0 X1\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[1].kind, ir::BlockKind::Data);
  EXPECT_EQ(p.blocks[1].sequence, 1339);
  EXPECT_EQ(p.blocks[2].kind, ir::BlockKind::Data);
  EXPECT_EQ(p.blocks[3].kind, ir::BlockKind::Normal);
  EXPECT_EQ(p.blocks[4].kind, ir::BlockKind::Normal);
  EXPECT_EQ(parseNct("G10 L52\nN1339 X5 R1\nG11\n").errors(), std::vector<std::string>{"2:7 2017"});
}

TEST(NctSpec_1_3, ValuesBeyondTheAddressTable) {
  EXPECT_EQ(parseNct("G43 H1000").errors(), std::vector<std::string>{"1:5 2002"});
  EXPECT_EQ(parseNct("M3.5").errors(), std::vector<std::string>{"1:1 2064"});
  EXPECT_EQ(parseNct("G1 X1 F-100").errors(), std::vector<std::string>{"1:7 2002"});
  EXPECT_EQ(parseNct("N123456789 G0").errors(), std::vector<std::string>{"1:1 2002"});
  EXPECT_EQ(parseNct("G1 JI5").errors(), std::vector<std::string>{"1:4 GCX015"});
}

TEST(NctSpec_0_1, SymbolFontMinusAliasesAreAcceptedWithAWarning) {
  Parsed p = parseNct("#1=#1!0.2\nG1 Y\xE2\x80\x93"
                      "60\nG1 X\xE2\x88\x92"
                      "5\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.warnings(), (std::vector<std::string>{"1:6 GCXW01", "2:5 GCXW01", "3:5 GCXW01"}));
  EXPECT_EQ(p.blocks[1].words[1].number, -60);
  EXPECT_EQ(p.blocks[2].words[1].number, -5);
}

TEST(NctSpec_5_1, SubprogramByFileNameKeepsItsCase) {
  const ir::Block b = only(parseNct("M98 <..\\Sub\\Pocket.prg> L2"));
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(b.words[1].kind, ir::ValueKind::Path);
  EXPECT_EQ(b.words[1].text, "..\\Sub\\Pocket.prg");
}

TEST(MacroSpec_1_1_L7, KeywordsGluedToOperands) {
  EXPECT_EQ(printed("#120=27MOD4"), "#120=27 MOD 4");
  EXPECT_EQ(printed("IF[#1EQ20]THEN#100=3.15"), "IF[#1 EQ 20] THEN #100=3.15");
  EXPECT_EQ(printed("IF[#100GT#101]GOTO210"), "IF[#100 GT #101] GOTO 210");
  EXPECT_EQ(printed("WHILE[#1LE5]DO1"), "WHILE[#1 LE 5] DO1");
  EXPECT_EQ(printed("END1"), "END1");
  EXPECT_EQ(printed("#100=#100AND#1132"), "#100=#100 AND #1132");
}

TEST(MacroSpec_3_1, OperatorPrecedenceAndFunctionOperands) {
  const ir::Block b = only(parseNct("#124=2+3*4"));
  const ir::Expr e = b.stmts.at(0).value;
  ASSERT_EQ(e.kind, ir::ExprKind::Binary);
  EXPECT_EQ(e.op, ir::Op::Add);
  EXPECT_EQ(e.args[1].op, ir::Op::Mul);

  const ir::Expr f = only(parseNct("#1=SIN30-#101")).stmts.at(0).value;
  ASSERT_EQ(f.kind, ir::ExprKind::Binary); // [SIN30]-#101
  EXPECT_EQ(f.args[0].kind, ir::ExprKind::Call);
  EXPECT_EQ(f.args[0].args[0].number, 30);

  const ir::Expr m = only(parseNct("#121=-27MOD4")).stmts.at(0).value; // unary minus binds first
  EXPECT_EQ(m.op, ir::Op::Mod);
  EXPECT_EQ(m.args[0].kind, ir::ExprKind::Unary);
}

TEST(MacroSpec_3_1, AtanOfTwoBracketsWarns) {
  Parsed p = parseNct("#1=ATAN[1]/[2]");
  EXPECT_EQ(p.warnings(), std::vector<std::string>{"1:4 NCTW02"});
}

TEST(MacroSpec_2_2, VariableReferences) {
  EXPECT_EQ(printed("#1=#[#120-4]+#_ABSIO[3]+#_PI"), "#1=#[#120-4]+#_ABSIO[3]+#_PI");
  EXPECT_EQ(parseNct("#132=##120").errors(), std::vector<std::string>{"1:7 2064"});
  EXPECT_EQ(parseNct("G1 X#").errors(), std::vector<std::string>{"1:5 2064"});
  EXPECT_EQ(parseNct("#1.5=2").errors(), std::vector<std::string>{"1:1 2064"});
}

TEST(MacroSpec_2_6, VariablesAsAddressValues) {
  EXPECT_EQ(printed("G#102 X#102 Y-#24 Z-[#18+#26]"), "G#102 X#102 Y-#24 Z-[#18+#26]");
  EXPECT_EQ(printed("G0 AX[#101]=10"), "G0 AX[#101]=10");
  EXPECT_EQ(parseNct("N#1 G0 X1").errors(), std::vector<std::string>{"1:1 NCTX10"});
}

TEST(MacroSpec_3_4, UnbalancedBrackets) {
  EXPECT_EQ(parseNct("#1=[1+2]]").errors(), std::vector<std::string>{"1:9 2064"});
  EXPECT_EQ(parseNct("#1=[[1+2]").errors(), std::vector<std::string>{"1:4 2121"});
}

TEST(MacroSpec_4_4_W4, WhileWithoutDoAndWrongTerminator) {
  EXPECT_EQ(parseNct("WHILE[#1LT5]").errors(), std::vector<std::string>{"1:1 2110"});
  EXPECT_EQ(parseNct("WHILE[#1LT5]=1").errors(), std::vector<std::string>{"1:13 2121"});
}

TEST(MacroSpec_4_5, StaticLoopPairing) {
  EXPECT_TRUE(parseNct("DO1\nDO2\nEND2\nEND1\nWHILE[#1LT3]DO1\nEND1\n").errors().empty());
  EXPECT_EQ(parseNct("DO1\nEND1\nEND1\n").errors(), std::vector<std::string>{"3:1 2125"});
  EXPECT_EQ(parseNct("DO1\nDO1\nEND1\nEND1\n").errors(), std::vector<std::string>{"2:1 NCTX06"});
  EXPECT_EQ(parseNct("DO1\nG0 X1\n").errors(), std::vector<std::string>{"1:1 NCTX06"});
  EXPECT_EQ(parseNct("DO4\nEND4\n").errors(), std::vector<std::string>{"1:1 2002"});
}

TEST(MacroSpec_4_1, GotoToAMissingBlock) {
  EXPECT_EQ(parseNct("GOTO 20\nN10 G0 X1\n").errors(), std::vector<std::string>{"1:1 2125"});
  EXPECT_TRUE(parseNct("GOTO 10\nN10 G0 X1\n").errors().empty());
  EXPECT_TRUE(parseNct("GOTO #1\n").errors().empty()); // known only at run time
}

TEST(MacroSpec_2_9_2, MessageCommentBelongsToTheAssignment) {
  const ir::Block b = only(parseNct("#3000=1(TOOL BROKEN)"));
  EXPECT_EQ(b.stmts.at(0).message, "TOOL BROKEN");
}

TEST(MacroSpec_9_2, PrmOnlyAsTheWholeRightSide) {
  EXPECT_TRUE(parseNct("#101=PRM[107,0]/[4]").errors().empty());
  EXPECT_EQ(parseNct("#101=PRM[107]+1").errors(), std::vector<std::string>{"1:6 2017"});
}

TEST(MacroSpec_5_4, ArgumentCollisionsAreForbiddenAddresses) {
  EXPECT_TRUE(parseNct("G65 P2200 A2.12 B3.213 J36.9 E129.73 J-12").errors().empty());
  EXPECT_EQ(parseNct("G65 P2200 A2.12 B3.213 J36.9 J-12 E129.73").errors(),
            std::vector<std::string>{"1:35 2017"});
  EXPECT_EQ(parseNct("G65 P2201 X1 X2").errors(), std::vector<std::string>{"1:14 2017"});
  EXPECT_EQ(parseNct("G65 P2201 ,C1").errors(), std::vector<std::string>{"1:11 2017"});
  EXPECT_TRUE(parseNct("G65 P2201 I1 J2 K3 I4 J5 K6").errors().empty());
  // G66.1 (a code with tenths) and G66 make call blocks too: their letters are arguments
  EXPECT_TRUE(parseNct("G66.1 P2201 I1 J2 K3 I4 J5 K6").errors().empty());
  EXPECT_TRUE(parseNct("G66 P2201 I1 J2 K3 I4 J5 K6").errors().empty());
  EXPECT_EQ(parseNct("G67 I1 I4").errors(), std::vector<std::string>{"1:8 GCX011"});
}

TEST(MacroSpec_6, PrintCommands) {
  EXPECT_EQ(printed("DPRNT[X#100[53]**Y#101[53]]"), "DPRNT[X#100[53]**Y#101[53]]");
  const ir::Block b = only(parseNct("DPRNT[X#100[53]]"));
  ASSERT_EQ(b.stmts.at(0).items.size(), 2u);
  EXPECT_EQ(b.stmts.at(0).items[1].variable, 100);
  EXPECT_EQ(b.stmts.at(0).items[1].intDigits, 5);
  EXPECT_EQ(b.stmts.at(0).items[1].fracDigits, 3);
  EXPECT_EQ(printed("POPEN31"), "POPEN31");
}

} // namespace
} // namespace gcx::test

namespace gcx::test {
namespace {

TEST(MacroSpec_4_2, IfGotoToAMissingBlockWarnsUntilTaken) {
  Parsed p = parseNct("#1=1\nIF[#1EQ2]GOTO77\nM30\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.warnings(), std::vector<std::string>{"2:1 2125"});
}

} // namespace
} // namespace gcx::test
