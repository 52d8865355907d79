// The macro evaluator against nct-macro.md §2.5, §3 and the test vectors of §10 (TV-01 … TV-07),
// with programs parsed by the real front end and assignments executed in order.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "diag/codes.h"
#include "passes/macro/evaluator.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using macro::Value;

// Variables in a map (missing = vacant), #34-#99 undefined, a few names, parameters and axes.
struct Store : macro::VariableAccess {
  explicit Store(diag::Engine& d) : diags(d) {}
  diag::Engine& diags;
  std::map<int, Value> vars;
  std::vector<std::string> prmCalls; // "id,bit,index" with - for omitted

  std::optional<Value> read(int n, const SourceRange& where) override {
    if (n < 0 || (n >= 34 && n <= 99)) {
      diags.error(diag::code::UndefinedVariable, where, "undefined variable");
      return std::nullopt;
    }
    auto it = vars.find(n);
    return it == vars.end() ? Value::empty() : it->second;
  }
  std::optional<Value> readNamed(const std::string& name, std::optional<int> index,
                                 const SourceRange& where) override {
    if (name == "EMPTY" && !index) return Value::empty();
    if (name == "PI" && !index) return Value::of(std::numbers::pi);
    if (name == "UI" && index && *index >= 0 && *index <= 31) return Value::of(*index % 2);
    diags.error(diag::code::UndefinedVariable, where, "undefined name");
    return std::nullopt;
  }
  std::optional<double> parameter(int id, std::optional<int> bit, std::optional<int> index,
                                  const SourceRange&) override {
    auto s = [](std::optional<int> v) { return v ? std::to_string(*v) : std::string("-"); };
    prmCalls.push_back(std::to_string(id) + "," + s(bit) + "," + s(index));
    return id + 0.5;
  }
  std::optional<int> axisNumber(char letter, const SourceRange& where) override {
    if (letter >= 'X' && letter <= 'Z') return letter - 'X' + 1;
    diags.error(diag::code::ForbiddenAddress, where, "no such axis");
    return std::nullopt;
  }
};

// Runs the assignments and IF-THEN statements of a program in order; stops at the first error.
struct Exec {
  diag::Engine diags{100};
  Store store{diags};
  macro::Evaluator ev{store, diags};

  explicit Exec(const std::string& text) {
    Parsed p = parseNct(text);
    EXPECT_TRUE(p.errors().empty()) << p.rendered();
    for (const ir::Block& b : p.blocks) {
      if (b.stmts.empty()) continue;
      const ir::Stmt& s = b.stmts.front();
      if (s.kind == ir::StmtKind::IfThen) {
        auto c = ev.condition(*s.cond);
        if (!c) return;
        if (!*c) continue;
      } else if (s.kind != ir::StmtKind::Assign) {
        continue;
      }
      auto n = ev.variableNumber(s.target);
      if (!n) return;
      auto v = ev.value(s.value);
      if (!v) return;
      store.vars[*n] = *v;
    }
  }

  Value at(int n) const {
    auto it = store.vars.find(n);
    return it == store.vars.end() ? Value::empty() : it->second;
  }
  double num(int n) const {
    EXPECT_FALSE(at(n).vacant) << "#" << n << " is vacant";
    return at(n).number;
  }
  bool vacant(int n) const { return at(n).vacant; }
  std::vector<std::string> codes() const {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      out.push_back(d.code);
    return out;
  }
};

std::string lines(std::initializer_list<const char*> blocks) {
  std::string s;
  for (const char* b : blocks)
    s.append(b).push_back('\n');
  return s;
}

using Codes = std::vector<std::string>;

TEST(MacroSpec_10_TV01, ArithmeticPrecedenceAndComments) {
  Exec r(lines({"#101=2", "#102=3", "#100=#101+#102", "#100=#100-3", "#100=#100+1",
                "#103=[#101+#102*5.27]/4.1", "#120=27MOD4", "#121=-27MOD4", "#122=10-2-3",
                "#123=12/2/3", "#124=2+3*4", "#1=1", "(#1=2", "#1=3)", "#2=#1", "M30"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.num(100), 3);
  EXPECT_NEAR(r.num(103), 4.34390243902439, 1e-9);
  EXPECT_EQ(r.num(120), 3);
  EXPECT_EQ(r.num(121), -3);
  EXPECT_EQ(r.num(122), 5);
  EXPECT_EQ(r.num(123), 2);
  EXPECT_EQ(r.num(124), 14);
  EXPECT_EQ(r.num(1), 1);
  EXPECT_EQ(r.num(2), 1);
}

TEST(MacroSpec_10_TV02, FunctionsAndConversions) {
  Exec r(lines({"#100=12", "#1=SQRT[#100+4]", "#2=ASIN[-0.5]", "#3=ACOS[-0.5]", "#4=ATAN[-0.5]",
                "#5=EXP1", "#6=LN2.718281828", "#7=ABS[-3.1]", "#8=FIX4.8", "#9=FIX[-6.7]",
                "#10=FUP12.1", "#11=FUP[-7.3]", "#12=FUP5", "#13=SIN90", "#14=COS90", "#15=TAN45",
                "M30"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.num(1), 4);
  EXPECT_NEAR(r.num(2), -30, 1e-9);
  EXPECT_NEAR(r.num(3), 120, 1e-9);
  EXPECT_NEAR(r.num(4), -26.56505117707799, 1e-9);
  EXPECT_NEAR(r.num(5), 2.718281828459045, 1e-9);
  EXPECT_NEAR(r.num(6), 0.9999999998311266, 1e-9);
  EXPECT_EQ(r.num(7), 3.1);
  EXPECT_EQ(r.num(8), 4);
  EXPECT_EQ(r.num(9), -6);
  EXPECT_EQ(r.num(10), 13);
  EXPECT_EQ(r.num(11), -8);
  EXPECT_EQ(r.num(12), 5);
  EXPECT_EQ(r.num(13), 1);
  EXPECT_EQ(r.num(14), 0);
  EXPECT_NEAR(r.num(15), 1, 1e-9);
}

TEST(MacroSpec_10_TV03, FunctionOperandsWithoutBrackets) {
  Exec r(lines({"#111=1", "#112=2", "#113=60", "#110=#111+#112*COS #113", "#101=0.5",
                "#114=SIN30-#101", "#116=SQRT16*2", "#117=-#112*3", "#121=5", "#122=2", "#123=10",
                "#125=0", "#126=2", "#120=COS[[[#121-#122]*#123+#125]*#126]", "M30"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_NEAR(r.num(110), 2, 1e-9);
  EXPECT_NEAR(r.num(114), 0, 1e-9);
  EXPECT_EQ(r.num(116), 8);
  EXPECT_EQ(r.num(117), -6);
  EXPECT_NEAR(r.num(120), 0.5, 1e-9);
}

TEST(MacroSpec_10_TV03, ErrorVariantsFromTheFrontEnd) {
  auto codes = [](const char* text) {
    std::vector<std::string> out;
    const Parsed p = parseNct(text);
    for (const diag::Diagnostic& d : p.diags.all())
      if (d.severity == diag::Severity::Error) out.push_back(d.code);
    return out;
  };
  EXPECT_EQ(codes("#130=[1+2\n"), Codes{"2121"});
  EXPECT_EQ(codes("#131=1+2]\n"), Codes{"2064"});
  EXPECT_EQ(codes("#132=##120\n"), Codes{"2064"});
  EXPECT_EQ(codes("#133=ROUND[1.5]\n"), Codes{"2064"});
}

TEST(MacroSpec_10_TV04, BitwiseOperations) {
  Exec r(lines({"#100=16777215", "#1=305419896", "#101=#100AND#1", "#102=-1694498816",
                "#103=#101XOR#102", "#104=[16777215AND#1]XOR[-1694498816]", "#105=NOT0",
                "#106=5OR2", "#107=6AND3", "#108=6XOR3", "#109=4294967295AND1", "M30"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.num(101), 3430008);     // 00345678h
  EXPECT_EQ(r.num(103), -1691068808); // 9B345678h read as signed 32-bit
  EXPECT_EQ(r.num(104), -1691068808);
  EXPECT_EQ(r.num(105), -1);
  EXPECT_EQ(r.num(106), 7);
  EXPECT_EQ(r.num(107), 2);
  EXPECT_EQ(r.num(108), 5);
  EXPECT_EQ(r.num(109), 1);
}

TEST(MacroSpec_10_TV04, OperandOutOfRangeIs2129) {
  Exec r("#110=4294967296OR0\n");
  EXPECT_EQ(r.codes(), Codes{"2129"});
  EXPECT_TRUE(r.vacant(110));
  // the bounds of §3.2: -(2^32-1) <= v < 2^32, checked for NOT too; vacant counts as 0
  EXPECT_TRUE(Exec("#1=-4294967295AND1\n#2=4294967295.9OR0\n#3=NOT#4\n").codes().empty());
  EXPECT_EQ(Exec("#1=-4294967296AND1\n").codes(), Codes{"2129"});
  EXPECT_EQ(Exec("#1=NOT4294967296\n").codes(), Codes{"2129"});
  Exec t("#1=1.9OR0\n#2=-1.9OR0\n#3=NOT#4\n"); // truncation toward zero
  EXPECT_EQ(t.num(1), 1);
  EXPECT_EQ(t.num(2), -1);
  EXPECT_EQ(t.num(3), -1);
}

TEST(MacroSpec_10_TV05, VacantInAssignments) {
  Exec r(lines({"#3=0", "#2=#1", "#4=#1*3", "#5=#1+#1", "#6=[#1]", "#7=-#1", "M30"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_TRUE(r.vacant(2));
  EXPECT_EQ(r.num(4), 0);
  EXPECT_EQ(r.num(5), 0);
  EXPECT_TRUE(r.vacant(6));
  EXPECT_EQ(r.num(7), 0);
}

TEST(MacroSpec_10_TV06, VacantInConditions) {
  Exec r(lines({"#2=0", "IF[#1EQ#0]#11=1", "IF[#1NE0]#12=1", "IF[#1GE#0]#13=1", "IF[#1GT0]#14=1",
                "IF[#2EQ#0]#21=1", "IF[#2NE0]#22=1", "IF[#2GE#0]#23=1", "IF[#2GT0]#24=1",
                "IF[#1LT5]#15=1", "IF[#1LE0]#16=1", "IF[#1GT-1]#17=1", "M30"}));
  EXPECT_TRUE(r.codes().empty());
  for (int n : {11, 12, 13, 14, 15, 17})
    EXPECT_EQ(r.num(n), 1) << "#" << n;
  for (int n : {21, 22, 23, 24, 16})
    EXPECT_TRUE(r.vacant(n)) << "#" << n;
}

TEST(MacroSpec_10_TV07, Indirection) {
  Exec r(lines({"#120=116", "#116=5", "#2=#[#120]", "#[#120-4]=9", "#3=#[#120+0.4]"}));
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.num(2), 5);
  EXPECT_EQ(r.num(112), 9);
  EXPECT_EQ(r.num(3), 5);
  // the full vector: #112 ends as 3.6
  Exec full(lines({"#120=116", "#116=5", "#2=#[#120]", "#[#120-4]=9", "#3=#[#120+0.4]", "#112=3.23",
                   "M#112", "#112=3.6", "M#112", "#102=1.0", "G#102 X[10/3] F100", "#104=2.5",
                   "M#104", "M30"}));
  EXPECT_EQ(full.num(112), 3.6);
}

TEST(MacroSpec_2_2, IndirectNumbersRoundHalfAwayFromZero) {
  Exec r("#116=5\n#117=7\n#1=#[116.5]\n#2=#[116.49]\n#3=#[#9]\n");
  EXPECT_EQ(r.num(1), 7);
  EXPECT_EQ(r.num(2), 5);
  EXPECT_TRUE(r.vacant(3)); // #[vacant] is #0
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(Exec("#1=#[-0.5]\n").codes(), Codes{"NCTX01"});       // -1: undefined
  EXPECT_EQ(Exec("#1=#[3000000000]\n").codes(), Codes{"NCTX01"}); // beyond int
}

// §2.5 table: all eight cells, through compare() and through IF.
TEST(MacroSpec_2_5, VacantTableEightCells) {
  using ir::RelOp;
  const Value vac = Value::empty(), zero = Value::of(0);
  EXPECT_TRUE(macro::compare(vac, RelOp::Eq, vac));
  EXPECT_FALSE(macro::compare(zero, RelOp::Eq, vac));
  EXPECT_TRUE(macro::compare(vac, RelOp::Ne, zero));
  EXPECT_FALSE(macro::compare(zero, RelOp::Ne, zero));
  EXPECT_TRUE(macro::compare(vac, RelOp::Ge, vac));
  EXPECT_FALSE(macro::compare(zero, RelOp::Ge, vac));
  EXPECT_TRUE(macro::compare(vac, RelOp::Gt, zero));
  EXPECT_FALSE(macro::compare(zero, RelOp::Gt, zero));
}

TEST(MacroSpec_2_5, VacantOrdersAsZeroPlus) {
  using ir::RelOp;
  const Value vac = Value::empty();
  const Value neg = Value::of(-1), zero = Value::of(0), tiny = Value::of(1e-300);
  for (const Value& low : {neg, zero}) {
    EXPECT_TRUE(macro::compare(vac, RelOp::Gt, low));
    EXPECT_TRUE(macro::compare(low, RelOp::Lt, vac));
    EXPECT_TRUE(macro::compare(low, RelOp::Le, vac));
    EXPECT_FALSE(macro::compare(vac, RelOp::Le, low));
  }
  EXPECT_TRUE(macro::compare(vac, RelOp::Lt, tiny));
  EXPECT_TRUE(macro::compare(tiny, RelOp::Ge, vac));
  EXPECT_FALSE(macro::compare(vac, RelOp::Ge, tiny));
  EXPECT_TRUE(macro::compare(vac, RelOp::Le, vac));
  EXPECT_FALSE(macro::compare(vac, RelOp::Lt, vac));
  EXPECT_FALSE(macro::compare(vac, RelOp::Ne, vac));
}

TEST(MacroSpec_2_5, ValueTransferKeepsVacancyOnlyForBareReferences) {
  Exec r("#2=[[#1]]\n#3=#1*1\n#4=+#1\n#5=#_EMPTY\n#6=SQRT#1\n#7=FIX#1\n#8=#1-#1\n#9=ABS#1\n");
  EXPECT_TRUE(r.codes().empty());
  EXPECT_TRUE(r.vacant(2));
  EXPECT_EQ(r.num(3), 0);
  EXPECT_TRUE(r.vacant(4)); // `+` is not stored (000:85)
  EXPECT_TRUE(r.vacant(5));
  EXPECT_EQ(r.num(6), 0);
  EXPECT_EQ(r.num(7), 0);
  EXPECT_EQ(r.num(8), 0);
  EXPECT_EQ(r.num(9), 0);
  // a condition with an operator on a vacant side compares numbers
  Exec c("IF[#1+0EQ#0]#11=1\nIF[#1+0EQ0]#12=1\nIF[[#1]EQ#0]#13=1\n");
  EXPECT_TRUE(c.vacant(11));
  EXPECT_EQ(c.num(12), 1);
  EXPECT_EQ(c.num(13), 1);
}

TEST(MacroSpec_3_2, ModHasTheSignOfTheDividend) {
  Exec r("#1=27MOD-4\n#2=-27MOD-4\n#3=7.5MOD2\n#4=-7.5MOD2\n#5=5.5MOD0.1\n#6=8MOD4\n");
  EXPECT_EQ(r.num(1), 3);
  EXPECT_EQ(r.num(2), -3);
  EXPECT_EQ(r.num(3), 1.5);
  EXPECT_EQ(r.num(4), -1.5);
  // the formula in binary64: 0.1·55 rounds to 5.5, so 0 (std::fmod gives 0.0999999999999997,
  // and a fused multiply-add -3.05e-16: clang folds the formula written here so)
  EXPECT_EQ(r.num(5), 0);
  EXPECT_EQ(r.num(6), 0);
}

TEST(MacroSpec_2_4, TrigonometryIsExactAtMultiplesOf90) {
  Exec r("#1=SIN180\n#2=COS180\n#4=SIN[-90]\n#5=COS270\n#6=SIN450\n#7=COS[-720]\n"
         "#8=TAN180\n#9=TAN[-360]\n");
  EXPECT_EQ(r.num(1), 0);
  EXPECT_EQ(r.num(2), -1);
  EXPECT_EQ(r.num(4), -1);
  EXPECT_EQ(r.num(5), 0);
  EXPECT_EQ(r.num(6), 1);
  EXPECT_EQ(r.num(7), 1);
  EXPECT_EQ(r.num(8), 0);
  EXPECT_EQ(r.num(9), 0);
}

TEST(MacroSpec_10_TV32, DomainErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"#1=SQRT[-1]", "2122"},  {"#1=TAN[90]", "2116"},       {"#1=TAN[-270]", "2116"},
      {"#1=ASIN[1.5]", "2117"}, {"#1=ACOS[-1.0001]", "2117"}, {"#1=LN0", "2118"},
      {"#1=LN[-2]", "2118"},    {"#1=LN#0", "2118"},          {"#1=5/0", "2093"},
      {"#1=5MOD#0", "2093"},    {"#1=5/[#2-#2]", "2093"},
  };
  for (const auto& [text, code] : cases) {
    Exec r(std::string(text) + "\n");
    EXPECT_EQ(r.codes(), Codes{code}) << text;
    EXPECT_TRUE(r.vacant(1)) << text;
  }
  EXPECT_TRUE(Exec("#1=ASIN1\n#2=ACOS[-1]\n#3=SQRT0\n#4=TAN89.999\n").codes().empty());
}

TEST(MacroSpec_3_4, ErrorsAreLocatedAtTheirExpression) {
  Exec r("#1=2+5/0\n");
  ASSERT_EQ(r.diags.all().size(), 1u);
  const SourceRange& at = r.diags.all()[0].range;
  EXPECT_EQ(at.begin.line, 1u);
  EXPECT_EQ(at.begin.col, 6u); // `5/0`
  EXPECT_EQ(at.length, 3u);
  Exec s("#1=1+SQRT[-4]\n");
  ASSERT_EQ(s.diags.all().size(), 1u);
  EXPECT_EQ(s.diags.all()[0].range.begin.col, 6u);
}

TEST(MacroSpec_3_3, FixTowardZeroFupAwayFromZero) {
  Exec r("#1=FIX[-0.5]\n#2=FUP[-5]\n#3=FUP0.0001\n#4=FUP[-0.0001]\n#5=FIX[-4.8]\n");
  EXPECT_EQ(r.num(1), 0);
  EXPECT_EQ(r.num(2), -5);
  EXPECT_EQ(r.num(3), 1);
  EXPECT_EQ(r.num(4), -1);
  EXPECT_EQ(r.num(5), -4);
}

TEST(MacroSpec_9_2, PrmOperandsRoundAndVacantCountsAsOmitted) {
  Exec r("#1=PRM[107,0]/[4]\n#2=PRM[#5]\n#3=PRM[2201,#9]/[1.5]\n#4=PRM[1339]/[#9]\n");
  EXPECT_EQ(r.codes(), Codes{"2064"}); // #2=PRM[#5]: the parameter number is vacant
  EXPECT_EQ(r.num(1), 107.5);
  Exec t("#1=PRM[107,0]/[4]\n#3=PRM[2201,#9]/[1.5]\n#4=PRM[1339]/[#9]\n");
  EXPECT_TRUE(t.codes().empty());
  EXPECT_EQ(t.store.prmCalls, (std::vector<std::string>{"107,0,4", "2201,-,2", "1339,-,-"}));
}

TEST(MacroSpec_3_3, AxnumDelegatesToTheChannel) {
  Exec r("#1=AXNUM[Y]\n#2=AXNUM[z]\n");
  EXPECT_EQ(r.num(1), 2);
  EXPECT_EQ(r.num(2), 3);
  EXPECT_EQ(Exec("#1=AXNUM[B]\n").codes(), Codes{"2017"});
}

TEST(MacroSpec_2_2, NamedVariablesAndIndices) {
  Exec r("#1=#_PI\n#2=#_UI[2.5]\n#3=#_UI[#9]\n");
  EXPECT_EQ(r.num(1), std::numbers::pi);
  EXPECT_EQ(r.num(2), 1); // index 3
  EXPECT_EQ(r.num(3), 0); // vacant index = 0
  EXPECT_EQ(Exec("#1=#50\n").codes(), Codes{"NCTX01"});
}

} // namespace
} // namespace gcx::test
