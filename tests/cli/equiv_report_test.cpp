// gcx equiv --report on an example and a copy with one coordinate changed: the page names the
// changed line on both sides and marks where the paths part; it is written only when complete.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fmt/format.h>
#include <fstream>

#include "support/test_support.h"

namespace gcx::test {
namespace {

struct ReportRun {
  int exitCode = -1;
  std::string html;
};

ReportRun equivReport(const fs::path& a, const fs::path& b, const fs::path& report) {
  const fs::path setup = sourceDir() / "examples" / "nct" / "O1001.setup.json";
  const std::string cmd =
      fmt::format("{} equiv {} {} --setup {} --report {} >/dev/null 2>&1", GCX_BINARY, a.string(),
                  b.string(), setup.string(), report.string());
  ReportRun r;
  r.exitCode = WEXITSTATUS(std::system(cmd.c_str()));
  if (fs::exists(report)) r.html = readFile(report);
  return r;
}

// O1001 with line 16 "G1 X130 F800" (the first face pass) changed to X131.
fs::path mutatedO1001(const fs::path& dir) {
  std::string text = readFile(sourceDir() / "examples" / "nct" / "O1001.nct");
  const auto at = text.find("\nG1 X130 F800\n");
  EXPECT_NE(at, std::string::npos);
  text.replace(at, 14, "\nG1 X131 F800\n");
  const fs::path p = dir / "O1001.nct";
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

TEST(EquivReport, NamesTheChangedLineOnBothSidesAndMarksTheDivergence) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("gcx-equiv-report-{}", ::getpid());
  fs::create_directories(dir);
  const fs::path original = sourceDir() / "examples" / "nct" / "O1001.nct";
  const ReportRun r = equivReport(original, mutatedO1001(dir), dir / "report.html");
  EXPECT_EQ(r.exitCode, 1);
  ASSERT_FALSE(r.html.empty());
  EXPECT_NE(r.html.find("<p class=\"verdict different\">Different: end point X differs by 1.000 "
                        "mm</p>"),
            std::string::npos);
  // the face pass ends at X130 Y10 of G54 (−412.5, −230): machine X−282.5 Y−220
  EXPECT_NE(r.html.find("<g id=\"divergence\" data-x=\"-282.5\" data-y=\"220\""),
            std::string::npos);
  EXPECT_NE(r.html.find("<div class=\"row hit\"><span class=\"ln\">16</span>G1 X130 F800</div>"),
            std::string::npos);
  EXPECT_NE(r.html.find("<div class=\"row hit\"><span class=\"ln\">16</span>G1 X131 F800</div>"),
            std::string::npos);
  EXPECT_NE(r.html.find("O1001.nct:16:1</td>"), std::string::npos);
  // both whole paths are drawn: the second face pass runs back to X−30 at Y50 (SVG y 180)
  EXPECT_NE(r.html.find("id=\"path-a\""), std::string::npos);
  EXPECT_NE(r.html.find("d=\"M-282.5 180L-442.5 180\""), std::string::npos);
  EXPECT_GT(r.html.find("d=\"M-281.5 180L-442.5 180\""), r.html.find("id=\"path-b\""));
  EXPECT_NE(r.html.find("d=\"M-281.5 180L-442.5 180\""), std::string::npos);

  // the same program twice: equivalent, no marker
  const ReportRun same = equivReport(original, original, dir / "same.html");
  EXPECT_EQ(same.exitCode, 0);
  EXPECT_NE(same.html.find("<p class=\"verdict equivalent\">"), std::string::npos);
  EXPECT_EQ(same.html.find("id=\"divergence\""), std::string::npos);

  // a report that cannot be written is a usage error, and leaves nothing behind
  const ReportRun nowhere = equivReport(original, original, dir / "missing" / "r.html");
  EXPECT_EQ(nowhere.exitCode, 2);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  fs::remove_all(dir);
}

} // namespace
} // namespace gcx::test
