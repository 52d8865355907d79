#include "report/excerpt.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace gcx::report {
namespace {

namespace fs = std::filesystem;

fs::path writeTemp(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("gcx-excerpt-" + name);
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string numbered(int lines, bool lastNewline) {
  std::string s;
  for (int i = 1; i <= lines; ++i) {
    s += 'N';
    s += std::to_string(i);
    if (i < lines || lastNewline) s += '\n';
  }
  return s;
}

std::vector<int> numbers(const std::vector<ExcerptLine>& lines) {
  std::vector<int> out;
  for (const auto& l : lines)
    out.push_back(l.number);
  return out;
}

TEST(Excerpt, LinesAroundTheLocationClippedToTheFile) {
  const fs::path p = writeTemp("twenty", numbered(20, false));
  const auto mid = readExcerpt(p.string(), 10, 2);
  EXPECT_EQ(numbers(mid), (std::vector<int>{8, 9, 10, 11, 12}));
  EXPECT_EQ(mid[2].text, "N10");
  EXPECT_EQ(numbers(readExcerpt(p.string(), 2, 5)), (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
  const auto end = readExcerpt(p.string(), 19, 5); // the last line has no line end
  EXPECT_EQ(numbers(end), (std::vector<int>{14, 15, 16, 17, 18, 19, 20}));
  EXPECT_EQ(end.back().text, "N20");
  EXPECT_TRUE(readExcerpt(p.string(), 0, 5).empty());
  EXPECT_TRUE(readExcerpt((p.string() + ".missing"), 3, 5).empty());
  fs::remove(p);
}

TEST(Excerpt, CrLfEmptyAndLongLines) {
  const fs::path p = writeTemp("mixed", "G0 X1\r\n\r\n" + std::string(1000, 'X') + "\nM30\n");
  const auto lines = readExcerpt(p.string(), 2, 2, 10);
  ASSERT_EQ(numbers(lines), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(lines[0].text, "G0 X1");
  EXPECT_EQ(lines[1].text, "");
  EXPECT_EQ(lines[2].text, "XXXXXXXXXX\xE2\x80\xA6");
  EXPECT_EQ(lines[3].text, "M30");
  fs::remove(p);
}

} // namespace
} // namespace gcx::report
