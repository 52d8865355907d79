// Every limit at exactly its value (the program runs) and one past it (a located error with its
// stable code): backward jumps (--max-jumps, GCX040), executed blocks (--max-blocks, GCX041),
// call depth (--max-depth, NCTX03; nct-macro.md V5), the block length of the reader (GCX005)
// and the error count (--max-errors, GCX009).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sstream>

#include "cli/commands.h"
#include "cli/execute.h"
#include "dialects/nct/reader.h"
#include "passes/macro/expander.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

macro::Limits jumps(std::uint64_t n) {
  macro::Limits l;
  l.maxJumps = n;
  return l;
}

MacroRun runMain(const std::string& text, const macro::Limits& limits) {
  return runMacroLimited({{"O0001.nct", text}}, "O0001.nct", limits);
}

// --- backward jumps --------------------------------------------------------------------------

TEST(Limits, WhileLoopNeedingExactlyTheJumpLimitFinishes) {
  // END1 jumps back three times (after #1 = 1, 2, 3); the third test of WHILE leaves the loop
  const std::string loop = "#1=0\nWHILE[#1LT3]DO1\n#1=#1+1\nG0 X#1\nEND1\nM30\n";
  MacroRun ok = runMain(loop, jumps(3));
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(ok.motion(), (V{"R 1,0,0", "R 2,0,0", "R 3,0,0", "END"}));
  EXPECT_EQ(runMain(loop, jumps(2)).errors, V{"O0001.nct:5:1 GCX040"});
}

TEST(Limits, BackwardGotoNeedingExactlyTheJumpLimitFinishes) {
  // GOTO10 goes back twice (after #1 = 1, 2); a forward GOTO is not a jump back
  const std::string loop = "#1=0\nN10 #1=#1+1\nIF[#1LT3]GOTO10\nGOTO20\nN20 M30\n";
  EXPECT_TRUE(runMain(loop, jumps(2)).errors.empty());
  EXPECT_EQ(runMain(loop, jumps(1)).errors, V{"O0001.nct:3:1 GCX040"});
}

TEST(Limits, M99InTheMainProgramCountsAsAJump) {
  // nct-macro.md §5.2 R6: M99 goes back to the first block, twice before #100 reaches 3
  const std::string loop = "#100=#100+1\nIF[#100GE3]GOTO10\nM99\nN10 M30\n";
  EXPECT_TRUE(runMain(loop, jumps(2)).errors.empty());
  EXPECT_EQ(runMain(loop, jumps(1)).errors, V{"O0001.nct:3:1 GCX040"});
}

// docs/limits.md: the defaults, the same for the library and the command line
TEST(Limits, DefaultsAreTheDocumentedOnes) {
  EXPECT_EQ(macro::Limits{}.maxJumps, 1'500'000u);
  EXPECT_EQ(macro::Limits{}.maxBlocks, 20'000'000u);
  EXPECT_EQ(cli::CommonOptions{}.maxJumps, macro::Limits{}.maxJumps);
  EXPECT_EQ(cli::CommonOptions{}.maxBlocks, macro::Limits{}.maxBlocks);
  EXPECT_EQ(cli::CommonOptions{}.maxMoves, 10'000'000u);
}

// --- executed blocks ---------------------------------------------------------------------------

TEST(Limits, ProgramOfExactlyTheBlockLimitRuns) {
  macro::Limits l;
  l.maxBlocks = 3;
  MacroRun ok = runMain("G0 X1\nG0 X2\nM30\n", l);
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(ok.motion(), (V{"R 1,0,0", "R 2,0,0", "END"}));
  l.maxBlocks = 2;
  EXPECT_EQ(runMain("G0 X1\nG0 X2\nM30\n", l).errors, V{"O0001.nct:3:1 GCX041"});
}

// --- call depth ---------------------------------------------------------------------------------

std::map<std::string, std::string> chain(int levels, const char* call) {
  // O0001 calls O0002, which calls O0003 ... down to O(levels + 1), which returns
  std::map<std::string, std::string> files;
  for (int i = 1; i <= levels + 1; ++i) {
    const std::string next = std::to_string(i + 1);
    std::string text = i <= levels ? std::string(call) + next + "\n" : "";
    text += "G91 G0 X1\n";
    text += i == 1 ? "M30\n" : "M99\n";
    files[fmt::format("O{:04}.nct", i)] = text;
  }
  return files;
}

TEST(Limits, SixteenNestedM98LevelsRunSeventeenFail) { // nct-macro.md §5.2 R8, V5
  MacroRun ok = runMacroLimited(chain(16, "M98 P"), "O0001.nct", macro::Limits{});
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(ok.program.x(), 17); // every level moved once on its way back
  EXPECT_EQ(runMacroLimited(chain(17, "M98 P"), "O0001.nct", macro::Limits{}).errors,
            V{"O0017.nct:1:1 NCTX03"});
}

TEST(Limits, SixteenNestedG65LevelsRunSeventeenFail) {
  MacroRun ok = runMacroLimited(chain(16, "G65 P"), "O0001.nct", macro::Limits{});
  ASSERT_TRUE(ok.errors.empty()) << ok.rendered;
  EXPECT_EQ(ok.program.x(), 17);
  EXPECT_EQ(runMacroLimited(chain(17, "G65 P"), "O0001.nct", macro::Limits{}).errors,
            V{"O0017.nct:1:1 NCTX03"});
}

TEST(Limits, MaxDepthIsConfigurable) {
  macro::Limits l;
  l.maxDepth = 2;
  EXPECT_TRUE(runMacroLimited(chain(2, "M98 P"), "O0001.nct", l).errors.empty());
  EXPECT_EQ(runMacroLimited(chain(3, "M98 P"), "O0001.nct", l).errors, V{"O0003.nct:1:1 NCTX03"});
  EXPECT_EQ(runMacroLimited(chain(3, "G65 P"), "O0001.nct", l).errors, V{"O0003.nct:1:1 NCTX03"});
}

// --- block length -------------------------------------------------------------------------------

V readErrors(const std::string& text, front::ReaderLimits limits, std::size_t* blocks = nullptr) {
  SourceManager sm;
  diag::Engine diags;
  const FileId f = sm.addBuffer("test.nct", text);
  std::istringstream in(text);
  nct::Reader reader(in, f, diags, limits);
  ir::Block b;
  std::size_t n = 0;
  while (reader.next(b))
    ++n;
  if (blocks) *blocks = n;
  V out;
  for (const diag::Diagnostic& d : diags.all())
    if (d.severity == diag::Severity::Error)
      out.push_back(fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code));
  return out;
}

TEST(Limits, BlockOfExactlyTheLengthLimitIsRead) {
  front::ReaderLimits l;
  l.maxBlockBytes = 16;
  std::size_t blocks = 0;
  EXPECT_EQ(readErrors("G1 X10 Y20 Z3000\nM30\n", l, &blocks), V{}); // 16 bytes
  EXPECT_EQ(blocks, 2u);
  EXPECT_EQ(readErrors("G1 X10 Y20 Z30000\nM30\n", l, &blocks), V{"1:1 GCX005"}); // 17 bytes
  EXPECT_EQ(blocks, 1u);
  // a CR before the LF is part of the block as read
  EXPECT_EQ(readErrors("G1 X10 Y20 Z300\r\nM30\n", l), V{});
  EXPECT_EQ(readErrors("G1 X10 Y20 Z3000\r\nM30\n", l), V{"1:1 GCX005"});
}

TEST(Limits, DefaultBlockLengthLimitIsOneMebibyte) {
  const std::size_t limit = std::size_t{1} << 20;
  EXPECT_EQ(front::ReaderLimits{}.maxBlockBytes, limit);
  const std::string head = "G0 X1 (";
  std::string exact = head + std::string(limit - head.size() - 1, 'a') + ")";
  ASSERT_EQ(exact.size(), limit);
  EXPECT_EQ(readErrors("M3\n" + exact + "\nM30\n", {}), V{});
  EXPECT_EQ(readErrors("M3\n" + exact + " \nM30\n", {}), V{"2:1 GCX005"});
}

// --- error count
// ----------------------------------------------------------------------------------

TEST(Limits, ErrorsUpToTheLimitAreAllReportedThenCollectingStops) {
  auto run = [](int errors) {
    diag::Engine e(3);
    for (int i = 1; i <= errors; ++i)
      e.error("2064", SourceRange{SourceLoc{0, static_cast<std::uint32_t>(i), 1, 0}, 1}, "x");
    V out;
    for (const diag::Diagnostic& d : e.all())
      out.push_back(fmt::format("{} {}", d.range.begin.line, d.code));
    return out;
  };
  EXPECT_EQ(run(2), (V{"1 2064", "2 2064"}));
  EXPECT_EQ(run(3), (V{"1 2064", "2 2064", "3 2064", "0 GCX009"}));
  EXPECT_EQ(run(4), (V{"1 2064", "2 2064", "3 2064", "0 GCX009"}));
  diag::Engine atLimit(3);
  for (int i = 0; i < 4; ++i)
    atLimit.error("2064", {}, "x");
  EXPECT_EQ(atLimit.errorCount(), 3u);
}

} // namespace
} // namespace gcx::test

// docs/limits.md: the automatic --max-output grows with the main program, so a long CAM program
// is never refused for its size; an explicit value is taken as it is
TEST(Limits, OutputBudgetIsAutomaticUnlessGiven) {
  gcx::cli::CommonOptions opt;
  EXPECT_EQ(gcx::cli::outputBudgetFor(opt, 1000), 256ULL << 20);
  EXPECT_EQ(gcx::cli::outputBudgetFor(opt, 100'000'000), 3'200'000'000ULL);
  opt.maxOutput = 10240;
  EXPECT_EQ(gcx::cli::outputBudgetFor(opt, 100'000'000), 10240u);
}
