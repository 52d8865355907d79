// IR v2 holds every construct of the WL4 grammar (wl4.md §6.8), built by hand as its front end
// will build it: what the IR keeps, in which order, and what gcx dump shows. The expressions'
// values are checked in tests/macro/wl4_expression_test.cpp.
#include <gtest/gtest.h>

#include "ir/dump.h"
#include "ir/items.h"
#include "support/hand_built_ir.h"

namespace gcx::test {
namespace {

using hand::bin;
using hand::num;
using hand::paren;
using hand::var;
using hand::word;
using ir::ExprKind;
using ir::ItemKind;
using ir::ItemRef;
using ir::Op;

std::string dump(const ir::Block& b) {
  return ir::toJson(b, true).dump();
}

using hand::guard;
using hand::jump;

TEST(Wl4Grammar_6_8, SeveralProgramsInOneFile) {
  // file = { "%" name EOL { line } "%" EOL }: a file is a sequence of named programs (§1.2)
  const std::vector<ir::Block> file = {
      hand::Block(ir::BlockKind::ProgramStart).name("MAIN_1").done(),
      hand::Block().add("L", "07").done(),
      hand::Block().add("M", "2").done(),
      hand::Block(ir::BlockKind::ProgramEnd).done(),
      hand::Block(ir::BlockKind::ProgramStart).name("07").done(),
      hand::Block().add("M", "99").done(),
      hand::Block(ir::BlockKind::ProgramEnd).done(),
  };
  std::vector<std::string> names;
  for (const ir::Block& b : file)
    if (b.kind == ir::BlockKind::ProgramStart) names.push_back(b.programName);
  EXPECT_EQ(names, (std::vector<std::string>{"MAIN_1", "07"}));
  EXPECT_EQ(dump(file[4]), R"({"kind":"program-start","program":"07"})");
  EXPECT_EQ(dump(file[6]), R"({"kind":"program-end"})");
}

TEST(Wl4Grammar_6_8, BlockSkip) {
  // `/` before N: one level only (§1.7)
  const ir::Block b = hand::Block().skip().sequence("23").add("G", "0").add("Z", "100").done();
  EXPECT_EQ(b.skipLevel, 1);
  EXPECT_EQ(dump(b).substr(0, 30), R"({"n":23,"n_text":"23","skip":1)");
}

TEST(Wl4Grammar_6_8, LabelIsNotAPlainBlockNumber) {
  // N010 is label 10, N10 cannot be jumped to (§1.8): the value alone cannot tell them apart
  const ir::Block label = hand::Block().sequence("010").add("X", "1").done();
  const ir::Block plain = hand::Block().sequence("10").add("X", "1").done();
  EXPECT_EQ(label.sequence, plain.sequence);
  EXPECT_EQ(label.sequenceText, "010");
  EXPECT_EQ(plain.sequenceText, "10");
  EXPECT_NE(dump(label), dump(plain));
}

TEST(Wl4Grammar_6_8, NWordThatIsNotFirstIsAJump) {
  // `N15 Z0 N17` moves, then continues at N017 (§6.6)
  const ir::Block b = hand::Block().sequence("15").add("Z", "0").add(jump("17")).done();
  EXPECT_EQ(b.sequence, 15);
  EXPECT_EQ(b.find('N'), nullptr);
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(b.stmts[0].label, "17");
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{{ItemKind::Word, 0}, {ItemKind::Stmt, 0}}));
  EXPECT_EQ(dump(b), R"({"n":15,"n_text":"15","stmt":{"kind":"jump","label":"17","value":)"
                     R"({"kind":"number","value":17.0}},"words":[{"address":"Z","text":"0",)"
                     R"("value":0.0}]})");
}

TEST(Wl4Grammar_6_8, LWordIsProgramAndRepeatCount) {
  // `L0703` calls %07 three times; as a word it keeps its digits, as a call it is split (§6.7)
  const ir::Block asWord = hand::Block().add("L", "0703").done();
  EXPECT_EQ(asWord.words[0].text, "0703");
  EXPECT_EQ(asWord.words[0].number, 703);
  ir::Stmt call = hand::stmt(ir::StmtKind::Call);
  call.callee = "07";
  call.value = num(3);
  const ir::Block asCall = hand::Block().add("G", "90").add(std::move(call)).done();
  EXPECT_EQ(asCall.stmts[0].callee, "07");
  EXPECT_EQ(asCall.stmts[0].value.number, 3);
}

TEST(Wl4Grammar_6_8, ValueForms) {
  // value = [+|-] (number | varref ["=" factor] | "(" expr ")") (§1.5)
  const ir::Block b =
      hand::Block()
          .add("X", "-5")                                                // signed number
          .add(word("Z", var(2)))                                        // Z#2
          .add(word("A", hand::indirect(bin(Op::Add, var(20), num(1))))) // A#(#20+1)
          .add(word("Y", paren(bin(Op::Add, var(1011), num(6.54)))))     // Y(#1011+6.54)
          .add(word("U", hand::unary(Op::Neg, paren(bin(Op::Add, var(23), var(2)))))) // U-(#23+#2)
          .add(word("W", hand::assign(var(25), paren(bin(Op::Sub, var(24), var(27))))))
          .done(); // W#25=(#24-#27)
  ASSERT_EQ(b.words.size(), 6u);
  EXPECT_EQ(b.words[0].text, "-5");
  EXPECT_EQ(b.words[1].expr.kind, ExprKind::Variable);
  EXPECT_EQ(b.words[2].expr.kind, ExprKind::Indirect);
  EXPECT_EQ(b.words[3].expr.kind, ExprKind::Bracket);
  EXPECT_EQ(b.words[4].expr.kind, ExprKind::Unary);
  EXPECT_EQ(b.words[4].expr.args[0].kind, ExprKind::Bracket);
  EXPECT_EQ(b.words[5].expr.kind, ExprKind::Assign);
  EXPECT_EQ(ir::toJson(b.words[5].expr, false).dump(),
            R"({"args":[{"kind":"variable","value":25.0},{"args":[{"args":[{"kind":"variable",)"
            R"("value":24.0},{"kind":"variable","value":27.0}],"kind":"binary","op":"-"}],"kind":)"
            R"("bracket"}],"kind":"assign"})");
}

TEST(Wl4Grammar_6_8, StatementsAnywhereInTheBlockInSourceOrder) {
  // `N10 G90 G0 X#1 Z#2 #1=(#1+#3) #2=(#2+#4)`: X and Z use the old #1 and #2 (§1.9, TV6)
  const ir::Block b = hand::Block()
                          .sequence("10")
                          .add("G", "90")
                          .add("G", "0")
                          .add(word("X", var(1)))
                          .add(word("Z", var(2)))
                          .add(hand::assignment(var(1), paren(bin(Op::Add, var(1), var(3)))))
                          .add(hand::assignment(var(2), paren(bin(Op::Add, var(2), var(4)))))
                          .done();
  ASSERT_EQ(b.stmts.size(), 2u);
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{{ItemKind::Word, 0},
                                                {ItemKind::Word, 1},
                                                {ItemKind::Word, 2},
                                                {ItemKind::Word, 3},
                                                {ItemKind::Stmt, 0},
                                                {ItemKind::Stmt, 1}}));
  // two statements dump as a list
  EXPECT_EQ(ir::toJson(b, false)["stmts"].size(), 2u);
}

TEST(Wl4Grammar_6_8, AssignmentBeforeWords) {
  // `N010 #1=(#1+1) G1 X(#1*10) F100` (TV7): the assignment comes first, so X sees the new #1
  const ir::Block b = hand::Block()
                          .sequence("010")
                          .add(hand::assignment(var(1), paren(bin(Op::Add, var(1), num(1)))))
                          .add("G", "1")
                          .add(word("X", paren(bin(Op::Mul, var(1), num(10)))))
                          .add("F", "100")
                          .done();
  EXPECT_EQ(
      ir::items(b),
      (std::vector<ItemRef>{
          {ItemKind::Stmt, 0}, {ItemKind::Word, 0}, {ItemKind::Word, 1}, {ItemKind::Word, 2}}));
}

TEST(Wl4Grammar_6_8, IfWithPrecisionGuardsTheRestOfTheBlock) {
  // `N10 IF3 (#1>=#2) #1=(#1-0.5) N1` (§6.5): the assignment and the jump depend on the guard
  const ir::Block b = hand::Block()
                          .sequence("10")
                          .add(guard(paren(bin(Op::Ge, var(1), var(2))), 3))
                          .add(hand::assignment(var(1), paren(bin(Op::Sub, var(1), num(0.5)))))
                          .add(jump("1"))
                          .done();
  ASSERT_EQ(b.stmts.size(), 3u);
  EXPECT_EQ(b.stmts[0].kind, ir::StmtKind::Guard);
  EXPECT_EQ(b.stmts[0].precision, 3);
  EXPECT_EQ(b.stmts[0].value.args[0].op, Op::Ge);
  // what the guard covers: every item after it
  std::vector<ItemRef> guarded;
  bool after = false;
  ir::forEachItem(b, [&](ItemRef r) {
    if (after) guarded.push_back(r);
    after |= r.kind == ItemKind::Stmt && b.stmts[r.index].kind == ir::StmtKind::Guard;
  });
  EXPECT_EQ(guarded, (std::vector<ItemRef>{{ItemKind::Stmt, 1}, {ItemKind::Stmt, 2}}));
  EXPECT_EQ(ir::toJson(b, false)["stmts"][0]["precision"], 3);
}

TEST(Wl4Grammar_6_8, IfWithoutPrecisionAfterWords) {
  // `N20 G1 X0 Z100 F500 IF ((#1-#2)>0) Z0`: words before the guard run anyway (TV8)
  const ir::Block b =
      hand::Block()
          .sequence("20")
          .add("G", "1")
          .add("X", "0")
          .add("Z", "100")
          .add("F", "500")
          .add(guard(paren(bin(Op::Gt, paren(bin(Op::Sub, var(1), var(2))), num(0)))))
          .add("Z", "0")
          .done();
  EXPECT_FALSE(b.stmts[0].precision);
  EXPECT_LT(b.words[3].order, b.stmts[0].order);
  EXPECT_GT(b.words[4].order, b.stmts[0].order);
  EXPECT_EQ(ir::toJson(b, false)["stmt"].dump(),
            R"({"kind":"guard","value":{"args":[{"args":[{"args":[{"args":[{"kind":"variable",)"
            R"("value":1.0},{"kind":"variable","value":2.0}],"kind":"binary","op":"-"}],"kind":)"
            R"("bracket"},{"kind":"number","value":0.0}],"kind":"binary","op":">"}],"kind":)"
            R"("bracket"}})");
}

TEST(Wl4Grammar_6_8, EmbeddedAssignmentInsideAnExpression) {
  // `X#1=(ABS(#3-#4) + #5=(40.78*#2))` (002:1988)
  const ir::Expr e = hand::assign(
      var(1), paren(bin(Op::Add, hand::call(ir::Func::Abs, paren(bin(Op::Sub, var(3), var(4)))),
                        hand::assign(var(5), paren(bin(Op::Mul, num(40.78), var(2)))))));
  const ir::Block b = hand::Block().add(word("X", e)).done();
  const ir::Expr& sum = b.words[0].expr.args[1].args[0];
  EXPECT_EQ(sum.op, Op::Add);
  EXPECT_EQ(sum.args[1].kind, ExprKind::Assign);
  EXPECT_EQ(sum.args[1].args[0].number, 5);
}

TEST(Wl4Grammar_6_8, EveryOperatorIsDistinct) {
  // op1 = ** * / MOD; op2 = + - == <> <= >= < > AND OR XOR: WL4's MOD, AND, OR, XOR are not
  // NCT's, so they are other operators of the IR
  const std::vector<std::pair<Op, const char*>> ops = {
      {Op::Pow, "**"},        {Op::Mul, "*"},
      {Op::Div, "/"},         {Op::FloorMod, "FLOORMOD"},
      {Op::Add, "+"},         {Op::Sub, "-"},
      {Op::Eq, "=="},         {Op::Ne, "<>"},
      {Op::Le, "<="},         {Op::Ge, ">="},
      {Op::Lt, "<"},          {Op::Gt, ">"},
      {Op::LogicalAnd, "&&"}, {Op::LogicalOr, "||"},
      {Op::LogicalXor, "^^"}};
  for (const auto& [op, spelled] : ops) {
    EXPECT_STREQ(ir::spelling(op), spelled);
    EXPECT_EQ(ir::toJson(bin(op, var(1), var(2)), false)["op"], spelled);
  }
  EXPECT_STRNE(ir::spelling(Op::LogicalAnd), ir::spelling(Op::And));
  EXPECT_STRNE(ir::spelling(Op::FloorMod), ir::spelling(Op::Mod));
}

TEST(Wl4Grammar_6_8, EveryFunction) {
  // func = ABS COS ACOS SIN ASIN TAN EXP FIX FUP LN ROUND SQRT, and ATAN(a)/(b)
  const std::vector<std::pair<ir::Func, const char*>> funcs = {
      {ir::Func::Abs, "ABS"}, {ir::Func::Cos, "COS"},     {ir::Func::Acos, "ACOS"},
      {ir::Func::Sin, "SIN"}, {ir::Func::Asin, "ASIN"},   {ir::Func::Tan, "TAN"},
      {ir::Func::Exp, "EXP"}, {ir::Func::Floor, "FLOOR"}, {ir::Func::Ceil, "CEIL"},
      {ir::Func::Ln, "LN"},   {ir::Func::Round, "ROUND"}, {ir::Func::Sqrt, "SQRT"}};
  for (const auto& [f, spelled] : funcs)
    EXPECT_EQ(ir::toJson(hand::call(f, paren(var(1))), false)["func"], spelled);
  const ir::Expr a = hand::atan2(paren(num(1)), paren(num(-1)));
  EXPECT_EQ(a.args.size(), 2u);
  EXPECT_EQ(ir::toJson(a, false).dump(),
            R"({"args":[{"args":[{"kind":"number","value":1.0}],"kind":"bracket"},{"args":[{)"
            R"("kind":"number","value":-1.0}],"kind":"bracket"}],"func":"ATAN2","kind":"call"})");
}

TEST(Wl4Grammar_6_8, DollarCommentAtTheEndAndAsALine) {
  // `$` ends the commands of a block; a line starting with `$` is a comment line (§1.6)
  const ir::Block tail =
      hand::Block().add("G", "0").add("X", "0").comment(ir::CommentKind::ToLineEnd, " HOME").done();
  EXPECT_EQ(ir::items(tail).back(), (ItemRef{ItemKind::Comment, 0}));
  EXPECT_EQ(ir::toJson(tail, false)["comments"].dump(), R"([{"to-line-end":" HOME"}])");
  const ir::Block line =
      hand::Block(ir::BlockKind::CommentLine).comment(ir::CommentKind::ToLineEnd, "PART 7").done();
  EXPECT_EQ(dump(line), R"({"comments":[{"to-line-end":"PART 7"}],"kind":"comment-line"})");
}

TEST(Wl4Grammar_6_8, DotMessage) {
  // `N010 M0 N10 .ERROR > UNKNOWN CYCLE IN RANGE G70-G79` (002:3489)
  const ir::Block b =
      hand::Block()
          .sequence("010")
          .add("M", "0")
          .add(jump("10"))
          .comment(ir::CommentKind::Message, "ERROR > UNKNOWN CYCLE IN RANGE G70-G79")
          .done();
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{
                              {ItemKind::Word, 0}, {ItemKind::Stmt, 0}, {ItemKind::Comment, 0}}));
  EXPECT_EQ(b.comments[0].kind, ir::CommentKind::Message);
  EXPECT_EQ(ir::toJson(b, false)["comments"].dump(),
            R"([{"message":"ERROR > UNKNOWN CYCLE IN RANGE G70-G79"}])");
  const ir::Block alone = hand::Block(ir::BlockKind::CommentLine)
                              .comment(ir::CommentKind::Message, "********* G31 ********")
                              .done();
  EXPECT_EQ(alone.kind, ir::BlockKind::CommentLine);
}

} // namespace
} // namespace gcx::test
