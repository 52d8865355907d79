// Macro programs that load but cannot be expanded: each folder of
// tests/corpus/nct/macro-errors holds the main program O0001.nct, the programs it calls, and
// `expect` naming the first error (FILE:LINE:COL CODE); an optional `max_jumps` lowers the
// runaway-loop limit so endless loops stop quickly. Expansion stops at the error: the program
// never reaches its end.
#include <algorithm>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/run_support.h"

namespace gcx::test {
namespace {

const fs::path& corpus() {
  static const fs::path dir = sourceDir() / "tests" / "corpus" / "nct" / "macro-errors";
  return dir;
}

std::vector<fs::path> cases() {
  std::vector<fs::path> dirs;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(corpus(), ec))
    if (entry.is_directory() && fs::exists(entry.path() / "expect")) dirs.push_back(entry.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

std::string firstLine(const fs::path& file) {
  std::string text = readFile(file);
  text = text.substr(0, text.find('\n'));
  while (!text.empty() && (text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  return text;
}

struct Case {
  std::map<std::string, std::string> files; // name -> text, every .nct of the folder
  std::string expected;
  std::uint64_t maxJumps = 100000;
};

Case load(const fs::path& dir) {
  Case c;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".nct")
      c.files[entry.path().filename().string()] = readFile(entry.path());
  c.expected = firstLine(dir / "expect");
  if (fs::exists(dir / "max_jumps")) c.maxJumps = std::stoull(firstLine(dir / "max_jumps"));
  return c;
}

MacroRun run(const Case& c) {
  return runMacro(c.files, "O0001.nct", {}, {}, c.maxJumps);
}

std::string testName(const testing::TestParamInfo<fs::path>& info) {
  return info.param.filename().string();
}

class MacroError : public testing::TestWithParam<fs::path> {};

TEST_P(MacroError, StopsAtTheExpectedFirstError) {
  const Case c = load(GetParam());
  ASSERT_TRUE(c.files.count("O0001.nct")) << GetParam() << " has no O0001.nct";
  const MacroRun r = run(c);
  ASSERT_FALSE(r.errors.empty()) << "no error for " << GetParam();
  EXPECT_EQ(r.errors.front(), c.expected) << r.rendered;
  for (const motion::Event& e : r.events)
    EXPECT_NE(e.kind, motion::Kind::End) << "the program ran to its end\n" << r.rendered;
}

INSTANTIATE_TEST_SUITE_P(Nct, MacroError, testing::ValuesIn(cases()), testName);

TEST(MacroErrorCorpus, HasAtLeastTwentyCases) {
  EXPECT_GE(cases().size(), 20u);
}

// TV-26: the blocks before the alarm run, the alarm carries its text, nothing after it runs.
TEST(MacroErrorCorpus, AlarmStopsWithItsMessage) {
  const MacroRun r = run(load(corpus() / "alarm_3000"));
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors.front(), "O0001.nct:5:1 4012");
  EXPECT_THAT(r.rendered, testing::HasSubstr("TOOL BROKEN")) << r.rendered;
  EXPECT_EQ(r.motion(), (std::vector<std::string>{"R 0,0,5", "R 10,0,5"}));
}

} // namespace
} // namespace gcx::test
