// The NCT front end fills IR v2 (docs/architecture.md, IR): literal texts as written, the first
// N's digits, the program name, statements in a list, and every item's place in the source, on
// both parse paths.
#include <gtest/gtest.h>

#include "ir/items.h"
#include "support/hand_built_ir.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using ir::ItemKind;
using ir::ItemRef;

const ir::Block& only(const Parsed&& p) = delete; // would dangle
const ir::Block& only(const Parsed& p) {
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks.size(), 1u);
  return p.blocks.at(0);
}

class NctIrV2 : public ::testing::TestWithParam<bool> {
protected:
  Parsed parse(const std::string& text) {
    ParseOptions o;
    o.fastPath = GetParam();
    return parseNct(text, o);
  }
};

TEST_P(NctIrV2, LiteralsKeepTheirTextAndTheFirstNItsDigits) {
  Parsed p = parse("N0010 G01 X-40 Y+5. (MID) Z.50\n");
  const ir::Block& b = only(p);
  EXPECT_EQ(b.sequence, 10);
  EXPECT_EQ(b.sequenceText, "0010");
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[0].text, "01");
  EXPECT_EQ(b.words[1].text, "-40");
  EXPECT_EQ(b.words[1].number, -40);
  EXPECT_EQ(b.words[2].text, "+5.");
  EXPECT_EQ(b.words[3].text, ".50");
  // the comment stands between Y and Z
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{{ItemKind::Word, 0},
                                                {ItemKind::Word, 1},
                                                {ItemKind::Word, 2},
                                                {ItemKind::Comment, 0},
                                                {ItemKind::Word, 3}}));
}

TEST_P(NctIrV2, ACommentBeforeTheSkipComesFirst) {
  const Parsed p = parse("(A) /2 X1 (B)\n"); // kept alive: `b` refers into it
  const ir::Block& b = only(p);
  EXPECT_EQ(
      ir::items(b),
      (std::vector<ItemRef>{{ItemKind::Comment, 0}, {ItemKind::Word, 0}, {ItemKind::Comment, 1}}));
}

INSTANTIATE_TEST_SUITE_P(BothParsePaths, NctIrV2, ::testing::Values(true, false));

TEST(NctIrV2Statements, AStatementIsTheBlocksOnlyStatementInItsPlace) {
  Parsed p = parseNct("N5 #1=#2+1 (SET)\n");
  const ir::Block& b = only(p);
  ASSERT_EQ(b.stmts.size(), 1u);
  EXPECT_EQ(b.stmts[0].kind, ir::StmtKind::Assign);
  EXPECT_TRUE(b.words.empty());
  EXPECT_EQ(ir::items(b), (std::vector<ItemRef>{{ItemKind::Stmt, 0}, {ItemKind::Comment, 0}}));
}

TEST(NctIrV2Statements, AnExpressionWordHasNoLiteralText) {
  const Parsed p = parseNct("G1 X#1 Y-[#2] M98 <a.nct>\n");
  const ir::Block& b = only(p);
  ASSERT_EQ(b.words.size(), 5u);
  EXPECT_EQ(b.words[1].text, "");
  EXPECT_EQ(b.words[2].text, "");
  EXPECT_EQ(b.words[3].text, "98");
  EXPECT_EQ(b.words[4].text, "a.nct"); // a path as written
}

TEST(NctIrV2Statements, AProgramIsNamedByItsNumber) {
  Parsed p = parseNct("%O1\nM30\n%\n");
  ASSERT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].kind, ir::BlockKind::ProgramStart);
  EXPECT_EQ(p.blocks[0].programName, "O0001");
}

} // namespace
} // namespace gcx::test
