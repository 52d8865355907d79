// The manual's examples (wl4.md §7) through the WL4 front end, each printed back as the WL4
// text of its IR (the printer writes every word, statement and comment in source order), plus
// the lexical rules of §1 and the grammar of §6.8.
#include <gtest/gtest.h>

#include "ir/items.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

V printed(const std::string& text) {
  Parsed p = parseWl4(text);
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  return printedWl4(p);
}

TEST(Wl4Syntax_7, Example1_WordSyntax) {
  // 002:160-166: a number without a point is whole millimetres, `.23` a fraction
  Parsed p = parseWl4("X.23\nZ123.4\nX1030\nM2\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].words[0].number, 0.23);
  EXPECT_EQ(p.blocks[0].words[0].text, ".23");
  EXPECT_EQ(p.blocks[2].words[0].number, 1030); // not 1.030 (Fanuc's increment, §9)
  EXPECT_EQ(printedWl4(p), (V{"X0.23", "Z123.4", "X1030", "M2"}));
}

TEST(Wl4Syntax_7, Example2_ConditionalBlocks) {
  Parsed p = parseWl4("N20 G0 X0 Z0\n/ N23 G0 Z100 M0 $ comment\n/ N24 Z5\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[1].skipLevel, 1);
  EXPECT_EQ(p.blocks[1].sequence, 23);
  ASSERT_EQ(p.blocks[1].comments.size(), 1u);
  EXPECT_EQ(p.blocks[1].comments[0].kind, ir::CommentKind::ToLineEnd);
  EXPECT_EQ(p.blocks[1].comments[0].text, " comment");
  EXPECT_EQ(printedWl4(p), (V{"N20 G0 X0 Z0", "/N23 G0 Z100 M0 $ comment", "/N24 Z5"}));
}

TEST(Wl4Syntax_7, Example3And4_ArcsByCentreAndByRadius) {
  EXPECT_EQ(printed("X100Z86.603F0.2\nG2X0Z100I-50K-86.603\nG90G54G17G1X-50Y86.603F100\n"
                    "G2X0Y100R100\n"),
            (V{"X100 Z86.603 F0.2", "G2 X0 Z100 I-50 K-86.603", "G90 G54 G17 G1 X-50 Y86.603 F100",
               "G2 X0 Y100 R100"}));
}

TEST(Wl4Syntax_7, Example5And6_FilletAndHome) {
  EXPECT_EQ(printed("G90G54G17G0X0Y100\nG12X100Y0F100\nN100 G36 Z0\nN101 G36 X0 Y0\n"),
            (V{"G90 G54 G17 G0 X0 Y100", "G12 X100 Y0 F100", "N100 G36 Z0", "N101 G36 X0 Y0"}));
}

TEST(Wl4Syntax_7, Example7_ProbeWithAGuardedJumpAndAComputedValue) {
  Parsed p = parseWl4("G94G38G1Y100F200\nIF (ABS(#132-#1011)>0.01) N010\nN05 M0 N05\n"
                      "N010 G92 Y(#1011+6.54)\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(printedWl4(p), (V{"G94 G38 G1 Y100 F200", "IF(ABS(#132-#1011)>0.01) N010", "N05 M0 N05",
                              "N010 G92 Y(#1011+6.54)"}));
  const ir::Block& guarded = p.blocks[1];
  ASSERT_EQ(guarded.stmts.size(), 2u);
  EXPECT_EQ(guarded.stmts[0].kind, ir::StmtKind::Guard);
  EXPECT_FALSE(guarded.stmts[0].precision);
  EXPECT_EQ(guarded.stmts[1].kind, ir::StmtKind::Jump);
  EXPECT_EQ(guarded.stmts[1].label, "010");
  EXPECT_EQ(p.blocks[2].sequenceText, "05"); // label 5, then a jump to it
  EXPECT_EQ(p.blocks[2].stmts[0].label, "05");
}

TEST(Wl4Syntax_7, Example8To12_ProbeArcSetMirrorSpindleLimitFeeds) {
  EXPECT_EQ(printed("G94G38G2Z100R200F200\nG92X100Y250Z30\nG51X-1\nG51X1Y-1\nG50\nG51 S2000\n"
                    "G94 F10.4\nG95 F0.5 S20\n"),
            (V{"G94 G38 G2 Z100 R200 F200", "G92 X100 Y250 Z30", "G51 X-1", "G51 X1 Y-1", "G50",
               "G51 S2000", "G94 F10.4", "G95 F0.5 S20"}));
}

TEST(Wl4Syntax_7, Example13_ChamferWords) {
  EXPECT_EQ(printed("N50 G0 X40 Z70\nN51 G1 X100 F0.2 B10\nN11 G3 X100 Z50 R50 B8 F0.2\n"),
            (V{"N50 G0 X40 Z70", "N51 G1 X100 F0.2 B10", "N11 G3 X100 Z50 R50 B8 F0.2"}));
}

TEST(Wl4Syntax_7, Example14_DirectIndirectAndComputedReferences) {
  Parsed p = parseWl4("X#20\nX#(#20)\nX#(ABS(#3-#4*2))\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(printedWl4(p), (V{"X#20", "X#(#20)", "X#(ABS(#3-#4*2))"}));
  EXPECT_EQ(p.blocks[1].words[0].expr.kind, ir::ExprKind::Indirect);
  // #4*2 binds first: ABS(#3 - (#4*2))
  const ir::Expr& abs = p.blocks[2].words[0].expr.args[0];
  EXPECT_EQ(abs.func, ir::Func::Abs);
  EXPECT_EQ(abs.args[0].op, ir::Op::Sub);
  EXPECT_EQ(abs.args[0].args[1].op, ir::Op::Mul);
}

TEST(Wl4Syntax_7, Example15_AssignmentsAnywhereAndInsideExpressions) {
  Parsed p = parseWl4("N5 #1=10 #2=20 #3=30 #4=40\nN10 G90 G0 X#1 Z#2 #1=(#1+#3) #2=(#2+#4)\n"
                      "N30 X#1=(ABS(#3-#4) + #5=(40.78*#2))\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(printedWl4(p),
            (V{"N5 #1=10 #2=20 #3=30 #4=40", "N10 G90 G0 X#1 Z#2 #1=(#1+#3) #2=(#2+#4)",
               "N30 X#1=(ABS(#3-#4)+#5=(40.78*#2))"}));
  EXPECT_EQ(ir::items(p.blocks[1]), (std::vector<ir::ItemRef>{{ir::ItemKind::Word, 0},
                                                              {ir::ItemKind::Word, 1},
                                                              {ir::ItemKind::Word, 2},
                                                              {ir::ItemKind::Word, 3},
                                                              {ir::ItemKind::Stmt, 0},
                                                              {ir::ItemKind::Stmt, 1}}));
  const ir::Expr& x = p.blocks[2].words[0].expr;
  EXPECT_EQ(x.kind, ir::ExprKind::Assign);
  EXPECT_EQ(x.args[1].args[0].args[1].kind, ir::ExprKind::Assign); // #5=(...) inside
}

TEST(Wl4Syntax_7, Example16_LabelsAndJumps) {
  Parsed p =
      parseWl4("N5 G1 X0 Z0 F50\nN010 Z10.5\nN15 Z0 N17\nN16\nN017 M0\nN20 U5 N10\nN25 M2\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(printedWl4(p), (V{"N5 G1 X0 Z0 F50", "N010 Z10.5", "N15 Z0 N17", "N16", "N017 M0",
                              "N20 U5 N10", "N25 M2"}));
  EXPECT_EQ(p.blocks[2].find('N'), nullptr); // the second N is a jump, not a word
  EXPECT_EQ(p.blocks[2].stmts[0].kind, ir::StmtKind::Jump);
  EXPECT_EQ(p.blocks[1].sequenceText, "010");
}

TEST(Wl4Syntax_7, Example17_ConditionsWithPrecisionAndStatementAssignments) {
  Parsed p = parseWl4("N10 IF3 (#1>=#2) #1=(#1-0.5) N1\nIF (#30) #30=(#30-1)\n"
                      "IF (#30<>0) #30=#30-1\nN20 G1 X0 Z100 F500 IF ((#1-#2)>0) Z0\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(printedWl4(p), (V{"N10 IF3(#1>=#2) #1=(#1-0.5) N1", "IF(#30) #30=(#30-1)",
                              "IF(#30<>0) #30=#30-1", "N20 G1 X0 Z100 F500 IF((#1-#2)>0) Z0"}));
  EXPECT_EQ(p.blocks[0].stmts[0].precision, 3);
  EXPECT_EQ(p.blocks[2].stmts[1].value.op, ir::Op::Sub); // #30=#30-1 goes on with '-'
}

TEST(Wl4Syntax_7, Example18_CallWords) {
  Parsed p = parseWl4("L07\nL0703\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].stmts[0].callee, "07");
  EXPECT_EQ(p.blocks[0].stmts[0].value.number, 1);
  EXPECT_EQ(p.blocks[1].stmts[0].callee, "07");
  EXPECT_EQ(p.blocks[1].stmts[0].value.number, 3);
  EXPECT_EQ(printedWl4(p), (V{"L07", "L0703"}));
}

TEST(Wl4Syntax_7, Example20_CycleCallBlock) {
  EXPECT_EQ(printed("G83 #2=1 #3=-17 #5=5 F100\nG90G0X100Y200\nG80\n"),
            (V{"G83 #2=1 #3=-17 #5=5 F100", "G90 G0 X100 Y200", "G80"}));
}

TEST(Wl4Syntax_7, Example21_ProgramUnitsAndContourWords) {
  // 002:3114-3125 with its contour N120-N124 (after M2 in the manual's layout too)
  Parsed p = parseWl4("%TEST_G77_1\nN9 G0 X10 Z40 $A\n"
                      "N10 G77 G0 X2 Z45 P120 Q124 I0.5 K0.5 E2 F0.7 S500 M3\n"
                      "N120 G1 Z35 F0.3\nN121 G2 X5 Z25 R10\nN122 G3 X7 Z20 R8\n"
                      "N123 G1 X8.5 Z18\nN124 Z5\nM2 $ END\n%\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].kind, ir::BlockKind::ProgramStart);
  EXPECT_EQ(p.blocks[0].programName, "TEST_G77_1");
  EXPECT_EQ(p.blocks[9].kind, ir::BlockKind::ProgramEnd);
  EXPECT_EQ(p.blocks[3].sequence, 120);
  EXPECT_EQ(p.blocks[7].sequence, 124);
  EXPECT_EQ(printedWl4(p), (V{"%TEST_G77_1", "N9 G0 X10 Z40 $A",
                              "N10 G77 G0 X2 Z45 P120 Q124 I0.5 K0.5 E2 F0.7 S500 M3",
                              "N120 G1 Z35 F0.3", "N121 G2 X5 Z25 R10", "N122 G3 X7 Z20 R8",
                              "N123 G1 X8.5 Z18", "N124 Z5", "M2 $ END", "%"}));
}

// 002:3229-3250: the duplicate numbers N11 and N12 are legal (§10.15), the contour follows M2
TEST(Wl4Syntax_7, Example22_G77RoughAndFinishWithDuplicateNumbers) {
  Parsed p = parseWl4("%TEST_G77\nN10 G0 Z100\nN11 T1 M6\nN12 G0 X10 Z40\n"
                      "N13 G77 G41 G0 X2 Z45 P120 Q124 R0.5 E2 F0.7 S500 M3\n"
                      "N14 G0 Z100$TOOL CHANGE POINT\nN15 T2 M6\nN16 G0 X10 Z40\n"
                      "N11 G77 G41 G0 X2 Z45 P120 Q124 R0.2 F0.3 S800\n"
                      "N12 G77 G41 G0 X2 Z45 P120 Q124 F0.3 S800\nM2\n"
                      "N120 G1 Z35\nN121 G2 X5 Z25 R10\nN122 G3 X7 Z20 R8\nN123 G1 X8.5 Z18\n"
                      "N124 Z5\n%\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].programName, "TEST_G77");
  EXPECT_EQ(p.blocks[2].sequence, 11);
  EXPECT_EQ(p.blocks[8].sequence, 11);
  EXPECT_EQ(p.blocks[9].sequence, 12);
  EXPECT_EQ(
      printedWl4(p),
      (V{"%TEST_G77", "N10 G0 Z100", "N11 T1 M6", "N12 G0 X10 Z40",
         "N13 G77 G41 G0 X2 Z45 P120 Q124 R0.5 E2 F0.7 S500 M3", "N14 G0 Z100 $TOOL CHANGE POINT",
         "N15 T2 M6", "N16 G0 X10 Z40", "N11 G77 G41 G0 X2 Z45 P120 Q124 R0.2 F0.3 S800",
         "N12 G77 G41 G0 X2 Z45 P120 Q124 F0.3 S800", "M2", "N120 G1 Z35", "N121 G2 X5 Z25 R10",
         "N122 G3 X7 Z20 R8", "N123 G1 X8.5 Z18", "N124 Z5", "%"}));
}

// 002:3412-3432: the transverse version, its contour monotone in X
TEST(Wl4Syntax_7, Example23_G78TransverseWithItsContour) {
  Parsed p = parseWl4("%TEST_G78\nN10 G0 Z100\nN11 T1 M6\nN12 G0 X10 Z40\n"
                      "N13 G78 G41 G0 X10 Z5 P120 Q124 R0.5 E2 F0.7 S500 M3\n"
                      "N14 G0 Z100\nN15 T2 M6\nN16 G0 X10 Z40\n"
                      "N11 G78 G41 G0 X10 Z5 P120 Q124 R0.2 F0.3 S800\n"
                      "N12 G78 G41 G0 X10 Z5 P120 Q124 F0.3 S800\nM2\n"
                      "N120 G1 X8.5\nN121 G1 X8 Z15\nN122 G3 X7 Z20 R10\nN123 G2 X5 Z25 R8\n"
                      "N124 Z40\n%\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].programName, "TEST_G78");
  EXPECT_EQ(printedWl4(p),
            (V{"%TEST_G78", "N10 G0 Z100", "N11 T1 M6", "N12 G0 X10 Z40",
               "N13 G78 G41 G0 X10 Z5 P120 Q124 R0.5 E2 F0.7 S500 M3", "N14 G0 Z100", "N15 T2 M6",
               "N16 G0 X10 Z40", "N11 G78 G41 G0 X10 Z5 P120 Q124 R0.2 F0.3 S800",
               "N12 G78 G41 G0 X10 Z5 P120 Q124 F0.3 S800", "M2", "N120 G1 X8.5", "N121 G1 X8 Z15",
               "N122 G3 X7 Z20 R10", "N123 G2 X5 Z25 R8", "N124 Z40", "%"}));
}

TEST(Wl4Syntax_7, Example24_MessagesOfTheSystemProgram) {
  Parsed p =
      parseWl4("N010 M0 N10 .ERROR > UNKNOWN CYCLE IN RANGE G70-G79\n.********* G31 ********\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  ASSERT_EQ(p.blocks[0].comments.size(), 1u);
  EXPECT_EQ(p.blocks[0].comments[0].kind, ir::CommentKind::Message);
  EXPECT_EQ(p.blocks[0].comments[0].text, "ERROR > UNKNOWN CYCLE IN RANGE G70-G79");
  EXPECT_EQ(p.blocks[1].kind, ir::BlockKind::CommentLine);
  EXPECT_EQ(printedWl4(p),
            (V{"N010 M0 N10 .ERROR > UNKNOWN CYCLE IN RANGE G70-G79", ".********* G31 ********"}));
}

TEST(Wl4Syntax_1_6, AMessageMayBeCyrillicAndADotInANumberIsNone) {
  // ".Ошибка в программе" in KOI8-R (lower case is allowed in a message) after a word and alone,
  // through both parsing paths
  const std::string koi8 =
      "G0 X1.5 .\xef\xdb\xc9\xc2\xcb\xc1 \xd7 \xd0\xd2\xcf\xc7\xd2\xc1\xcd\xcd\xc5\n"
      "M0 .\xf3\xf4\xef\xf0\n";
  for (bool fast : {true, false}) {
    Parsed p = parseWl4(koi8, front::Encoding::Koi8R, fast);
    ASSERT_TRUE(p.errors().empty()) << p.rendered();
    ASSERT_EQ(p.blocks[0].comments.size(), 1u);
    EXPECT_EQ(p.blocks[0].comments[0].text,
              "\u041E\u0448\u0438\u0431\u043A\u0430 \u0432 "
              "\u043F\u0440\u043E\u0433\u0440\u0430\u043C\u043C\u0435");
    EXPECT_EQ(printedWl4(p)[1], "M0 .\u0421\u0422\u041E\u041F");
  }
  // outside a message Cyrillic is still an error
  EXPECT_EQ(parseWl4("G0 X1 \xef\n", front::Encoding::Koi8R).errors(), (V{"1:7 2064"}));
}

// The message's dot is the only byte of the line that means something: the block reader must
// see it though it stands in the middle of a long run of letters, digits and blanks.
TEST(Wl4Syntax_1_6, APlainMessageAfterALongRunOfWords) {
  for (bool fast : {true, false}) {
    Parsed p = parseWl4("N010 G0 X10 Z20 .TOOL CHANGE AND CHECK THE INSERT\n",
                        front::Encoding::Utf8, fast);
    ASSERT_TRUE(p.errors().empty()) << p.rendered();
    ASSERT_EQ(p.blocks.at(0).comments.size(), 1u);
    EXPECT_EQ(p.blocks[0].comments[0].kind, ir::CommentKind::Message);
    EXPECT_EQ(p.blocks[0].comments[0].text, "TOOL CHANGE AND CHECK THE INSERT");
    EXPECT_EQ(p.blocks[0].sequence, 10);
    EXPECT_EQ(p.blocks[0].words.size(), 3u); // G0 X10 Z20
  }
}

// ---------------------------------------------------------------- §6.3 precedence

TEST(Wl4Syntax_6_3, TwoLevelsLeftToRight) {
  // `#3>#4+1` is (#3>#4)+1; `2*3**2` is (2*3)**2
  Parsed p = parseWl4("#1=(#3>#4+1)\n#2=(2*3**2)\n#5=(#1 MOD 3 AND #2)\n#6=ATAN(1)/(2)\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  const ir::Expr& a = p.blocks[0].stmts[0].value.args[0];
  EXPECT_EQ(a.op, ir::Op::Add);
  EXPECT_EQ(a.args[0].op, ir::Op::Gt);
  const ir::Expr& b = p.blocks[1].stmts[0].value.args[0];
  EXPECT_EQ(b.op, ir::Op::Pow);
  EXPECT_EQ(b.args[0].op, ir::Op::Mul);
  const ir::Expr& c = p.blocks[2].stmts[0].value.args[0];
  EXPECT_EQ(c.op, ir::Op::LogicalAnd);
  EXPECT_EQ(c.args[0].op, ir::Op::FloorMod);
  EXPECT_EQ(p.blocks[3].stmts[0].value.func, ir::Func::Atan2);
}

// ---------------------------------------------------------------- §1.1 encoding

TEST(Wl4Syntax_1_1, AKoi8RFileAndItsUtf8TwinGiveTheSameBlocks) {
  // "$ Деталь" in KOI8-R: Д=0xE4 е=0xC5 т=0xD4 а=0xC1 л=0xCC ь=0xD8
  const std::string koi8 = "%MAIN\nG0 X1 $ \xE4\xC5\xD4\xC1\xCC\xD8\nM2\n%\n";
  const std::string utf8 = "%MAIN\nG0 X1 $ Деталь\nM2\n%\n";
  Parsed a = parseWl4(koi8, front::Encoding::Koi8R);
  Parsed b = parseWl4(utf8, front::Encoding::Utf8);
  ASSERT_TRUE(a.errors().empty()) << a.rendered();
  ASSERT_TRUE(b.errors().empty()) << b.rendered();
  EXPECT_EQ(printedWl4(a), printedWl4(b));
  EXPECT_EQ(a.blocks[1].comments[0].text, " Деталь");
}

} // namespace
} // namespace gcx::test
