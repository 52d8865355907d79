// LinuxCNC text of IR expressions (dialects/ngc/expression.h): operators and functions with the
// same meaning spelled LinuxCNC's way, every operation bracketed, the others refused with why.
#include <gtest/gtest.h>

#include "dialects/ngc/expression.h"

namespace gcx::ngc {
namespace {

ir::Expr num(double v) {
  return ir::Expr::literal(v);
}
ir::Expr var(int n) {
  return ir::Expr::variable(n);
}
ir::Expr binary(ir::Op op, ir::Expr a, ir::Expr b) {
  ir::Expr e;
  e.kind = ir::ExprKind::Binary;
  e.op = op;
  e.args = {std::move(a), std::move(b)};
  return e;
}
ir::Expr call(ir::Func f, ir::Expr a) {
  ir::Expr e;
  e.kind = ir::ExprKind::Call;
  e.func = f;
  e.args = {std::move(a)};
  return e;
}
ir::Expr neg(ir::Expr a) {
  ir::Expr e;
  e.kind = ir::ExprKind::Unary;
  e.op = ir::Op::Neg;
  e.args = {std::move(a)};
  return e;
}

// every variable as #n, except #7, which has no LinuxCNC form here
const VariableText kVars = [](int n, std::string& why) -> std::string {
  if (n == 7) {
    why = "no #7";
    return {};
  }
  return "#" + std::to_string(n);
};

std::string text(const ir::Expr& e) {
  std::string out, why;
  EXPECT_TRUE(expressionText(e, kVars, out, why)) << why;
  return out;
}

std::string refused(const ir::Expr& e) {
  std::string out, why;
  EXPECT_FALSE(expressionText(e, kVars, out, why)) << out;
  return why;
}

TEST(NgcExpression, EveryOperationInItsOwnBrackets) {
  EXPECT_EQ(text(binary(ir::Op::Add, var(3),
                        binary(ir::Op::Div, binary(ir::Op::Mul, var(5), num(360)), var(1)))),
            "[#3+[[#5*360]/#1]]");
  EXPECT_EQ(text(binary(ir::Op::Le, var(1), num(-2))), "[#1 LE -2]");
  EXPECT_EQ(text(binary(ir::Op::LogicalAnd, var(1), var(2))), "[#1 AND #2]");
  EXPECT_EQ(text(binary(ir::Op::FloorMod, var(1), num(3))), "[#1 MOD 3]");
}

TEST(NgcExpression, NegationOfANumberIsTheNumberOfAnythingElseATimesMinusOne) {
  EXPECT_EQ(text(neg(num(15))), "-15");
  EXPECT_EQ(text(neg(var(2))), "[-1*#2]");
}

// NCT FIX truncates and FUP rounds away from zero; LinuxCNC's FIX floors and FUP ceils.
TEST(NgcExpression, TruncationIsFloorForPositivesAndCeilingForNegatives) {
  EXPECT_EQ(text(call(ir::Func::Fix, var(1))), "[[FIX[#1]*[#1 GE 0]]+[FUP[#1]*[#1 LT 0]]]");
  EXPECT_EQ(text(call(ir::Func::Fup, var(1))), "[[FIX[#1]*[#1 LT 0]]+[FUP[#1]*[#1 GE 0]]]");
  EXPECT_EQ(text(call(ir::Func::Floor, var(1))), "FIX[#1]");
  EXPECT_EQ(text(call(ir::Func::Ceil, var(1))), "FUP[#1]");
}

TEST(NgcExpression, FunctionsOfTheSameMeaning) {
  EXPECT_EQ(text(call(ir::Func::Cos, var(6))), "COS[#6]");
  EXPECT_EQ(text(call(ir::Func::Round, var(6))), "ROUND[#6]");
  EXPECT_EQ(text(call(ir::Func::Atan, var(6))), "ATAN[#6]/[1]"); // LinuxCNC's ATAN takes y/x
}

TEST(NgcExpression, OperatorsOfAnotherMeaningAreRefused) {
  EXPECT_EQ(refused(binary(ir::Op::Mod, var(1), num(3))),
            "NCT MOD keeps the dividend's sign, LinuxCNC MOD is never negative");
  EXPECT_EQ(refused(binary(ir::Op::And, var(1), num(3))),
            "NCT AND/OR/XOR are bitwise, LinuxCNC's logical");
  EXPECT_EQ(refused(binary(ir::Op::Add, var(1), var(7))), "no #7");
}

TEST(NgcExpression, AWordValueIsANumberAParameterOrBrackets) {
  std::string out, why;
  ir::Word w;
  w.kind = ir::ValueKind::Expression;
  w.expr = call(ir::Func::Sin, var(6));
  EXPECT_TRUE(wordValueText(w, kVars, out, why));
  EXPECT_EQ(out, "[SIN[#6]]");
  out.clear();
  w.expr = neg(num(8));
  EXPECT_TRUE(wordValueText(w, kVars, out, why));
  EXPECT_EQ(out, "-8");
}

} // namespace
} // namespace gcx::ngc
