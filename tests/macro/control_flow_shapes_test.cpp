// The control-flow engine under remap tables of other dialects' shapes (docs/control-flow.md):
// NCT's own table, FMS-3000's table of calls (fms3000.md §6.1) and a small hand-made table for
// the WL4 calls and user canned cycles (wl4.md §5.1, §6.7). The programs are written in NCT
// syntax and run through a dialect that is NCT with the other ControlFlow.
#include <gtest/gtest.h>

#include "dialect/control_flow.h"
#include "dialect/dialect.h"
#include "dialects/fms3000/control_flow.h"
#include "dialects/nct/profile.h"
#include "ir/block.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

Remap row(const char* address, std::optional<double> code, FlowAction action) {
  Remap r;
  r.address = address;
  r.code = code;
  r.action = action;
  return r;
}

// A program unit is the file `<unit>.nct` beside the caller, named "%unit" in messages.
ControlFlow namedByFile(RemapTable table) {
  ControlFlow f = *nct::profile().controlFlow;
  f.remaps = std::move(table);
  f.programFiles = [](const std::string& unit, const std::string& ext) {
    return std::vector<std::string>{unit + ext};
  };
  f.programLabel = [](const std::string& unit) { return "%" + unit; };
  return f;
}

// WL4: `L nnpp` calls %nn pp times with a copy of the caller's locals (§6.7); G81-G89 call
// %81-%89 after every block with axis words until G80 (§5.1); #1-#29 local, #30-#99 global.
ControlFlow wl4Shape() {
  RemapTable t;
  Remap l = row("L", std::nullopt, FlowAction::CallSubprogram);
  l.program = ProgramSource::CodeDigits;
  l.nameDigits = 2;
  l.frame = LocalFrame::Copy;
  t.rows.push_back(l);
  t.rows.push_back(row("M", 99, FlowAction::Return));
  Remap cycle = row("G", 81, FlowAction::ModalCall);
  cycle.last = 89;
  cycle.program = ProgramSource::CodeDigits;
  cycle.frame = LocalFrame::Copy;
  cycle.registerRunsBlock = true;
  t.rows.push_back(cycle);
  t.rows.push_back(row("G", 80, FlowAction::ModalCancel));
  ControlFlow f = namedByFile(std::move(t));
  f.variables = VariableSpace{1, 29, 30, 99};
  return f;
}

// FMS-3000's own table (dialects/fms3000/control_flow): `P<digits>` calls the program named by
// the digits as written, after the block; G<n> calls the user program G<n> when it exists,
// GG<n> is the built-in G<n>; M98 ends the program (§6.1).
ControlFlow fmsShape() {
  return namedByFile(fms3000::remapTable());
}

// NCT syntax with a hand-made control flow: the profile and dialect live as long as the test.
struct Shaped {
  static inline Profile profile;
  static const Profile& current() { return profile; }
  ControlFlow flow;
  Dialect dialect;
  explicit Shaped(ControlFlow f) : flow(std::move(f)), dialect(*findDialect("nct")) {
    profile = nct::profile();
    profile.controlFlow = &flow;
    dialect.profile = &Shaped::current;
  }
};

ir::Word word(const char* address, double value, const char* text) {
  ir::Word w;
  w.address = address;
  w.number = value;
  w.text = text;
  return w;
}

// ---------------------------------------------------------------- tables

TEST(RemapTable, NctRowsForCallsReturnsAndModalCalls) {
  const RemapTable& t = nct::profile().controlFlow->remaps;
  ASSERT_NE(t.find("M", 98), nullptr);
  EXPECT_EQ(t.find("M", 98)->action, FlowAction::CallSubprogram);
  EXPECT_EQ(t.find("M", 98)->frame, LocalFrame::Shared);
  EXPECT_EQ(t.find("M", 98)->programWord, 'P');
  EXPECT_EQ(t.find("M", 98)->repeatWord, 'L');
  EXPECT_EQ(t.find("M", 99)->action, FlowAction::Return);
  EXPECT_EQ(t.find("G", 65)->action, FlowAction::CallMacro);
  EXPECT_EQ(t.find("G", 65)->frame, LocalFrame::Arguments);
  EXPECT_EQ(t.find("G", 65, 10.0)->action, FlowAction::CallMacro);
  EXPECT_EQ(t.find("G", 65, 9999.0)->action, FlowAction::CallCycle); // cycles.md §5
  EXPECT_EQ(t.find("G", 66)->action, FlowAction::ModalCall);
  EXPECT_EQ(t.find("G", 66.1)->action, FlowAction::ModalCallEveryBlock);
  EXPECT_EQ(t.find("G", 67)->action, FlowAction::ModalCancel);
  EXPECT_EQ(t.find("G", 1), nullptr);
  EXPECT_EQ(t.find("M", 3), nullptr);
  EXPECT_EQ(t.find("P", 98), nullptr);
}

TEST(RemapTable, NctProgramFilesAndLabels) {
  const ControlFlow& f = *nct::profile().controlFlow;
  EXPECT_EQ(f.programFiles("12", ".nct"), (V{"O0012.nct", "O00000012.nct"}));
  EXPECT_EQ(f.programFiles("0012", ".NCT"), (V{"O0012.NCT", "O00000012.NCT"}));
  EXPECT_EQ(f.programFiles("123456", ".nct"), (V{"O00123456.nct"}));
  EXPECT_EQ(f.programFiles("-5", ".nct"), V{});
  EXPECT_EQ(f.programLabel("12"), "O0012");
  EXPECT_EQ(f.programLabel("9999"), "O9999");
}

TEST(RemapTable, NctMessageVariablesAndVariableSpace) {
  const ControlFlow& f = *nct::profile().controlFlow;
  ASSERT_TRUE(f.messageVariable(3000));
  EXPECT_EQ(f.messageVariable(3000)->kind, MessageRule::Alarm);
  EXPECT_EQ(f.messageVariable(3000)->alarmBase, 4000);
  EXPECT_EQ(f.messageVariable(3006)->kind, MessageRule::Stop);
  EXPECT_EQ(f.messageVariable(3106)->kind, MessageRule::Note);
  EXPECT_FALSE(f.messageVariable(100));
  EXPECT_FALSE(f.messageVariable(3001));
  EXPECT_EQ(f.variables.frameSize(), 34);
  EXPECT_EQ(f.variables.commonFirst, 100);
}

TEST(Wl4Spec_6_7, LWordNamesProgramAndRepeatsByItsDigits) {
  const ControlFlow f = wl4Shape();
  const Remap* l = f.remaps.find("L", 703);
  ASSERT_NE(l, nullptr);
  const ProgramCall twice = programFromDigits(*l, programDigits(word("L", 703, "0703")));
  EXPECT_EQ(twice.unit, "07");
  EXPECT_EQ(twice.times, 3);
  const ProgramCall once = programFromDigits(*l, programDigits(word("L", 7, "07")));
  EXPECT_EQ(once.unit, "07");
  EXPECT_EQ(once.times, std::nullopt);
}

TEST(Wl4Spec_5_1, G81ToG89CallTheirOwnNumbers) {
  const ControlFlow f = wl4Shape();
  for (double g : {81.0, 85.0, 89.0}) {
    const Remap* r = f.remaps.find("G", g);
    ASSERT_NE(r, nullptr) << g;
    EXPECT_EQ(r->action, FlowAction::ModalCall);
    EXPECT_EQ(programFromDigits(*r, programDigits(word("G", g, ""))).unit,
              std::to_string(static_cast<int>(g)));
  }
  EXPECT_EQ(f.remaps.find("G", 80)->action, FlowAction::ModalCancel);
  EXPECT_EQ(f.remaps.find("G", 90), nullptr);
  EXPECT_EQ(f.remaps.find("G", 1), nullptr);
}

TEST(FmsSpec_6_1, PDigitsKeepTheirLeadingZeros) {
  const ControlFlow f = fmsShape();
  const Remap* p = f.remaps.find("P", 19);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(programFromDigits(*p, programDigits(word("P", 19, "019"))).unit, "019");
  EXPECT_EQ(programFromDigits(*p, programDigits(word("P", 19, "19"))).unit, "19");
}

TEST(FmsSpec_6_1, GSubprogramsGgBuiltinsAndM98) {
  const ControlFlow f = fmsShape();
  const Remap* g = f.remaps.find("G", 1);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->action, FlowAction::CallMacro);
  EXPECT_TRUE(g->onlyIfProgramExists);
  EXPECT_EQ(programFromDigits(*g, programDigits(word("G", 1, "1"))).unit, "G1");
  const Remap* gg = f.remaps.find("GG", 1);
  ASSERT_NE(gg, nullptr);
  EXPECT_EQ(gg->action, FlowAction::Builtin);
  EXPECT_EQ(gg->builtin, "G");
  EXPECT_EQ(f.remaps.find("M", 98)->action, FlowAction::EndProgram);
}

TEST(RemapTable, ProgramDigitsFallBackToTheValue) {
  EXPECT_EQ(programDigits(word("P", 12, "12.")), "12");
  EXPECT_EQ(programDigits(word("P", 12, "")), "12"); // a computed value has no text
  EXPECT_EQ(programDigits(word("P", 7, "0007")), "0007");
}

// ---------------------------------------------------------------- the engine under the shapes

TEST(Wl4Spec_6_7, LCallRepeatsWithAFreshCopyOfTheCallersLocals) {
  // each of the three runs starts from the caller's #1 = 5; the caller's #1 stays 5
  Shaped wl4(wl4Shape());
  MacroRun r = runMacroAs(
      wl4.dialect,
      {{"main.nct", "#1=5\nL0703\nG90 G0 X#1\nM30\n"}, {"07.nct", "G91 G0 X#1\n#1=1\nM99\n"}},
      "main.nct", {1});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 5,0,0", "R 10,0,0", "R 15,0,0", "R 5,0,0", "END"}));
  EXPECT_EQ(r.vars[1].number, 5);
}

TEST(Wl4Spec_5_1, UserCycleRunsAfterEveryBlockWithAxisWordsUntilG80) {
  // G81 X10 moves, then %81 runs; so does X20; after G80, X30 only moves
  Shaped wl4(wl4Shape());
  MacroRun r = runMacroAs(
      wl4.dialect,
      {{"main.nct", "#2=-3\nG81 X10\nX20\nG80\nX30\nM30\n"}, {"81.nct", "G0 Z#2\nZ0\nM99\n"}},
      "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 10,0,0", "R 10,0,-3", "R 10,0,0", "R 20,0,0", "R 20,0,-3", "R 20,0,0",
                           "R 30,0,0", "END"}));
}

TEST(FmsSpec_6_1, PCallRunsAfterTheBlockAndP019IsNotP19) {
  Shaped fms(fmsShape());
  MacroRun r = runMacroAs(fms.dialect,
                          {{"main.nct", "G0 X1000 P19\nP019\nM30\n"},
                           {"19.nct", "G0 Y1\nM99\n"},
                           {"019.nct", "G0 Y2\nM99\n"}},
                          "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1000,0,0", "R 1000,1,0", "R 1000,2,0", "END"}));
}

TEST(FmsSpec_6_1, AUserGProgramOverridesTheBuiltinWithTheBlockAsArguments) {
  // G1 X100 Y100 calls G1.nct (X -> #24, Y -> #25); G0 has no program and stays the built-in
  Shaped fms(fmsShape());
  MacroRun r = runMacroAs(
      fms.dialect,
      {{"main.nct", "G1 X100 Y100 F500\nG0 X5\nM30\n"}, {"G1.nct", "G0 X#24 Y[#25+1]\nM99\n"}},
      "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 100,101,0", "R 5,101,0", "END"}));
}

TEST(FmsSpec_6_1, M98EndsTheProgram) {
  Shaped fms(fmsShape());
  MacroRun r = runMacroAs(fms.dialect, {{"main.nct", "G0 X1\nM98\nG0 X2\nM30\n"}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "END"}));
}

} // namespace
} // namespace gcx::test
