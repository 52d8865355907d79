// Diagnostics read like clang's: file:line:col, severity, message, [code], line, caret.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace gcx::test {
namespace {

TEST(Diagnostics, TextHasLocationCodeLineAndCaret) {
  Parsed p = parseNct("G0 X0\nG1 X10 Y20 X30 F100\n", {.name = "part.nct"});
  ASSERT_EQ(p.diags.all().size(), 1u);
  EXPECT_EQ(diag::renderText(p.diags.all()[0], p.sources),
            "part.nct:2:12: error: address X appears twice in one block [GCX011]\n"
            "  G1 X10 Y20 X30 F100\n"
            "             ^~~\n");
}

TEST(Diagnostics, JsonCarriesTheSameFacts) {
  Parsed p = parseNct("G1 X1.2.3\n", {.name = "a.nct"});
  auto json = nlohmann::json::parse(diag::renderJson(p.diags.all(), p.sources));
  ASSERT_EQ(json.size(), 1u);
  EXPECT_EQ(json[0]["file"], "a.nct");
  EXPECT_EQ(json[0]["line"], 1);
  EXPECT_EQ(json[0]["column"], 8);
  EXPECT_EQ(json[0]["code"], "2064");
  EXPECT_EQ(json[0]["severity"], "error");
}

TEST(Diagnostics, SeveralErrorsInOneRun) {
  Parsed p = parseNct("G1 X1.2.3\nG0 G1 X1\nM3 M5\nGOTO 99\n");
  EXPECT_EQ(p.errors(),
            (std::vector<std::string>{"1:8 2064", "2:4 GCX012", "3:4 GCX014", "4:1 2125"}));
}

TEST(Diagnostics, ErrorLimitStopsCollecting) {
  std::string text;
  for (int i = 0; i < 100; ++i)
    text += "G1 X1.2.3\n";
  Parsed p;
  {
    diag::Engine e(10);
    for (int i = 0; i < 100; ++i)
      e.error("2064", {}, "x");
    EXPECT_EQ(e.errorCount(), 10u);
    EXPECT_TRUE(e.limitReached());
  }
}

} // namespace
} // namespace gcx::test
