// NC words with variable values: nct-macro.md §2.5 rule 4 (vacant drops the word), §2.6
// (rounding per address, range check NCTX04) and the expanded blocks of TV-05 and TV-07.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "diag/codes.h"
#include "dialects/nct/word_value_rules.h"
#include "emit/number.h"
#include "passes/macro/word_values.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using macro::Value;
using macro::WordResult;

// NCT's address table (the dialect's ControlFlow::wordValues), the rules these sections test.
const WordValueRules& nctRules() {
  static const WordValueRules rules = nct::wordValueRules();
  return rules;
}
macro::WordOptions withNct(macro::WordOptions opt) {
  if (!opt.rules) opt.rules = &nctRules();
  return opt;
}

struct Store : macro::VariableAccess {
  std::map<int, Value> vars;
  std::optional<Value> read(int n, const SourceRange&) override {
    auto it = vars.find(n);
    return it == vars.end() ? Value::empty() : it->second;
  }
  std::optional<Value> readNamed(const std::string& name, std::optional<int>,
                                 const SourceRange&) override {
    return name == "EMPTY" ? Value::empty() : Value::of(7);
  }
  std::optional<double> parameter(int, std::optional<int>, std::optional<int>,
                                  const SourceRange&) override {
    return 0;
  }
  std::optional<int> axisNumber(char, const SourceRange&) override { return 1; }
};

// Executes assignments in order and expands NC blocks to text (§10 "expanded blocks"); M30 ends.
struct Exec {
  diag::Engine diags{100};
  Store store;
  macro::Evaluator ev{store, diags};
  std::vector<std::string> expanded;

  explicit Exec(const std::string& text, const macro::WordOptions& opt = {}) {
    Parsed p = parseNct(text);
    EXPECT_TRUE(p.errors().empty()) << p.rendered();
    for (const ir::Block& b : p.blocks) {
      if (!b.stmts.empty()) {
        auto n = ev.variableNumber(b.stmts.front().target);
        auto v = n ? ev.value(b.stmts.front().value) : std::nullopt;
        if (!v) return;
        store.vars[*n] = *v;
        continue;
      }
      if (b.words.size() == 1 && b.words[0].is('M') && b.words[0].isLiteral() &&
          b.words[0].number == 30)
        return;
      std::string line;
      for (const ir::Word& w : b.words) {
        const macro::WordValue r = macro::wordValue(w, ev, withNct(opt));
        if (r.result == WordResult::Error) return;
        if (r.result == WordResult::Dropped) continue;
        line += (line.empty() ? "" : " ") + w.address + (w.incremental ? "I" : "") +
                emit::formatNumber(r.number);
      }
      if (!line.empty()) expanded.push_back(line);
    }
  }
  std::vector<std::string> codes() const {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      out.push_back(d.code);
    return out;
  }
};

using Lines = std::vector<std::string>;

// One word `text` (an NC block of one word) after `setup` assignments.
macro::WordValue word(const std::string& setup, const std::string& text,
                      const macro::WordOptions& opt = {}, diag::Engine* out = nullptr) {
  Parsed p = parseNct(setup + text + "\n", {.staticChecks = false});
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  diag::Engine diags;
  Store store;
  macro::Evaluator ev(store, out ? *out : diags);
  for (const ir::Block& b : p.blocks) {
    if (b.stmts.empty()) return macro::wordValue(b.words.at(0), ev, withNct(opt));
    store.vars[*ev.variableNumber(b.stmts.front().target)] = *ev.value(b.stmts.front().value);
  }
  return {};
}

TEST(MacroSpec_10_TV05, VacantInAddresses) {
  Exec r("#3=0\n#2=#1\n#4=#1*3\n#5=#1+#1\n#6=[#1]\n#7=-#1\nG90 G0 X20 Y#1\nG90 G0 X20 Y#3\n"
         "G0 X-#1 Y[#1+10] Z#3\nG0 XI#1 Y5\nM30\n");
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.expanded, (Lines{"G90 G0 X20", "G90 G0 X20 Y0", "G0 Y10 Z0", "G0 Y5"}));
}

TEST(MacroSpec_10_TV07, IndirectionAndAddressRounding) {
  Exec r("#120=116\n#116=5\n#2=#[#120]\n#[#120-4]=9\n#3=#[#120+0.4]\n#112=3.23\nM#112\n"
         "#112=3.6\nM#112\n#102=1.0\nG#102 X[10/3] F100\n#104=2.5\nM#104\nM30\n");
  EXPECT_TRUE(r.codes().empty());
  EXPECT_EQ(r.expanded, (Lines{"M3", "M4", "G1 X3.333333 F100", "M3"}));
}

TEST(MacroSpec_10_TV07, OutOfRangeIsNCTX04) {
  Exec r("#112=123456789\nM#112\nM30\n");
  EXPECT_EQ(r.codes(), std::vector<std::string>{"NCTX04"});
  ASSERT_EQ(r.diags.all().size(), 1u);
  EXPECT_EQ(r.diags.all()[0].range.begin.line, 2u); // located at the word `M#112`
  EXPECT_EQ(r.diags.all()[0].range.length, 5u);
}

TEST(MacroSpec_2_5, SignedAndIndirectBareReferencesDrop) {
  for (const char* text : {"X-#1", "XI-#1", "X+#1", "X#[#5]", "X#_EMPTY", "G#1", "M#1", "F#9"})
    EXPECT_EQ(word("", text).result, WordResult::Dropped) << text;
  for (const char* text : {"X[#1]", "X-[#1]", "Y[#1+10]", "X[-#1]"})
    EXPECT_EQ(word("", text).result, WordResult::Value) << text;
  EXPECT_EQ(word("", "Y[#1+10]").number, 10);
  const macro::WordValue z = word("#3=0\n", "X-#3"); // -0 comes out as 0
  EXPECT_EQ(z.number, 0);
  EXPECT_FALSE(std::signbit(z.number));
}

TEST(MacroSpec_2_6, IncrementalOperatorWithNegatedVariable) {
  Exec r("#24=135.342\nG0 XI-#24\nM30\n"); // 000:11854-11855
  EXPECT_EQ(r.expanded, (Lines{"G0 XI-135.342"}));
}

TEST(MacroSpec_2_6, RoundingPerAddress) {
  EXPECT_EQ(word("#1=84.2\n", "G#1").number, 84.2);
  EXPECT_EQ(word("#1=1.04\n", "G#1").number, 1);
  EXPECT_EQ(word("#1=84.25\n", "G#1").number, 84.3);
  EXPECT_EQ(word("", "X[1/3]").number, 0.333333);
  EXPECT_EQ(word("", "X[-2/3]").number, -0.666667);
  EXPECT_EQ(word("", ",C[1/3]").number, 0.333333);
  EXPECT_EQ(word("", "AX[1]=[1/3]").number, 0.333333);
  EXPECT_EQ(word("", "X[1/3]", {.resolution = 1e-7}).number, 0.3333333);
  EXPECT_EQ(word("", "F[1/3]").number, 1.0 / 3);
  EXPECT_EQ(word("", "Q[1/3]").number, 1.0 / 3);
  EXPECT_EQ(word("", "P[1/3]").number, 1.0 / 3);
  EXPECT_EQ(word("", "S[1/3]").number, 1.0 / 3);
  EXPECT_EQ(word("#1=11.5\n", "P#1", {.resolution = {}, .callNumber = true}).number, 12);
  EXPECT_EQ(word("#1=11.5\n", "S#1", {.resolution = {}, .callNumber = true}).number, 12);
  EXPECT_EQ(word("#1=-2.5\n", "X#1").number, -2.5);
  EXPECT_EQ(word("#1=-0.25\n", "X#1", {.resolution = 0.5}).number, -0.5); // tie away from 0
  EXPECT_EQ(word("#1=0.25\n", "X#1", {.resolution = 0.5}).number, 0.5);
  for (const char* a : {"T", "H", "D", "L"})
    EXPECT_EQ(word("#1=2.5\n", std::string(a) + "#1").number, 3) << a;
}

TEST(MacroSpec_2_6, AddressTableRows) {
  const WordValueRules& t = nctRules();
  EXPECT_EQ(t.find("M", false).rounding, Rounding::Integer);
  EXPECT_EQ(t.find("G", false).rounding, Rounding::Tenth);
  EXPECT_EQ(t.find("E", false).rounding, Rounding::Resolution);
  EXPECT_EQ(t.find("P", false).rounding, Rounding::None);
  EXPECT_EQ(t.find("P", true).rounding, Rounding::Integer);
  EXPECT_EQ(t.find("F", true).rounding, Rounding::None);
  EXPECT_EQ(t.find("XDE", false).rounding, Rounding::Resolution);
  EXPECT_EQ(t.find("H", false).max, 999);
}

TEST(MacroSpec_2_6, RangeCheckAfterRounding) {
  const std::pair<const char*, const char*> bad[] = {
      {"#1=-1\n", "H#1"}, {"#1=999.5\n", "D#1"},     {"#1=-3\n", "M#1"}, {"#1=-1\n", "T#1"},
      {"#1=-1\n", "L#1"}, {"#1=100000000\n", "T#1"}, {"#1=-1\n", "G#1"}, {"#1=-5\n", "F#1"},
      {"#1=0\n", "P#1"},  {"#1=-1\n", "S#1"},
  };
  for (const auto& [setup, text] : bad) {
    diag::Engine diags;
    const bool call = text[0] == 'P';
    EXPECT_EQ(word(setup, text, {.resolution = {}, .callNumber = call}, &diags).result, WordResult::Error) << text;
    ASSERT_EQ(diags.all().size(), 1u) << text;
    EXPECT_EQ(diags.all()[0].code, std::string("NCTX04")) << text;
  }
  // documented zeros pass (M0, H0, D0, M99 L0; T0 by analogy, §12 Q29), and so does -0.4
  for (const char* text : {"M#1", "H#1", "D#1", "L#1", "T#1"}) {
    EXPECT_EQ(word("#1=0\n", text).result, WordResult::Value) << text;
    EXPECT_EQ(word("#1=-0.4\n", text).result, WordResult::Value) << text;
  }
  EXPECT_EQ(word("#1=99999999\n", "M#1").number, 99999999);
  EXPECT_EQ(word("#1=-4\n", "P#1").number, -4); // P as auxiliary data keeps its sign
}

TEST(MacroSpec_2_6, SequenceNumbersAreWholeFrom1) { // N as a G65 argument or jump target
  diag::Engine diags;
  EXPECT_EQ(macro::addressValue(2.5, "N", {}, diags, withNct({})), 3);
  EXPECT_EQ(macro::addressValue(0.4, "N", {}, diags, withNct({})), std::nullopt);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, std::string("NCTX04"));
}

TEST(MacroSpec_2_6, EvaluationErrorsPassThrough) {
  diag::Engine diags;
  EXPECT_EQ(word("", "X[1/0]", {}, &diags).result, WordResult::Error);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, std::string("2093"));
}

TEST(MacroSpec_2_6, LiteralWordsPassUnchanged) {
  const macro::WordValue v = word("", "X1.23456789");
  EXPECT_EQ(v.result, WordResult::Value);
  EXPECT_EQ(v.number, 1.23456789);
}

} // namespace
} // namespace gcx::test
