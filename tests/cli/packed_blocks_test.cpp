// The packed form the reading thread hands blocks over in (cli/packed_blocks.h): a block of
// literal one-letter words comes back field for field as it was read, whatever the block
// unpacked before it held; every other block is left whole.
#include <gtest/gtest.h>

#include "cli/packed_blocks.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

void expectSameRange(const SourceRange& a, const SourceRange& b, const std::string& what) {
  EXPECT_EQ(a.begin.file, b.begin.file) << what;
  EXPECT_EQ(a.begin.line, b.begin.line) << what;
  EXPECT_EQ(a.begin.col, b.begin.col) << what;
  EXPECT_EQ(a.begin.offset, b.begin.offset) << what;
  EXPECT_EQ(a.length, b.length) << what;
}

void expectSameBlock(const ir::Block& a, const ir::Block& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.skipLevel, b.skipLevel);
  EXPECT_EQ(a.sequence, b.sequence);
  EXPECT_EQ(a.sequenceText, b.sequenceText);
  expectSameRange(a.sequenceRange, b.sequenceRange, "sequence");
  EXPECT_EQ(a.programName, b.programName);
  EXPECT_TRUE(b.stmts.empty());
  EXPECT_TRUE(b.comments.empty());
  expectSameRange(a.range, b.range, "block");
  EXPECT_EQ(a.lastLine, b.lastLine);
  ASSERT_EQ(a.words.size(), b.words.size());
  for (std::size_t i = 0; i < a.words.size(); ++i) {
    const ir::Word &x = a.words[i], &y = b.words[i];
    const std::string what = "word " + x.address + x.text;
    EXPECT_EQ(x.address, y.address) << what;
    EXPECT_EQ(x.incremental, y.incremental) << what;
    EXPECT_EQ(x.kind, y.kind) << what;
    EXPECT_EQ(x.order, y.order) << what;
    EXPECT_EQ(x.number, y.number) << what;
    EXPECT_EQ(x.text, y.text) << what;
    EXPECT_EQ(y.expr.kind, ir::ExprKind::Number) << what;
    EXPECT_TRUE(y.expr.name.empty() && y.expr.args.empty()) << what;
    EXPECT_FALSE(y.expr.range.begin.valid()) << what;
    EXPECT_TRUE(y.axisIndex.empty()) << what;
    expectSameRange(x.range, y.range, what);
  }
}

constexpr const char* kPlain = "N10 G1 X-40.5 Y07 F1200\n"
                               "/2 N0020 G0 Z5.\n"
                               "  G2 X1 Y2 I0.5 J0\n"
                               "M3 S1000 T0101\n"
                               "G91 XI-5 Y+3\n";

TEST(PackedBlocks, PlainBlocksComeBackFieldForField) {
  const Parsed p = parseNct(kPlain);
  ASSERT_EQ(p.errors(), std::vector<std::string>{}) << p.rendered();
  ASSERT_EQ(p.blocks.size(), 5u);
  cli::PackedBlocks packed;
  for (const ir::Block& b : p.blocks)
    ASSERT_TRUE(packed.pack(b)) << "line " << b.range.begin.line;
  ASSERT_EQ(packed.size(), 5u);
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    cli::UnpackedBlock fresh;
    packed.unpack(i, fresh);
    expectSameBlock(p.blocks[i], fresh.block());
  }
}

TEST(PackedBlocks, UnpackingInPlaceLeavesNothingOfTheBlockBefore) {
  // one after another into the same block, as the executing thread does: more words, then fewer
  // (4, 2, 5, 3, 3 words and back), with and without sequence numbers and skip levels
  const Parsed p = parseNct(kPlain);
  cli::PackedBlocks packed;
  for (const ir::Block& b : p.blocks)
    ASSERT_TRUE(packed.pack(b));
  cli::UnpackedBlock out;
  for (std::size_t i : {0u, 1u, 2u, 1u, 4u, 0u, 3u, 2u, 4u, 1u}) {
    packed.unpack(i, out);
    expectSameBlock(p.blocks[i], out.block());
  }
}

TEST(PackedBlocks, OtherBlocksStayWhole) {
  const Parsed p = parseNct("%O0001\n"
                            "G1 X#1\n"
                            "#1=2\n"
                            "G1 X1 (comment)\n"
                            "G1 X1 Y1 ,C2\n"
                            "G1 X1 (a comment\nover two lines) Y2\n"
                            "G1 X000000000000000012.5\n", // 22 characters of text, more than 15
                            {.staticChecks = false});
  ASSERT_EQ(p.errors(), std::vector<std::string>{}) << p.rendered();
  ASSERT_EQ(p.blocks.size(), 7u);
  cli::PackedBlocks packed;
  for (const ir::Block& b : p.blocks)
    EXPECT_FALSE(packed.pack(b)) << "line " << b.range.begin.line;
  EXPECT_EQ(packed.size(), 0u);
}

} // namespace
} // namespace gcx::test
