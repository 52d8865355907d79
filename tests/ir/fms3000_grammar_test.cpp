// IR v2 holds every construct of the FMS-3000 grammar (fms3000.md §6.3), built by hand as its
// front end will build it: what the IR keeps, in which order, and what gcx dump shows.
#include <gtest/gtest.h>

#include "ir/dump.h"
#include "ir/items.h"
#include "support/hand_built_ir.h"

namespace gcx::test {
namespace {

using hand::word;
using ir::ItemKind;
using ir::ItemRef;

std::string dump(const ir::Block& b) {
  return ir::toJson(b, true).dump();
}

TEST(Fms3000Grammar_6_3, RemLineIsACommentLine) {
  // `rem` starts a comment to the end of the line (001:3343)
  const ir::Block b = hand::Block(ir::BlockKind::CommentLine)
                          .comment(ir::CommentKind::ToLineEnd, "ROUGH PROFILE")
                          .done();
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(dump(b), R"({"comments":[{"to-line-end":"ROUGH PROFILE"}],"kind":"comment-line"})");
}

TEST(Fms3000Grammar_6_3, EndcontLineEndsTheContour) {
  const ir::Block b = hand::Block(ir::BlockKind::ContourEnd).done();
  EXPECT_EQ(b.kind, ir::BlockKind::ContourEnd);
  EXPECT_EQ(dump(b), R"({"kind":"contour-end"})");
}

TEST(Fms3000Grammar_6_3, SeqnoOfSevenDigits) {
  const ir::Block b = hand::Block().sequence("9999999").add("X", "1").done();
  EXPECT_EQ(b.sequence, 9999999);
  EXPECT_EQ(b.sequenceText, "9999999");
  EXPECT_EQ(dump(b),
            R"({"n":9999999,"n_text":"9999999","words":[{"address":"X","text":"1","value":1.0}]})");
}

TEST(Fms3000Grammar_6_3, BareSeqnoHasNoNumber) {
  // "bare N tolerated" (§6.3, §7): written, but no value
  const ir::Block b = hand::Block().sequence("").add("G", "1").done();
  EXPECT_FALSE(b.sequence);
  EXPECT_EQ(b.sequenceText, "");
}

TEST(Fms3000Grammar_6_3, GwordAndGgword) {
  // `GG1` forces the built-in linear move where a G-subprogram G1 overrides it (001:3782)
  const ir::Block b = hand::Block().add("GG", "1").add("G", "081").add("X", "100").done();
  EXPECT_EQ(b.words[0].address, "GG");
  EXPECT_FALSE(b.words[0].is('G')); // GG is not a G word
  EXPECT_EQ(b.words[0].number, 1);
  EXPECT_EQ(b.words[1].text, "081");
  EXPECT_EQ(b.words[1].number, 81);
}

TEST(Fms3000Grammar_6_3, PwordKeepsItsDigitString) {
  // P7 and P07 are different programs (001:292, 001:319-322); the value alone cannot tell them
  const ir::Block p019 = hand::Block().add("P", "019").done();
  const ir::Block p19 = hand::Block().add("P", "19").done();
  EXPECT_EQ(p019.words[0].number, p19.words[0].number);
  EXPECT_EQ(p019.words[0].text, "019");
  EXPECT_EQ(p19.words[0].text, "19");
  EXPECT_NE(dump(p019), dump(p19));
  // the structural identity compares values only
  EXPECT_EQ(ir::toJson(p019, false), ir::toJson(p19, false));
}

TEST(Fms3000Grammar_6_3, PwordAsCycleParameterIsANumber) {
  const ir::Block b = hand::Block().add("G", "156").add("P", "0.5").done();
  EXPECT_EQ(b.words[1].number, 0.5);
  EXPECT_EQ(b.words[1].text, "0.5");
}

TEST(Fms3000Grammar_6_3, MultiLetterAddresses) {
  // longest match: DR5 is DR=5 (§1.1)
  const ir::Block b = hand::Block()
                          .add("G", "96")
                          .add("LIMS", "2000")
                          .add("DR", "5")
                          .add("DX", "-.707")
                          .add("DY", "+0.707")
                          .add("DZ", "0")
                          .done();
  ASSERT_EQ(b.words.size(), 6u);
  EXPECT_EQ(b.words[1].address, "LIMS");
  EXPECT_EQ(b.words[1].number, 2000);
  EXPECT_EQ(b.words[2].address, "DR");
  EXPECT_EQ(b.words[3].number, -0.707);
  EXPECT_EQ(b.words[3].text, "-.707");
  EXPECT_EQ(b.words[4].number, 0.707);
  EXPECT_EQ(b.words[4].text, "+0.707");
  EXPECT_EQ(b.find('D'), nullptr); // DR, DX ... are not D
}

TEST(Fms3000Grammar_6_3, ValueForms) {
  // value = [+|-] (digits [. [digits]] | . digits): X100 = X100. = 100 mm (§1.2)
  for (const char* text : {"100", "100.", "+100", "100.000"})
    EXPECT_EQ(word("X", text).number, 100) << text;
  EXPECT_EQ(word("X", ".5").number, 0.5);
  EXPECT_EQ(word("X", "-.5").number, -0.5);
}

// cycle_block = [seqno] {pre_word} cycle_g {param_word}: the words before the cycle's G code
// are ordinary words, those after it its parameters (§5.1, §6.3).
TEST(Fms3000Grammar_6_3, CycleBlockKeepsPreWordsBeforeTheCycle) {
  const ir::Block b = hand::Block()
                          .sequence("40")
                          .add("X", "10")
                          .add("Y", "20")
                          .add("G", "81")
                          .add("Z", "-5")
                          .add("R", "2")
                          .add("F", "100")
                          .done();
  std::vector<std::string> order;
  ir::forEachItem(b, [&](ItemRef r) {
    ASSERT_EQ(r.kind, ItemKind::Word);
    order.push_back(b.words[r.index].address);
  });
  EXPECT_EQ(order, (std::vector<std::string>{"X", "Y", "G", "Z", "R", "F"}));
}

TEST(Fms3000Grammar_6_3, CycleBlockAsSemanticCycleCall) {
  // the same block with the cycle kept as a cycle: pre-words, then the call with its parameters
  ir::Stmt cycle = hand::stmt(ir::StmtKind::CycleCall);
  cycle.callee = "G81";
  cycle.args = {word("Z", "-5"), word("R", "2"), word("F", "100")};
  const ir::Block b =
      hand::Block().sequence("40").add("X", "10").add("Y", "20").add(std::move(cycle)).done();
  EXPECT_EQ(ir::items(b),
            (std::vector<ItemRef>{{ItemKind::Word, 0}, {ItemKind::Word, 1}, {ItemKind::Stmt, 0}}));
  const ir::Stmt& s = b.stmts[0];
  ASSERT_EQ(s.args.size(), 3u);
  EXPECT_EQ(s.args[0].address, "Z");
  EXPECT_EQ(s.args[2].number, 100);
  EXPECT_EQ(dump(b),
            R"({"n":40,"n_text":"40","stmt":{"args":[{"address":"Z","text":"-5","value":-5.0},)"
            R"({"address":"R","text":"2","value":2.0},{"address":"F","text":"100","value":100.0}],)"
            R"("callee":"G81","kind":"cycle-call"},"words":[{"address":"X","text":"10","value":)"
            R"(10.0},{"address":"Y","text":"20","value":20.0}]})");
}

TEST(Fms3000Grammar_6_3, RepeatG25LThroughM25) {
  // G25 before L, `G25 L_` ends its block; the fragment up to the M25 block repeats L times
  const std::vector<ir::Block> blocks = {
      hand::Block().add("G", "91").add("G", "25").add("L", "3").done(),
      hand::Block().add("G", "1").add("X", "10").add("F", "100").done(),
      hand::Block().add("Y", "5").add("M", "25").done(),
  };
  const ir::Block& head = blocks[0];
  ASSERT_EQ(head.words.size(), 3u);
  EXPECT_LT(head.words[1].order, head.words[2].order); // G25 precedes L
  EXPECT_EQ(head.words[2].text, "3");
  EXPECT_EQ(blocks[2].find('M')->number, 25);
}

TEST(Fms3000Grammar_6_3, SubprogramCallRunsAfterTheBlock) {
  // `X1000 P19`: the call runs after the motion (001:3752-3755); the name is a digit string
  ir::Stmt call = hand::stmt(ir::StmtKind::Call);
  call.callee = "19";
  call.value = hand::num(1);
  const ir::Block b = hand::Block().add("X", "1000").add(std::move(call)).done();
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{{ItemKind::Word, 0}, {ItemKind::Stmt, 0}}));
  EXPECT_EQ(dump(b),
            R"({"stmt":{"callee":"19","kind":"call","value":{"kind":"number","value":1.0}},)"
            R"("words":[{"address":"X","text":"1000","value":1000.0}]})");
}

TEST(Fms3000Grammar_6_3, GSubprogramCallTakesTheWordsAfterTheG) {
  // `N100 G1 X100 Y100` calls subprogram G1 with arguments X100 Y100 (001:3769-3786)
  ir::Stmt call = hand::stmt(ir::StmtKind::Call);
  call.callee = "G1";
  call.value = hand::num(1);
  call.args = {word("X", "100"), word("Y", "100")};
  const ir::Block b = hand::Block().sequence("100").add(std::move(call)).done();
  EXPECT_TRUE(b.words.empty());
  EXPECT_EQ(b.stmts[0].callee, "G1");
  EXPECT_EQ(b.stmts[0].args[1].address, "Y");
}

TEST(Fms3000Grammar_6_3, ProgramsAreNamedByDigitStrings) {
  // `0`, `00`, `000`, `0000` are four programs (001:319-322); each file is one unit named by
  // its base name (§1.3)
  const std::vector<ir::Program> units = {
      {0, "0", {}}, {0, "00", {}}, {0, "0019", {}}, {0, "19", {}}, {0, "G81", {}}};
  for (std::size_t i = 0; i < units.size(); ++i)
    for (std::size_t j = i + 1; j < units.size(); ++j)
      EXPECT_NE(units[i].name, units[j].name);
}

TEST(Fms3000Grammar_6_3, ProgramAndSubprogramEnds) {
  // a program ends with M02, M30 or M98; a subprogram with M99 (001:336-340)
  ir::Program main{0, "0019", {}};
  main.blocks.push_back(hand::Block().add("G", "0").add("X", "0").done());
  main.blocks.push_back(hand::Block().add("M", "98").done());
  ir::Program sub{0, "19", {}};
  sub.blocks.push_back(hand::Block().add("M", "99").done());
  EXPECT_EQ(main.blocks.back().words[0].number, 98);
  EXPECT_EQ(sub.blocks.back().words[0].number, 99);
  EXPECT_NE(main.name, sub.name);
}

} // namespace
} // namespace gcx::test
