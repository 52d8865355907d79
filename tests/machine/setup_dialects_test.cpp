// The setup file's dialect-owned keys (docs/setup.md): each dialect's parameter and variable
// syntax from its profile, and the dialect sections of a setup shared by several dialects.
#include "cli/setup_dialects.h"

#include <gtest/gtest.h>

#include "diag/codes.h"
#include "machine/setup.h"

namespace gcx::test {
namespace {

struct Read {
  SourceManager sources;
  diag::Engine diags{1000};
  std::optional<machine::Setup> setup;

  /// "line:col CODE message" of every error, in order.
  std::vector<std::string> errors() const {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      out.push_back(std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.col) +
                    " " + d.code + " " + d.message);
    return out;
  }
};

Read readFor(const std::string& dialect, const std::string& text) {
  Read r;
  r.setup = machine::parseSetup(text, r.sources.addBuffer("setup.json", text), r.diags,
                                cli::setupDialects(dialect));
  return r;
}

using Params = std::map<std::string, double>;
using Vars = std::map<int, double>;

constexpr const char* shared = R"({
  "work_offsets": {"G55": [1, 2, 3], "G54.1 P7": [4, 5, 6]},
  "nct": {"parameters": {"N1339": 0.05, "n607.ori": 0}, "variables": {"#500": 2}},
  "fms3000": {"parameters": {"N3021": 1}},
  "wl4": {"parameters": {"ARC_TOLERANCE": 0.005}, "variables": {"#31": 7}}
})";

// Each program reads its own section and only its own: NCT's N1339 is not FMS-3000's.
TEST(SetupDialects, EachDialectReadsItsOwnSection) {
  const Read nct = readFor("nct", shared);
  ASSERT_TRUE(nct.setup) << ::testing::PrintToString(nct.errors());
  EXPECT_EQ(nct.setup->parameters, (Params{{"N1339", 0.05}, {"N0607.ORI", 0}}));
  EXPECT_EQ(nct.setup->variables, (Vars{{500, 2}}));
  const Read fms = readFor("fms3000", shared);
  ASSERT_TRUE(fms.setup);
  EXPECT_EQ(fms.setup->parameters, (Params{{"N3021", 1}}));
  EXPECT_TRUE(fms.setup->variables.empty());
  const Read wl4 = readFor("wl4", shared);
  ASSERT_TRUE(wl4.setup);
  EXPECT_EQ(wl4.setup->parameters, (Params{{"arc_tolerance", 0.005}}));
  EXPECT_EQ(wl4.setup->variables, (Vars{{31, 7}}));
  // the machine is shared: every dialect sees the same offsets
  for (const Read* r : {&nct, &fms, &wl4})
    EXPECT_EQ(r->setup->workOffset("G54.1 P7"), (std::array<double, 3>{4, 5, 6}));
}

// Top-level parameters and variables are the program's dialect's, in its syntax.
TEST(SetupDialects, TopLevelKeysUseTheProgramsSyntax) {
  const std::string text = R"({"parameters": {"arc_tolerance": 0.02}, "variables": {"#40": 1}})";
  const Read wl4 = readFor("wl4", text);
  ASSERT_TRUE(wl4.setup);
  EXPECT_EQ(wl4.setup->parameters, (Params{{"arc_tolerance", 0.02}}));
  const Read nct = readFor("nct", text);
  EXPECT_FALSE(nct.setup);
  EXPECT_EQ(nct.errors(),
            (std::vector<std::string>{
                "1:17 GCX023 \"arc_tolerance\" is not a parameter; nct parameters are N and 1-4 "
                "digits, optionally followed by .BIT with BIT 0-7 or a bit name (\"N0001\")",
                "1:55 GCX023 #40 cannot be preset; the setup may set #1-#33 and #100-#999"}));
  const Read fms = readFor("fms3000", R"({"parameters": {"N3021.1": 1}, "variables": {"#1": 1}})");
  EXPECT_EQ(fms.errors(),
            (std::vector<std::string>{
                "1:17 GCX023 \"N3021.1\" is not a parameter; fms3000 parameters are N and 1-4 "
                "digits (\"N0001\")",
                "1:46 GCX023 #1 cannot be preset; fms3000 has no variables a setup may preset"}));
}

// FMS-3000 N3022 (fms3000.md §3.3, 001:1137-1145) and N3035 (§4.2, 001:2176-2190): gcx models
// one value of each; another is refused where the setup writes it, never silently ignored.
TEST(Fms3000Spec_3_3, N3022AndN3035OnlyTakeTheValuesGcxModels) {
  const Read good = readFor("fms3000", R"({"parameters": {"N3022": 1, "N3035": 1}})");
  ASSERT_TRUE(good.setup);
  EXPECT_EQ(good.setup->parameters, (Params{{"N3022", 1}, {"N3035", 1}}));
  const Read bad = readFor("fms3000", R"({"parameters": {"N3022": 0,
"N3035": 2}})");
  EXPECT_FALSE(bad.setup);
  EXPECT_EQ(bad.errors(),
            (std::vector<std::string>{
                "1:26 GCX023 N3022 = 0: only 1, \"G0 with linear interpolation\" (a straight "
                "rapid), is modelled; \"G0 without interpolation\" (each axis at its own rate, a "
                "dog-leg path, 001:1137-1145) is not",
                "2:10 GCX023 N3035 = 2: only 1 (the cancel removes the offset on both plane axes "
                "when a plane axis moves) is modelled; 0 (only on the moved axis) and 2 (even "
                "without a move) are not (001:2176-2190)"}));
  // the rule is FMS-3000's: an NCT setup's N3022 is an ordinary parameter
  EXPECT_TRUE(readFor("nct", R"({"parameters": {"N3022": 0}})").setup);
}

// Another dialect's section is checked by that dialect's syntax even when it does not apply.
TEST(SetupDialects, OtherSectionsAreCheckedByTheirOwnSyntax) {
  const Read r = readFor("nct", R"({"wl4": {"parameters": {"N1339": 1}, "feed": 2},
"fms3000": []})");
  EXPECT_FALSE(r.setup);
  EXPECT_EQ(r.errors(),
            (std::vector<std::string>{
                "1:25 GCX023 \"N1339\" is not a parameter; wl4 parameters are \"arc_tolerance\", "
                "\"lathe\", \"gear_range\", \"b_chamfer\"",
                "1:38 GCX021 unknown key \"feed\" in the wl4 section; the keys are parameters, "
                "variables",
                "2:12 GCX022 the fms3000 section must be an object {...}, not an array"}));
}

// One parameter at the top level and again in the program's section: which one holds would be
// a guess, so it is an error with a note at the first.
TEST(SetupDialects, TopLevelAndOwnSectionMayNotBothSetAKey) {
  const Read r = readFor("nct", R"({"parameters": {"N1339": 1},
"nct": {"parameters": {"n1339": 2}}})");
  EXPECT_FALSE(r.setup);
  ASSERT_EQ(r.errors(), (std::vector<std::string>{"2:24 GCX023 \"N1339\" and \"n1339\" are both "
                                                  "parameter N1339"}));
  ASSERT_EQ(r.diags.all()[0].notes.size(), 1u);
  EXPECT_EQ(r.diags.all()[0].notes[0].range.begin.line, 1u);
}

// Work offsets are the machine's: a key any dialect names is accepted for every program, so a
// translation's source and target share one setup; a near miss names the intended key.
TEST(SetupDialects, WorkOffsetKeysComeFromTheProfiles) {
  const Read fms = readFor("fms3000", R"({"work_offsets": {"G54.1 P99": [1, 1, 1]}})");
  ASSERT_TRUE(fms.setup);
  const Read bad = readFor("fms3000", R"({"work_offsets": {"G54.1 P100": [1, 1, 1],
"g54.1p07": [0, 0, 0]}})");
  EXPECT_EQ(bad.errors(),
            (std::vector<std::string>{
                "1:19 GCX023 \"G54.1 P100\" is not a work offset; the keys are G54..G59 and "
                "\"common\"",
                "2:1 GCX023 work offset \"g54.1p07\" should be written \"G54.1 P7\""}));
}

// The syntax itself, from the profiles (machine rules, variable space).
TEST(SetupDialects, SyntaxIsTheProfilesData) {
  const machine::SetupDialects d = cli::setupDialects("nct");
  ASSERT_TRUE(d.own);
  EXPECT_EQ(d.own->parameterKey("n1300.3"), "N1300.3");
  EXPECT_EQ(d.own->parameterKey("N12345"), std::nullopt);
  EXPECT_EQ(d.own->parameterKey("N1300.8"), std::nullopt);
  EXPECT_TRUE(d.own->isWorkOffset("G54.1 P99"));
  EXPECT_FALSE(d.own->isWorkOffset("G54.1 P100"));
  const machine::SetupSyntax* fms = d.find("fms3000");
  ASSERT_TRUE(fms);
  EXPECT_EQ(fms->parameterKey("n7001"), "N7001");
  EXPECT_EQ(fms->parameterKey("N7001.2"), std::nullopt); // no bits
  EXPECT_FALSE(fms->isWorkOffset("G54.1 P1"));
  EXPECT_EQ(d.find("wl4")->presetVariables, (std::vector<std::pair<int, int>>{{1, 29}, {30, 99}}));
  EXPECT_EQ(d.find("wl4")->namedParameters,
            (std::vector<std::string>{"arc_tolerance", "lathe", "gear_range",
                                      "b_chamfer"})); // settings, B's role
  EXPECT_FALSE(cli::setupDialects("").own);
}

} // namespace
} // namespace gcx::test
