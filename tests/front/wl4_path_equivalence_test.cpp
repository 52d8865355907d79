// The two WL4 front ends agree: the hand parser (the fast path) and the grammar path
// (grammar/WL4.g4 and its tree builder) give the same IR, locations included, and the same
// diagnostics (code, line, column) on every WL4 file of the project, every WL4 program written
// inside the WL4 tests, malformed lines, and generated blocks.
#include <gtest/gtest.h>

#include "ir/dump.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

// The diagnostics with their codes and places, errors and warnings alike.
std::vector<std::string> diagnostics(const Parsed& p) {
  std::vector<std::string> out = p.errors();
  for (const std::string& w : p.warnings())
    out.push_back("warning " + w);
  return out;
}

/// Parses text both ways and compares; the number of blocks read without error.
std::size_t expectSamePaths(const std::string& text, const std::string& what) {
  const Parsed fast = parseWl4(text, front::Encoding::Utf8, true);
  const Parsed grammar = parseWl4(text, front::Encoding::Utf8, false);
  EXPECT_EQ(diagnostics(fast), diagnostics(grammar)) << what << "\n"
                                                     << text << "\nhand parser:\n"
                                                     << fast.rendered() << "grammar:\n"
                                                     << grammar.rendered();
  EXPECT_EQ(fast.blocks.size(), grammar.blocks.size()) << what;
  for (std::size_t i = 0; i < fast.blocks.size() && i < grammar.blocks.size(); ++i)
    EXPECT_EQ(ir::toJson(fast.blocks[i], true).dump(), ir::toJson(grammar.blocks[i], true).dump())
        << what << " block " << i;
  return fast.blocks.size();
}

std::vector<fs::path> wl4Files() {
  std::vector<fs::path> out;
  for (const char* dir :
       {"examples/wl4", "dialects/wl4/programs", "tests/differential/wl4", "tests/corpus/wl4"})
    for (const fs::path& p : filesUnder(sourceDir() / dir, {".wl4"}))
      out.push_back(p);
  return out;
}

// The C++ string literals of a test source that hold a WL4 program (they start with `%`),
// adjacent literals joined as the compiler joins them.
std::vector<std::string> programsIn(const std::string& src) {
  std::vector<std::string> out;
  std::string current;
  bool joining = false;
  for (std::size_t i = 0; i < src.size(); ++i) {
    if (src[i] == '/' && i + 1 < src.size() && src[i + 1] == '/') { // a comment
      i = src.find('\n', i);
      if (i == std::string::npos) break;
      continue;
    }
    if (src[i] == '\'') { // a character literal
      i = src.find('\'', i + (src[i + 1] == '\\' ? 3 : 2));
      continue;
    }
    if (src[i] == '"') {
      std::string lit;
      for (++i; i < src.size() && src[i] != '"'; ++i) {
        if (src[i] != '\\') {
          lit += src[i];
          continue;
        }
        const char e = src[++i];
        lit += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      }
      current += lit;
      joining = true;
      continue;
    }
    if (joining && src[i] != ' ' && src[i] != '\n') {
      if (!current.empty() && current[0] == '%') out.push_back(current);
      current.clear();
      joining = false;
    }
  }
  return out;
}

std::vector<fs::path> wl4TestSources() {
  std::vector<fs::path> out;
  for (const fs::path& p : filesUnder(sourceDir() / "tests", {".cpp"}))
    if (p.filename().string().rfind("wl4_", 0) == 0) out.push_back(p);
  return out;
}

TEST(Wl4PathEquivalence, EveryWl4FileParsesIdenticallyBothWays) {
  const std::vector<fs::path> files = wl4Files();
  ASSERT_GE(files.size(), 59u); // examples, %81-%89, the differential programs, the bad corpus
  for (const fs::path& f : files)
    expectSamePaths(readFile(f), f.string());
}

TEST(Wl4PathEquivalence, EveryProgramOfTheWl4TestsParsesIdenticallyBothWays) {
  std::size_t programs = 0;
  for (const fs::path& src : wl4TestSources())
    for (const std::string& text : programsIn(readFile(src))) {
      ++programs;
      expectSamePaths(text, src.filename().string());
    }
  EXPECT_GE(programs, 40u); // the spec's vectors and the conformance tests' programs
}

TEST(Wl4PathEquivalence, MalformedLinesGiveTheSameFirstErrorBothWays) {
  // each line is a program of its own: the first error's code and place must agree
  const char* const lines[] = {
      "N 10 X1",    "N70000 X1",  "X1 L7",    "L 07",     "L0700",     "IF33 (#1>0) X1",
      "IF 3(1)",    "IF X1",      "# 1=2",    "#X=1",     "#1 5",      "#1==2",
      "X",          "X-",         "X)",       "X--1",     "X=1",       "X.",
      "X1 5",       "X1. 5",      "X1  5",    "N10 5",    "(COMMENT)", "X1 (C)",
      "X(2(3))",    "X(1",        "X(1+)",    "X(ABS 1)", "X(AB(1))",  "X(Y)",
      "XABS(1)",    "GOTO 5",     "X1 / 2",   "/2 X1",    "X1 %",      "X1,5",
      "#1=",        "#1=(1))",    "X#1=2+3",  "X(.)",     "X(1 .5)",   "ATAN(1)",
      "MOD",        "N",          "N10 N",    "X(#1MOD)", "X[1]",      "G1 X1 ; Y2",
      "#(N010ABS(", "#(+3.5(<07", "#(#1 -XQ",
  };
  for (const char* line : lines)
    expectSamePaths(std::string("%P\n") + line + "\nM2\n%\n", line);
  expectSamePaths("%P\n#1=" + std::string(70, '(') + "1" + std::string(70, ')') + "\n%\n",
                  "70 parentheses");
  expectSamePaths("%P\nX" + std::string(5000, '(') + "1\n%\n", "5000 open parentheses");
  expectSamePaths("%" + std::string(81, 'A') + "\n%\n", "a long name");
  expectSamePaths("%A B\n%\n% X\n%\n%A-B\n%\n", "bad names");
}

TEST(Wl4PathEquivalence, WellFormedLinesGiveTheSameIrBothWays) {
  const char* const lines[] = {
      "/N023 G0 X-1.5 Y.5 Z1. $ a comment",
      "N010 G1 X#1 Y-#2 Z+#3 F(#4*2)",
      "#1=#2=3 X#5=(#1+1)",
      "IF (#1==1 AND #2<>3 OR #4>=5 XOR #6<=7) N017",
      "IF3 (#1>#2) G1 X1 L0703",
      "X(ATAN(1)/(2)) Y(ATAN(1)/2) Z(SQRT(4)**2 MOD 3)",
      "X(-(-#1)) Y(FIX(-1.5)+FUP(1.5)+ROUND(2.5))",
      "#(#1+2)=5 X#(3)",
      "G1 X1 .A MESSAGE $ AND A COMMENT",
      ".5 MM STOCK LEFT",
      "X1 .5",
      "G1X10.Y5",
      "X1.5.3",
      "%MAIN_1 $ the heading",
      "% $ the end",
      "X( 1 + 2 ) Y ( #1 ) Z - 5",
  };
  for (const char* line : lines)
    expectSamePaths(std::string(line[0] == '%' ? "" : "%P\n") + line + "\n", line);
}

// Random blocks from WL4's pieces: words, expressions, keywords, stray characters.
std::string randomBlock(std::uint64_t& state) {
  auto next = [&] {
    state ^= state << 13, state ^= state >> 7, state ^= state << 17;
    return state;
  };
  static const char* const pieces[] = {
      "G",    "X",     "N",  "L",   "#",   "IF", "(",   ")",   "=",    "==",   "<>",    "<",
      ">=",   "+",     "-",  "*",   "**",  "/",  "MOD", "AND", "XOR",  "ABS(", "ATAN(", ".",
      "1",    "07",    "12", "3.5", ".25", "7.", " ",   " ",   "  ",   "#1",   "#(",    "IF3",
      "N010", "L0703", "X1", "Y-2", "$C",  "Q",  ",",   "%",   "SQRT", "FIX(", "0",     "65536"};
  std::string b;
  const int n = 1 + static_cast<int>(next() % 9);
  for (int k = 0; k < n; ++k)
    b += pieces[next() % (sizeof pieces / sizeof *pieces)];
  return b;
}

TEST(Wl4PathEquivalence, GeneratedBlocksParseIdenticallyBothWays) {
  std::uint64_t state = 0x2545F4914F6CDD1Dull;
  std::size_t blocks = 0;
  for (int r = 0; r < 3000; ++r) {
    std::string text = "%P\n";
    for (int i = 0; i < 5; ++i)
      text += randomBlock(state) + "\n";
    blocks += expectSamePaths(text + "%\n", "generated");
    if (HasFailure()) break;
  }
  EXPECT_GT(blocks, 7000u); // 6000 program lines and over 1000 generated blocks without error
}

} // namespace
} // namespace gcx::test
