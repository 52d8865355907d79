// The control-flow engine on the statements a WL4 block holds (wl4.md §1.2, §1.7-§1.9,
// §6.4-§6.7), with blocks built by hand as a front end builds them: several `%name ... %` units
// per file, words and statements evaluated left to right, a guard `IF<p> (cond)` that drops the
// rest of its block, a Jump to a label after the block, a Call of a unit by name with a repeat
// count and a copy of the caller's locals, and block skip in the dialect's sense.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "dialect/control_flow.h"
#include "dialect/dialect.h"
#include "dialects/nct/profile.h"
#include "dialects/wl4/control_flow.h"
#include "passes/macro/expander.h"
#include "support/hand_built_ir.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using hand::bin;
using hand::callUnit;
using hand::guard;
using hand::jump;
using hand::num;
using hand::paren;
using hand::var;
using hand::word;
using ir::Op;
using V = std::vector<std::string>;

// ---------------------------------------------------------------- a dialect of hand-built IR

// A file's text is a key into this table: the blocks its "front end" gives.
std::map<std::string, std::vector<ir::Block>>& handFiles() {
  static std::map<std::string, std::vector<ir::Block>> files;
  return files;
}

class HandSource : public BlockSource {
public:
  HandSource(std::istream& in, FileId file) {
    std::ostringstream text;
    text << in.rdbuf();
    blocks_ = handFiles().at(text.str());
    // each block on its own line, each item at the column of its order
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      ir::Block& b = blocks_[i];
      const auto at = [&](std::uint32_t order) {
        return SourceRange{SourceLoc{file, static_cast<std::uint32_t>(i + 1), order + 1, order}, 1};
      };
      b.range = at(0);
      for (ir::Word& w : b.words)
        w.range = at(w.order);
      for (ir::Stmt& s : b.stmts)
        s.range = at(s.order);
    }
  }
  bool next(ir::Block& out) override {
    if (at_ == blocks_.size()) return false;
    out = blocks_[at_++];
    return true;
  }
  bool sawInput() const override { return !blocks_.empty(); }
  std::size_t failedBlocks() const override { return 0; }

private:
  std::vector<ir::Block> blocks_;
  std::size_t at_ = 0;
};

struct HandDialect {
  static inline Profile profile;
  static inline ControlFlow flow;
  static const Profile& current() { return profile; }
  Dialect dialect;
  HandDialect() : dialect(*findDialect("nct")) {
    flow = wl4::controlFlow();
    profile = nct::profile();
    profile.controlFlow = &flow;
    profile.machine.skipSense = SkipSense::RunWhenOn;
    for (AddressSpec& a : profile.addresses) // the last of a repeated address is used (§1.3)
      a.repeatable = true;
    dialect.profile = &HandDialect::current;
    dialect.openSource = [](std::istream& in, FileId file, diag::Engine&,
                            front::Encoding) -> std::unique_ptr<BlockSource> {
      return std::make_unique<HandSource>(in, file);
    };
  }
};

// A file of units: each unit `%name`, its blocks, `%`. Registered under a key of its own.
std::string file(const std::string& key,
                 const std::vector<std::pair<std::string, std::vector<ir::Block>>>& units) {
  std::vector<ir::Block>& blocks = handFiles()[key];
  blocks.clear();
  for (const auto& [name, body] : units) {
    blocks.push_back(hand::Block(ir::BlockKind::ProgramStart).name(name).done());
    blocks.insert(blocks.end(), body.begin(), body.end());
    blocks.push_back(hand::Block(ir::BlockKind::ProgramEnd).done());
  }
  return key;
}

ir::Block words(std::vector<std::pair<std::string, std::string>> ws) {
  hand::Block b;
  for (auto& [a, t] : ws)
    b.add(a, t);
  return b.done();
}
ir::Block end() {
  return words({{"M", "30"}});
}
ir::Block ret() {
  return words({{"M", "99"}});
}

MacroRun run(const std::map<std::string, std::string>& files, const std::string& main,
             const std::vector<int>& watch = {}, const machine::Setup& setup = {}) {
  HandDialect d;
  macro::Limits limits;
  limits.maxJumps = 1000;
  return runMacroAs(d.dialect, files, main, watch, setup, limits);
}

// ---------------------------------------------------------------- units

TEST(Wl4Engine_1_2, TheFirstUnitIsTheMainProgramAndCallsFindUnitsOfTheSameFile) {
  // %MAIN calls %07 of the same file; %07 and the text after it are not run by themselves
  const std::string f =
      file("units",
           {{"MAIN",
             {words({{"G", "0"}, {"X", "1"}}), hand::Block().add(callUnit("07", 1)).done(), end()}},
            {"07", {words({{"G", "0"}, {"Y", "7"}}), ret()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 1,7,0", "END"}));
}

TEST(Wl4Engine_1_2, ACallFindsTheUnitInAFileOfItsNameBeside) {
  const std::string main =
      file("beside-main", {{"MAIN", {hand::Block().add(callUnit("11", 1)).done(), end()}}});
  const std::string other = file("beside-11", {{"11", {words({{"G", "0"}, {"Z", "-2"}}), ret()}}});
  MacroRun r = run({{"main.nct", main}, {"11.nct", other}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,-2", "END"}));
}

TEST(Wl4Engine_1_2, AFileOfTheUnitsNameWithoutThatUnitIsAnError) {
  const std::string main =
      file("missing-main",
           {{"MAIN", {words({{"G", "0"}}), hand::Block().add(callUnit("12", 1)).done(), end()}}});
  const std::string other = file("missing-12", {{"13", {ret()}}});
  MacroRun r = run({{"main.nct", main}, {"12.nct", other}}, "main.nct");
  EXPECT_EQ(r.errors, (V{"main.nct:3:1 NCTX07"})) << r.rendered;
}

// ---------------------------------------------------------------- calls

TEST(Wl4Engine_6_7, CallRunsAfterTheBlockWithAFreshCopyOfTheLocalsEachTime) {
  // `#1=5` / `G0 X1 L0703` / `X#1`: X1 first, then %07 three times from #1 = 5; #1 stays 5
  const std::string f = file(
      "copy",
      {{"MAIN",
        {hand::Block().add(hand::assignment(var(1), num(5))).done(),
         hand::Block().add("G", "0").add("X", "1").add(callUnit("07", 3)).done(),
         hand::Block().add(word("X", var(1))).done(), end()}},
       {"07",
        {hand::Block().add("G", "91").add(word("X", var(1))).done(),
         hand::Block().add(hand::assignment(var(1), num(100))).add("G", "90").done(), ret()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct", {1});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "R 6,0,0", "R 11,0,0", "R 16,0,0", "R 5,0,0", "END"}));
  EXPECT_EQ(r.vars[1].number, 5);
}

TEST(Wl4Engine_1_9, AJumpInTheCallingBlockIsTakenAfterTheReturn) {
  // `L07 N19`: %07 runs, then the jump skips the Y block and lands on N019
  const std::string f = file(
      "call-jump", {{"MAIN",
                     {hand::Block().add(callUnit("07", 1)).add(jump("19")).done(),
                      words({{"G", "0"}, {"Y", "50"}}),
                      hand::Block().sequence("019").add("G", "0").add("Z", "5").done(), end()}},
                    {"07", {words({{"G", "0"}, {"X", "3"}}), ret()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 3,0,0", "R 3,0,5", "END"}));
}

// ---------------------------------------------------------------- order of evaluation

TEST(Wl4Engine_1_9, WordsUseTheValuesBeforeAnAssignmentThatFollowsThem) {
  // `#1=2` / `G0 X#1 #1=(#1+3)` / `Y#1` (TV6): X2, then Y5
  const std::string f =
      file("order", {{"MAIN",
                      {hand::Block().add(hand::assignment(var(1), num(2))).done(),
                       hand::Block()
                           .add("G", "0")
                           .add(word("X", var(1)))
                           .add(hand::assignment(var(1), paren(bin(Op::Add, var(1), num(3)))))
                           .done(),
                       hand::Block().add(word("Y", var(1))).done(), end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 2,0,0", "R 2,5,0", "END"}));
}

TEST(Wl4Engine_6_4, AnAssignmentInsideAWordsValueTakesEffect) {
  // `G0 X#31=(4*2) Y#31`: #31 (global) is 8 when Y is read
  const std::string f = file(
      "embedded", {{"MAIN",
                    {hand::Block()
                         .add("G", "0")
                         .add(word("X", hand::assign(var(31), paren(bin(Op::Mul, num(4), num(2))))))
                         .add(word("Y", var(31)))
                         .done(),
                     end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct", {31});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 8,8,0", "END"}));
  EXPECT_EQ(r.vars[31].number, 8);
}

TEST(Wl4Engine_6_1, AVariableNeverWrittenReadsZero) {
  // `G0 X3` / `X#5`: #5 reads 0, so the word stays and moves back to X0 (no vacant drop)
  const std::string f = file("zero", {{"MAIN",
                                       {words({{"G", "0"}, {"X", "3"}}),
                                        hand::Block().add(word("X", var(5))).done(), end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct", {5, 40});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 3,0,0", "R 0,0,0", "END"}));
  EXPECT_FALSE(r.vars[5].vacant);
  EXPECT_FALSE(r.vars[40].vacant);
}

// ---------------------------------------------------------------- guards

TEST(Wl4Engine_6_5, AFalseGuardDropsTheRestButWordsBeforeItRun) {
  // `G1 X0 Z100 F500 IF ((#1-#2)>0) Z0` (TV8): with #1 = #2 one move to X0 Z100
  const auto block =
      hand::Block()
          .add("G", "1")
          .add("X", "0")
          .add("Z", "100")
          .add("F", "500")
          .add(guard(paren(bin(Op::Gt, paren(bin(Op::Sub, var(1), var(2))), num(0)))))
          .add("Z", "0")
          .done();
  const ir::Block start = words({{"G", "0"}, {"Z", "50"}});
  const std::string f = file("guard-false", {{"MAIN", {start, block, end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,50", "L 0,0,100 F500", "END"}));
  // with #1 > #2 the later Z0 wins: one move to X0 Z0
  const std::string g =
      file("guard-true",
           {{"MAIN",
             {start, hand::Block().add(hand::assignment(var(1), num(1))).done(), block, end()}}});
  MacroRun t = run({{"main.nct", g}}, "main.nct");
  ASSERT_TRUE(t.errors.empty()) << t.rendered;
  EXPECT_EQ(t.motion(), (V{"R 0,0,50", "L 0,0,0 F500", "END"}));
}

TEST(Wl4Engine_6_5, AGuardWithPrecisionComparesRoundedValues) {
  // TV22: `#1=1.0004 #2=1.0001` / `IF3 (#1>#2) G1 X1 F100` / `IF (#1>#2) G1 X2 F100`
  const auto cond = [] { return paren(bin(Op::Gt, var(1), var(2))); };
  const std::string f = file(
      "precision",
      {{"MAIN",
        {hand::Block()
             .add(hand::assignment(var(1), num(1.0004)))
             .add(hand::assignment(var(2), num(1.0001)))
             .done(),
         hand::Block().add(guard(cond(), 3)).add("G", "1").add("X", "1").add("F", "100").done(),
         hand::Block().add(guard(cond())).add("G", "1").add("X", "2").add("F", "100").done(),
         end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 2,0,0 F100", "END"}));
}

// ---------------------------------------------------------------- jumps

TEST(Wl4Engine_6_6, ALabelAndAGuardedJumpMakeALoop) {
  // TV7: `N010 #1=(#1+1) G1 X(#1*10) F100` / `IF (#1<3) N10` / `M30`
  const std::string f =
      file("loop",
           {{"MAIN",
             {hand::Block()
                  .sequence("010")
                  .add(hand::assignment(var(1), paren(bin(Op::Add, var(1), num(1)))))
                  .add("G", "1")
                  .add(word("X", paren(bin(Op::Mul, var(1), num(10)))))
                  .add("F", "100")
                  .done(),
              hand::Block().add(guard(paren(bin(Op::Lt, var(1), num(3))))).add(jump("10")).done(),
              end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"L 10,0,0 F100", "L 20,0,0 F100", "L 30,0,0 F100", "END"}));
}

TEST(Wl4Engine_6_6, TheJumpComesAfterTheBlocksMotion) {
  // `N15 G0 Z1 N17` moves, then continues at N017, past the X block
  const std::string f =
      file("after",
           {{"MAIN",
             {hand::Block().sequence("15").add("G", "0").add("Z", "1").add(jump("17")).done(),
              words({{"X", "9"}}), hand::Block().sequence("017").add("Y", "2").done(), end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 0,0,1", "R 0,2,1", "END"}));
}

TEST(Wl4Engine_1_8, ABlockNumberWithoutALeadingZeroIsNoLabel) {
  // `N17` is block 17, not label 17: the jump has no target (located at the jump)
  const std::string f =
      file("nolabel", {{"MAIN",
                        {hand::Block().add("G", "0").add("Z", "1").add(jump("17")).done(),
                         hand::Block().sequence("17").add("Y", "2").done(), end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  EXPECT_EQ(r.errors, (V{"main.nct:2:3 2125"})) << r.rendered;
  EXPECT_EQ(r.motion(), V{}); // found while the block is read, before it moves
}

TEST(Wl4Engine_6_6, AnEndlessJumpLoopStopsAtTheJumpLimit) {
  const std::string f =
      file("endless",
           {{"MAIN", {hand::Block().sequence("01").add("G", "0").add(jump("1")).done(), end()}}});
  MacroRun r = run({{"main.nct", f}}, "main.nct");
  EXPECT_EQ(r.errors, (V{"main.nct:2:1 GCX040"})) << r.rendered;
}

// ---------------------------------------------------------------- block skip

TEST(Wl4Engine_1_7, ASkippedBlockRunsOnlyWhileTheSwitchIsOn) {
  const std::string f =
      file("skip", {{"MAIN", {hand::Block().skip().add("G", "0").add("X", "4").done(), end()}}});
  MacroRun off = run({{"main.nct", f}}, "main.nct");
  ASSERT_TRUE(off.errors.empty()) << off.rendered;
  EXPECT_EQ(off.motion(), (V{"END"}));
  machine::Setup on;
  on.blockSkip = {1};
  MacroRun r = run({{"main.nct", f}}, "main.nct", {}, on);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 4,0,0", "END"}));
}

} // namespace
} // namespace gcx::test
