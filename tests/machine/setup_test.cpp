// The machine setup file (--setup): parsed values, defaults, and located errors of every kind.
#include "machine/setup.h"

#include <filesystem>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cli/setup_dialects.h"
#include "diag/codes.h"

namespace gcx::test {
namespace {

using ::testing::HasSubstr;
using Xyz = std::array<double, 3>;

struct Loaded {
  SourceManager sources;
  diag::Engine diags{1000};
  std::optional<machine::Setup> setup;

  /// "line:col CODE" of every error, in order.
  std::vector<std::string> errors() const {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      if (d.severity == diag::Severity::Error)
        out.push_back(std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.col) +
                      " " + d.code);
    return out;
  }
  std::string message(std::size_t i) const { return diags.all().at(i).message; }
  std::string rendered() const {
    std::string out;
    for (const diag::Diagnostic& d : diags.all())
      out += diag::renderText(d, sources);
    return out;
  }
};

void parse(Loaded& l, const std::string& text) {
  l.setup = machine::parseSetup(text, l.sources.addBuffer("setup.json", text), l.diags,
                                cli::setupDialects("nct"));
}

// The key ranges at their edges: G54..G59, G54.1 P1..P99, tools 0..999, bits 0..7.
TEST(Setup, KeysAtTheEdgesOfTheirRanges) {
  Loaded ok;
  parse(ok, R"({"work_offsets": {"G59": [1, 2, 3], "G54.1 P99": [4, 5, 6], "G54.1 P1": [7, 8, 9]},
"tools": {"999": {"length": 9}}, "parameters": {"N1300.7": 1, "N1300.0": 1}})");
  ASSERT_TRUE(ok.setup) << ok.rendered();
  EXPECT_EQ(ok.setup->workOffset("G59"), (Xyz{1, 2, 3}));
  EXPECT_EQ(ok.setup->workOffset("G54.1 P99"), (Xyz{4, 5, 6}));
  EXPECT_EQ(ok.setup->tools.at(999).length, 9);
  EXPECT_EQ(ok.setup->parameter("N1300.7", 0), 1);
  Loaded past;
  parse(past,
        R"({"work_offsets": {"G53": [1, 2, 3], "G54.1 P100": [4, 5, 6], "G54.1 P0": [7, 8, 9]},
"tools": {"1000": {}}, "parameters": {"N1300.8": 1}})");
  EXPECT_FALSE(past.setup);
  EXPECT_EQ(past.errors(), (std::vector<std::string>{"1:19 GCX023", "1:37 GCX023", "1:62 GCX023",
                                                     "2:11 GCX023", "2:39 GCX023"}))
      << past.rendered();
}

TEST(Setup, ValidFileGivesExactValues) {
  Loaded l;
  parse(l, R"({
  // comments are allowed
  "work_offsets": {"G54": [100, 200, -300.5], "G54.1 P7": [1, 2, 3], "common": [0, 0, -1]},
  "tools": {"1": {"length": 101.6, "radius": 5}, "12": {"radius": 3}, "0": {}},
  "parameters": {"N1339": 0.01, "N607.ori": 1, "n1300.3": 1, "N12": 7},
  "variables": {"#500": 1.5, "#1": -2, "#999": 0},
  "initial_position": [10, 20, 30],
  "block_skip": [1, 3, 3],
  "reference_points": {"2": [1, 2, 3]},
  "rapid_rate": 15000
}
)");
  ASSERT_TRUE(l.setup) << l.rendered();
  EXPECT_TRUE(l.diags.all().empty());
  const machine::Setup& s = *l.setup;
  EXPECT_EQ(s.workOffsets,
            (std::map<std::string, Xyz>{
                {"G54", {100, 200, -300.5}}, {"G54.1 P7", {1, 2, 3}}, {"common", {0, 0, -1}}}));
  EXPECT_EQ(s.workOffset("G54"), (Xyz{100, 200, -300.5}));
  EXPECT_EQ(s.workOffset("G55"), (Xyz{0, 0, 0}));
  ASSERT_EQ(s.tools.size(), 3u);
  EXPECT_EQ(s.tools.at(1).length, 101.6);
  EXPECT_EQ(s.tools.at(1).radius, 5);
  EXPECT_EQ(s.tools.at(12).length, 0);
  EXPECT_EQ(s.tools.at(12).radius, 3);
  EXPECT_EQ(s.tools.at(0).length, 0);
  EXPECT_EQ(s.parameters, (std::map<std::string, double>{
                              {"N1339", 0.01}, {"N0607.ORI", 1}, {"N1300.3", 1}, {"N0012", 7}}));
  EXPECT_EQ(s.parameter("N1339", 0), 0.01);
  EXPECT_EQ(s.parameter("N0607.ORI", 0), 1); // under the canonical key the file's became
  EXPECT_EQ(s.parameter("N1404", 3), 3);
  EXPECT_EQ(s.variables, (std::map<int, double>{{1, -2}, {500, 1.5}, {999, 0}}));
  EXPECT_EQ(s.initialPosition, (Xyz{10, 20, 30}));
  EXPECT_EQ(s.blockSkip, (std::set<int>{1, 3}));
  EXPECT_EQ(s.referencePoints,
            (std::map<int, Xyz>{{1, {0, 0, 0}}, {2, {1, 2, 3}}, {3, {0, 0, 0}}, {4, {0, 0, 0}}}));
  EXPECT_EQ(s.rapidRate, 15000);
}

TEST(Setup, EmptyObjectIsTheReferenceProfile) {
  Loaded l;
  parse(l, " {}\n");
  ASSERT_TRUE(l.setup);
  const machine::Setup& s = *l.setup;
  EXPECT_TRUE(s.workOffsets.empty());
  EXPECT_TRUE(s.tools.empty());
  EXPECT_TRUE(s.parameters.empty());
  EXPECT_TRUE(s.variables.empty());
  EXPECT_EQ(s.initialPosition, (Xyz{0, 0, 0}));
  EXPECT_TRUE(s.blockSkip.empty());
  EXPECT_EQ(s.referencePoints.size(), 4u);
  for (const auto& [n, xyz] : s.referencePoints)
    EXPECT_EQ(xyz, (Xyz{0, 0, 0})) << n;
  EXPECT_EQ(s.rapidRate, 10000);
}

TEST(Setup, NotJsonIsLocatedWhereTheParserStopped) {
  {
    Loaded l;
    parse(l, "{\n  \"tools\": {\"1\": {\"length\": 1,}}\n}\n");
    EXPECT_FALSE(l.setup);
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"2:31 GCX020"}));
    EXPECT_EQ(l.message(0), "setup file is not valid JSON: syntax error while parsing object key "
                            "- unexpected '}'; expected string literal");
  }
  {
    Loaded l;
    parse(l, "");
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:1 GCX020"}));
  }
  {
    Loaded l;
    parse(l, "{\"rapid_rate\": \"fast\nslow\"}");
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:21 GCX020"}));
  }
  {
    Loaded l;
    parse(l, "{}\n\n  x\n");
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"3:3 GCX020"}));
  }
}

TEST(Setup, NumberBeyondDoubleIsOutOfRange) {
  Loaded l;
  parse(l, "{\n  \"rapid_rate\": 1e999\n}");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"2:17 GCX023"}));
  EXPECT_EQ(l.message(0), "number 1e999 is out of range");
}

TEST(Setup, UnknownKeysNameTheAllowedOnes) {
  Loaded l;
  parse(l, R"({
  "work_offsets": {},
  "tool": {},
  "tools": {"3": {"length": 1, "diameter": 10}}
}
)");
  EXPECT_FALSE(l.setup);
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"3:3 GCX021", "4:32 GCX021"}));
  EXPECT_EQ(l.message(0), "unknown key \"tool\" in the setup; the keys are work_offsets, tools, "
                          "parameters, variables, initial_position, block_skip, "
                          "reference_points, rapid_rate, and the dialect sections nct, fms3000, "
                          "wl4");
  EXPECT_EQ(l.message(1),
            "unknown key \"diameter\" in tool 3; the keys are length, radius, nose_radius, "
            "turning");
}

TEST(Setup, TurningOffsetsAreThreeNumbers) { // G43.7 (nct.md §3.16)
  Loaded l;
  parse(l, R"({"tools": {"11": {"turning": [152.3, 0, 96.5]}}})");
  ASSERT_TRUE(l.setup) << l.rendered();
  EXPECT_EQ(l.setup->tools.at(11).turning, (Xyz{152.3, 0, 96.5}));
  Loaded bad;
  parse(bad, R"({"tools": {"11": {"turning": [1, 2]}}})");
  EXPECT_FALSE(bad.setup);
  EXPECT_EQ(bad.errors(), (std::vector<std::string>{"1:30 GCX023"}));
}

TEST(Setup, ANoseRadiusIsANumberNotBelowZero) { // WL4's Rt (wl4.md §4.1, 002:1324-1326)
  Loaded l;
  parse(l, R"({"tools": {"1": {"nose_radius": 0.8, "radius": -0.3}}})");
  ASSERT_TRUE(l.setup) << l.rendered();
  EXPECT_EQ(l.setup->tools.at(1).noseRadius, 0.8);
  EXPECT_EQ(l.setup->tools.at(1).radius, -0.3);
  Loaded bad;
  parse(bad, R"({"tools": {"1": {"nose_radius": -0.1}}})");
  EXPECT_FALSE(bad.setup);
  EXPECT_EQ(bad.errors(), (std::vector<std::string>{"1:33 GCX023"}));
}

TEST(Setup, WrongTypesAreLocatedAtTheValue) {
  Loaded l;
  parse(l, R"({
  "rapid_rate": "fast",
  "tools": {"1": {"length": "101.6"}, "2": 5},
  "work_offsets": {"G54": {"x": 1}, "G55": [1, "2", 3]},
  "block_skip": 1,
  "variables": {"#100": null}
}
)");
  EXPECT_FALSE(l.setup);
  EXPECT_EQ(l.errors(),
            (std::vector<std::string>{"2:17 GCX022", "3:29 GCX022", "3:44 GCX022", "4:27 GCX022",
                                      "4:48 GCX022", "5:17 GCX022", "6:25 GCX022"}));
  EXPECT_EQ(l.message(0), "rapid_rate must be a number, not a string");
  EXPECT_EQ(l.message(1), "tool 1 length must be a number, not a string");
  EXPECT_EQ(l.message(2), "tool 2 must be an object {...}, not a number");
  EXPECT_EQ(l.message(3), "work offset G54 must be an array of 3 numbers [x, y, z], not an object");
  EXPECT_EQ(l.message(4), "work offset G55 y must be a number, not a string");
  EXPECT_EQ(l.message(6), "#100 must be a number, not null");
}

TEST(Setup, TheWholeFileMustBeAnObject) {
  Loaded l;
  parse(l, "\n  [1, 2, 3]\n");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"2:3 GCX022"}));
}

TEST(Setup, OutOfRangeValuesAndMalformedKeys) {
  Loaded l;
  parse(l, R"({
  "work_offsets": {"G60": [0, 0, 0], "G54": [1, 2], "g54.1p07": [0, 0, 0]},
  "parameters": {"N12345": 1, "N1300.8": 1, "N1300.3": 2, "N1.x2": 0},
  "variables": {"#50": 1, "#abc": 2, "#1000": 3},
  "tools": {"-1": {}, "1000": {}, "T1": {}},
  "block_skip": [0, 1.5, 10, 9],
  "reference_points": {"5": [0, 0, 0], "1": [0, 0, 0, 0]},
  "rapid_rate": 0
}
)");
  EXPECT_FALSE(l.setup);
  EXPECT_EQ(l.errors(),
            (std::vector<std::string>{"2:20 GCX023", "2:45 GCX023", "2:53 GCX023", "3:18 GCX023",
                                      "3:31 GCX023", "3:56 GCX023", "3:59 GCX023", "4:17 GCX023",
                                      "4:27 GCX023", "4:38 GCX023", "5:13 GCX023", "5:23 GCX023",
                                      "5:35 GCX023", "6:18 GCX023", "6:21 GCX023", "6:26 GCX023",
                                      "7:24 GCX023", "7:45 GCX023", "8:17 GCX023"}))
      << l.rendered();
  EXPECT_EQ(l.message(0), "\"G60\" is not a work offset; the keys are G54..G59, "
                          "\"G54.1 P1\"..\"G54.1 P99\" and \"common\"");
  EXPECT_EQ(l.message(1), "work offset G54 must have exactly 3 numbers [x, y, z], not 2");
  EXPECT_EQ(l.message(2), "work offset \"g54.1p07\" should be written \"G54.1 P7\"");
  EXPECT_THAT(l.message(3), HasSubstr("\"N12345\" is not a parameter"));
  EXPECT_EQ(l.message(4), "\"N1300.8\": bit numbers are 0..7");
  EXPECT_EQ(l.message(5), "bit parameter N1300.3 must be 0 or 1, not 2");
  EXPECT_EQ(l.message(7), "#50 cannot be preset; the setup may set #1-#33 and #100-#999");
  EXPECT_EQ(l.message(8), "\"#abc\" is not a macro variable; write #n, e.g. \"#500\"");
  EXPECT_EQ(l.message(10), "\"-1\" is not a tool number; tools are numbered 0..999");
  EXPECT_EQ(l.message(14), "block-skip switches are 1..9, not 1.5");
  EXPECT_EQ(l.message(16), "\"5\" is not a reference point; the keys are \"1\"..\"4\"");
  EXPECT_EQ(l.message(18), "rapid_rate must be more than 0 mm/min, not 0");
}

TEST(Setup, AllKindsOfErrorsInOneRunInFileOrder) {
  Loaded l;
  parse(l, R"({"tools": {"1": {"length": true}}, "offsets": 1, "rapid_rate": -1})");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:28 GCX022", "1:36 GCX021", "1:64 GCX023"}));
}

TEST(Setup, LocatorFollowsNestingAndSkipsStringsAndComments) {
  Loaded l;
  // "1" and "length" appear earlier under other parents, inside a string and in a comment
  parse(l, R"({
  "reference_points": {"1": [0, 0, 0]},
  "work_offsets": {"G54": [0, 0, 0], "G55": "\"1\": {\"length\": \"x\"} /* \"tools\" */"},
  /* "tools": {"1": {"length": "comment"}} */
  "tools": {"1": {"length": "x"}}
}
)");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"3:45 GCX022", "5:29 GCX022"}));
}

TEST(Setup, EscapedKeysAreDecoded) {
  Loaded l;
  parse(l, R"({"tools": {"1": {"len\u0067th": "x"}}})");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:33 GCX022"}));
  EXPECT_EQ(l.message(0), "tool 1 length must be a number, not a string");
}

TEST(Setup, RepeatedKeyPointsAtBothPlaces) {
  Loaded l;
  parse(l, "{\n  \"rapid_rate\": 100,\n  \"rapid_rate\": 200\n}\n");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"3:3 GCX023"}));
  const diag::Diagnostic& d = l.diags.all().at(0);
  EXPECT_EQ(d.message, "key \"rapid_rate\" given twice");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].range.begin.line, 2u);
  EXPECT_EQ(d.notes[0].range.begin.col, 3u);
}

TEST(Setup, TwoSpellingsOfOneEntryAreRepeats) {
  {
    Loaded l;
    parse(l, R"({"parameters": {"N1339": 0.01, "n1339": 0.02}})");
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:32 GCX023"}));
    EXPECT_EQ(l.message(0), "\"N1339\" and \"n1339\" are both parameter N1339");
    EXPECT_EQ(l.diags.all()[0].notes.at(0).range.begin.col, 17u);
  }
  {
    Loaded l; // "#0500" sorts before "#500"; the later one in the file is still the error
    parse(l, R"({"variables": {"#500": 1, "#0500": 2}})");
    EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:27 GCX023"}));
    EXPECT_EQ(l.diags.all()[0].notes.at(0).range.begin.col, 16u);
  }
}

TEST(Setup, RenderedLikeEveryOtherDiagnostic) {
  Loaded l;
  parse(l, R"({"work_offsets": {"G60": [0, 0, 0]}})");
  EXPECT_EQ(l.rendered(), "setup.json:1:19: error: \"G60\" is not a work offset; the keys are "
                          "G54..G59, \"G54.1 P1\"..\"G54.1 P99\" and \"common\" [GCX023]\n"
                          "  {\"work_offsets\": {\"G60\": [0, 0, 0]}}\n"
                          "                    ^~~~~\n");
}

TEST(Setup, ByteOrderMarkAndCrLf) {
  Loaded l;
  parse(l, "\xEF\xBB\xBF{\r\n  \"rapid_rate\": -5\r\n}\r\n");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"2:17 GCX023"}));
}

TEST(Setup, DeepNestingDoesNotExhaustTheStack) {
  Loaded l;
  parse(l, "{\"x\": " + std::string(20000, '[') + std::string(20000, ']') + "}");
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"1:2 GCX021"}));
}

TEST(Setup, LoadReadsTheFileAndNamesItInLocations) {
  const auto path = std::filesystem::temp_directory_path() / "gcx_setup_test.json";
  {
    std::ofstream out(path, std::ios::binary);
    out << "{\"tools\": {\"5\": {\"radius\": 2}},\n \"rapid_rate\": \"x\"}\n";
  }
  Loaded l;
  EXPECT_FALSE(machine::loadSetup(path.string(), l.sources, l.diags, cli::setupDialects("nct")));
  EXPECT_EQ(l.errors(), (std::vector<std::string>{"2:16 GCX022"}));
  EXPECT_THAT(l.rendered(), HasSubstr(path.string() + ":2:16: error:"));
  {
    std::ofstream out(path, std::ios::binary);
    out << "{\"tools\": {\"5\": {\"radius\": 2}}}\n";
  }
  Loaded ok;
  const auto setup =
      machine::loadSetup(path.string(), ok.sources, ok.diags, cli::setupDialects("nct"));
  std::filesystem::remove(path);
  ASSERT_TRUE(setup);
  EXPECT_EQ(setup->tools.at(5).radius, 2);
}

TEST(Setup, UnreadableFileIsReportedWithoutLocation) {
  for (const std::string& path :
       {std::string("/nonexistent/setup.json"), std::filesystem::temp_directory_path().string()}) {
    Loaded l;
    EXPECT_FALSE(machine::loadSetup(path, l.sources, l.diags, cli::setupDialects("nct")));
    ASSERT_EQ(l.diags.all().size(), 1u);
    const diag::Diagnostic& d = l.diags.all()[0];
    EXPECT_EQ(d.code, diag::code::SetupCannotRead);
    EXPECT_FALSE(d.range.begin.valid());
    EXPECT_THAT(d.message, HasSubstr(path + ": cannot read the setup file: "));
  }
}

} // namespace
} // namespace gcx::test
