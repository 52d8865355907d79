// The evaluator on the expression nodes WL4 needs (wl4.md §6.3-§6.5, test vectors TV6, TV22),
// with trees built by hand as WL4's front end will build them: left to right inside each of the
// two precedence levels.
#include <gtest/gtest.h>

#include <map>

#include "diag/codes.h"
#include "passes/macro/evaluator.h"
#include "support/hand_built_ir.h"

namespace gcx::test {
namespace {

using hand::atan2;
using hand::bin;
using hand::call;
using hand::num;
using hand::paren;
using hand::var;
using ir::Func;
using ir::Op;
using macro::Value;

// Numbered variables only, 0 until written (WL4 has no vacant state, wl4.md §6.1).
struct NumberedStore : macro::VariableAccess {
  std::map<int, double> vars;

  std::optional<Value> read(int n, const SourceRange&) override { return Value::of(vars[n]); }
  std::optional<Value> readNamed(const std::string&, std::optional<int>,
                                 const SourceRange&) override {
    return std::nullopt;
  }
  std::optional<double> parameter(int, std::optional<int>, std::optional<int>,
                                  const SourceRange&) override {
    return std::nullopt;
  }
  std::optional<int> axisNumber(char, const SourceRange&) override { return std::nullopt; }
};

// WL4 assigns inside expressions.
struct Wl4Store : NumberedStore {
  std::vector<int> writes;

  bool assignsInExpressions() const override { return true; }
  bool write(int n, const Value& v, const SourceRange&) override {
    vars[n] = v.number;
    writes.push_back(n);
    return true;
  }
};

class Wl4Expressions_6_3 : public ::testing::Test {
protected:
  diag::Engine diags{100};
  Wl4Store store;
  macro::Evaluator ev{store, diags};

  double eval(const ir::Expr& e) {
    auto v = ev.number(e);
    EXPECT_TRUE(v) << "no value";
    return v.value_or(-999999);
  }
  std::string firstError() {
    return diags.all().empty() ? std::string() : diags.all().front().code;
  }
};

TEST_F(Wl4Expressions_6_3, PowerBindsLikeMultiplicationLeftToRight) {
  // `2*3**2` = (2*3)**2 = 36: level 1 is ** * / MOD, left to right
  EXPECT_EQ(eval(bin(Op::Pow, bin(Op::Mul, num(2), num(3)), num(2))), 36);
  EXPECT_EQ(eval(bin(Op::Pow, num(2), num(10))), 1024);
  EXPECT_EQ(eval(bin(Op::Pow, num(4), num(0.5))), 2);
}

TEST_F(Wl4Expressions_6_3, PowerWithoutARealResultIsAnError) {
  EXPECT_FALSE(ev.number(bin(Op::Pow, num(-8), num(1.0 / 3))));
  EXPECT_EQ(firstError(), diag::code::ValueOutOfRange);
}

TEST_F(Wl4Expressions_6_3, RelationalOperatorsYieldOneOrZero) {
  store.vars = {{1, 2}, {2, 3}, {3, 4}, {4, 4}};
  EXPECT_EQ(eval(bin(Op::Eq, var(3), var(4))), 1);
  EXPECT_EQ(eval(bin(Op::Ne, var(3), var(4))), 0);
  EXPECT_EQ(eval(bin(Op::Lt, var(1), var(2))), 1);
  EXPECT_EQ(eval(bin(Op::Le, var(3), var(4))), 1);
  EXPECT_EQ(eval(bin(Op::Gt, var(1), var(2))), 0);
  EXPECT_EQ(eval(bin(Op::Ge, var(2), var(3))), 0);
  // `#1+#2>#3` = (#1+#2)>#3 = 5>4; `#3>#4+1` = (#3>#4)+1 = 1 (one level, left to right)
  EXPECT_EQ(eval(bin(Op::Gt, bin(Op::Add, var(1), var(2)), var(3))), 1);
  EXPECT_EQ(eval(bin(Op::Add, bin(Op::Gt, var(3), var(4)), num(1))), 1);
}

TEST_F(Wl4Expressions_6_3, LogicalOperatorsTakeNonZeroAsTrue) {
  // WL4 AND OR XOR are logical (002:1925-1956), NCT's are bitwise: 6 AND 1 differs
  EXPECT_EQ(eval(bin(Op::LogicalAnd, num(6), num(1))), 1);
  EXPECT_EQ(eval(bin(Op::And, num(6), num(1))), 0);
  EXPECT_EQ(eval(bin(Op::LogicalAnd, num(6), num(0))), 0);
  EXPECT_EQ(eval(bin(Op::LogicalOr, num(0), num(-2.5))), 1);
  EXPECT_EQ(eval(bin(Op::LogicalOr, num(0), num(0))), 0);
  EXPECT_EQ(eval(bin(Op::LogicalXor, num(6), num(1))), 0);
  EXPECT_EQ(eval(bin(Op::Xor, num(6), num(1))), 7);
  EXPECT_EQ(eval(bin(Op::LogicalXor, num(6), num(0))), 1);
}

TEST_F(Wl4Expressions_6_3, ModIsNonNegativeBelowTheDivisor) {
  // f = x - |y|*floor(x/|y|): 0 <= f < |y| (002:1937-1939); NCT's MOD keeps the dividend's sign
  EXPECT_EQ(eval(bin(Op::FloorMod, num(7), num(3))), 1);
  EXPECT_EQ(eval(bin(Op::FloorMod, num(-7), num(3))), 2);
  EXPECT_EQ(eval(bin(Op::FloorMod, num(-7), num(-3))), 2);
  EXPECT_EQ(eval(bin(Op::FloorMod, num(6), num(3))), 0);
  EXPECT_EQ(eval(bin(Op::Mod, num(-7), num(3))), -1);
  EXPECT_FALSE(ev.number(bin(Op::FloorMod, num(1), num(0))));
  EXPECT_EQ(firstError(), diag::code::DivideByZero);
}

TEST_F(Wl4Expressions_6_3, FixFloorsFupCeilsRoundGoesHalfAway) {
  EXPECT_EQ(eval(call(Func::Floor, paren(num(-2.5)))), -3);
  EXPECT_EQ(eval(call(Func::Fix, paren(num(-2.5)))), -2); // NCT FIX truncates
  EXPECT_EQ(eval(call(Func::Floor, paren(num(2.5)))), 2);
  EXPECT_EQ(eval(call(Func::Ceil, paren(num(-2.5)))), -2);
  EXPECT_EQ(eval(call(Func::Fup, paren(num(-2.5)))), -3); // NCT FUP goes away from zero
  EXPECT_EQ(eval(call(Func::Ceil, paren(num(2.1)))), 3);
  EXPECT_EQ(eval(call(Func::Round, paren(num(2.5)))), 3);
  EXPECT_EQ(eval(call(Func::Round, paren(num(-2.5)))), -3);
  EXPECT_EQ(eval(call(Func::Round, paren(num(2.4999)))), 2);
}

TEST_F(Wl4Expressions_6_3, AtanOfTwoArgumentsIsAtan2InDegrees) {
  // ATAN(a)/(b) = atan2(a, b) in (-180, 180]
  EXPECT_EQ(eval(atan2(paren(num(1)), paren(num(1)))), 45);
  EXPECT_EQ(eval(atan2(paren(num(1)), paren(num(-1)))), 135);
  EXPECT_EQ(eval(atan2(paren(num(-1)), paren(num(-1)))), -135);
  EXPECT_EQ(eval(atan2(paren(num(0)), paren(num(-1)))), 180);
  EXPECT_EQ(eval(atan2(paren(num(-0.0)), paren(num(-1)))), 180); // never -180
  EXPECT_EQ(eval(atan2(paren(num(2)), paren(num(0)))), 90);
}

TEST_F(Wl4Expressions_6_3, OtherFunctions) {
  EXPECT_EQ(eval(call(Func::Abs, paren(num(-3)))), 3);
  EXPECT_DOUBLE_EQ(eval(call(Func::Sin, paren(num(30)))), 0.5);
  EXPECT_EQ(eval(call(Func::Cos, paren(num(90)))), 0);
  EXPECT_EQ(eval(call(Func::Acos, paren(num(0)))), 90);
  EXPECT_EQ(eval(call(Func::Asin, paren(num(1)))), 90);
  EXPECT_EQ(eval(call(Func::Sqrt, paren(num(16)))), 4);
  EXPECT_EQ(eval(call(Func::Ln, paren(num(1)))), 0);
  EXPECT_EQ(eval(call(Func::Exp, paren(num(0)))), 1);
  EXPECT_FALSE(ev.number(call(Func::Asin, paren(num(2)))));
  EXPECT_EQ(firstError(), diag::code::ArcDomain);
}

using Wl4Assignment_6_4 = Wl4Expressions_6_3;

TEST_F(Wl4Assignment_6_4, EmbeddedAssignmentYieldsItsValue) {
  // TV6 N30 after N10/N20/N25: #2=60 #3=30 #4=40; `X#1=(ABS(#3-#4) + #5=(40.78*#2))`
  store.vars = {{1, 40}, {2, 60}, {3, 30}, {4, 40}, {5, 35}};
  const ir::Expr x = hand::assign(
      var(1), paren(bin(Op::Add, call(Func::Abs, paren(bin(Op::Sub, var(3), var(4)))),
                        hand::assign(var(5), paren(bin(Op::Mul, num(40.78), var(2)))))));
  EXPECT_DOUBLE_EQ(eval(x), 2456.8);
  EXPECT_DOUBLE_EQ(store.vars[5], 2446.8);
  EXPECT_DOUBLE_EQ(store.vars[1], 2456.8);
  EXPECT_EQ(store.writes, (std::vector<int>{5, 1})); // the inner one first
}

TEST_F(Wl4Assignment_6_4, RelationalInsideArithmetic) {
  // TV6 N20 `#5=(#4/2+15*(#3>#4))` = 20, N25 `#5=(#4/2+15*(#3<#4))` = 35
  store.vars = {{3, 30}, {4, 40}};
  auto tv6 = [](Op rel) {
    return paren(bin(Op::Add, bin(Op::Div, var(4), num(2)),
                     bin(Op::Mul, num(15), paren(bin(rel, var(3), var(4))))));
  };
  EXPECT_EQ(eval(tv6(Op::Gt)), 20);
  EXPECT_EQ(eval(tv6(Op::Lt)), 35);
}

TEST_F(Wl4Assignment_6_4, AssignmentBindsTighterThanOperators) {
  // `U-(#20=(#20+#21)*#3)`: #20 receives #20+#21 only (002:3578)
  store.vars = {{20, 1}, {21, 2}, {3, 10}};
  const ir::Expr u = hand::unary(
      Op::Neg,
      paren(bin(Op::Mul, hand::assign(var(20), paren(bin(Op::Add, var(20), var(21)))), var(3))));
  EXPECT_EQ(eval(u), -30);
  EXPECT_EQ(store.vars[20], 3);
}

TEST_F(Wl4Assignment_6_4, AnIndirectTargetIsEvaluatedFirst) {
  // `#(#1+1)=(#1*5)` inside an expression: target #3 when #1 = 2
  store.vars = {{1, 2}};
  EXPECT_EQ(eval(hand::assign(hand::indirect(bin(Op::Add, var(1), num(1))),
                              paren(bin(Op::Mul, var(1), num(5))))),
            10);
  EXPECT_EQ(store.vars[3], 10);
}

TEST(Wl4Assignment_6_4_Nct, NctHasNoAssignmentInsideAnExpression) {
  NumberedStore store; // as NCT: no assignment inside an expression
  diag::Engine diags{10};
  macro::Evaluator ev{store, diags};
  EXPECT_FALSE(ev.number(hand::assign(var(1), num(2))));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, diag::code::SyntaxError);
}

using Wl4Conditions_6_5 = Wl4Expressions_6_3;

TEST_F(Wl4Conditions_6_5, PrecisionRoundsTheDifference) {
  // TV22: #1=1.0004 #2=1.0001; `IF3 (#1>#2)` is false (0.0003 rounds to 0), `IF (#1>#2)` true
  store.vars = {{1, 1.0004}, {2, 1.0001}};
  const ir::Expr cond = paren(bin(Op::Gt, var(1), var(2)));
  EXPECT_EQ(ev.guard(cond, 3), false);
  EXPECT_EQ(ev.guard(cond, std::nullopt), true);
  EXPECT_EQ(ev.guard(cond, 4), true);
  // outside a guard the same relation is exact again
  EXPECT_EQ(eval(cond), 1);
}

TEST_F(Wl4Conditions_6_5, PrecisionRoundsTheFinalValue) {
  // `IF (#30)` is true for any non-zero #30; with precision 2, 0.004 rounds to 0
  store.vars = {{30, 0.004}};
  EXPECT_EQ(ev.guard(paren(var(30)), std::nullopt), true);
  EXPECT_EQ(ev.guard(paren(var(30)), 2), false);
  store.vars[30] = 0.005; // half away from zero
  EXPECT_EQ(ev.guard(paren(var(30)), 2), true);
}

TEST_F(Wl4Conditions_6_5, Tv8) {
  // `IF ((#1-#2)>0)`: true for #1=5 #2=3, false for #1=1
  store.vars = {{1, 5}, {2, 3}};
  const ir::Expr cond = paren(bin(Op::Gt, paren(bin(Op::Sub, var(1), var(2))), num(0)));
  EXPECT_EQ(ev.guard(cond, std::nullopt), true);
  store.vars[1] = 1;
  EXPECT_EQ(ev.guard(cond, std::nullopt), false);
}

} // namespace
} // namespace gcx::test
