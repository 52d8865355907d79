// Mutation tests of gcx equiv (docs/equivalence.md): single changes to example programs, each
// judged different with the mutated block named (as the block that moves differently, the block
// that set the differing state, or the call whose repeat count changed), and changes of
// segmentation only, each judged equivalent.
#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

#include "equiv/equiv.h"
#include "equiv/report.h"
#include "support/equiv_support.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using equiv::DivergenceKind;
using equiv::ProgramInput;

struct Mutation {
  const char* dir;  // examples/nct or tests/differential/programs
  const char* main; // the program compared
  const char* file; // the file mutated (main, or a subprogram it calls)
  int line;
  const char* from; // the whole original line
  const char* to;   // its replacement (may hold several lines)
  DivergenceKind kind;
  /// Where the report names the mutation: "B" (B's event is at the line), "set" (the state was
  /// set at the line on B), "chain" (A's call chain passes the line).
  const char* named;
};

std::ostream& operator<<(std::ostream& os, const Mutation& m) {
  return os << m.file << ":" << m.line << " '" << m.from << "' -> '" << m.to << "'";
}

constexpr const char* kEx = "examples/nct";
constexpr const char* kDiff = "tests/differential/programs";
constexpr auto G = DivergenceKind::Geometry;
constexpr auto S = DivergenceKind::State;
constexpr auto E = DivergenceKind::Event;

const Mutation kMutations[] = {
    // coordinates
    {kEx, "O1001", "O1001", 16, "G1 X130 F800", "G1 X129.5 F800", G, "B"},
    {kEx, "O1001", "O1001", 30, "G1 Z-10.5 F300", "G1 Z-10 F300", G, "B"},
    {kEx, "O1003", "O1003", 18, "G99 G81 X20 Y60 Z-3.5 R3 F120", "G99 G81 X20 Y60 Z-4 R3 F120", G,
     "B"},
    {kEx, "O1003", "O1003", 19, "X50", "X51", G, "B"},
    {kEx, "O1004", "O1004", 12, "G99 G81 X-30 Y-20 Z-26 R3 F180", "G99 G81 X-30 Y-20 Z-25 R3 F180",
     G, "B"},
    {kEx, "O1002", "O1002", 14, "G1 X57 F600", "G1 X57.5 F600", G, "B"},
    {kEx, "O1007", "O2001", 7, "G1 X80 ZI-1 F400", "G1 X80 ZI-1.5 F400", G, "B"},
    // arcs: direction, the other arc of an R, helix turns
    {kEx, "O1001", "O1001", 33, "G2 X0 Y65 I5 J0", "G3 X0 Y65 I5 J0", G, "B"},
    {kEx, "O1001", "O1001", 35, "G2 X105 Y50 R15", "G2 X105 Y50 R-15", G, "B"},
    {kEx, "O1001", "O1001", 40, "G3 X41.339746 Y-5 I-8.660254 J5",
     "G2 X41.339746 Y-5 I-8.660254 J5", G, "B"},
    {kEx, "O1002", "O1002", 15, "G3 Z-12 I-7 L5", "G3 Z-12 I-7 L4", G, "B"},
    // feeds
    {kEx, "O1001", "O1001", 32, "G1 Y60 F700", "G1 Y60 F650", S, "B"},
    {kEx, "O1004", "O1004", 27, "G99 G84 X-30 Y-20 Z-20 R5 F450", "G99 G84 X-30 Y-20 Z-20 R5 F400",
     S, "B"},
    {kEx, "O1007", "O1007", 16, "G1 X80 F400", "G1 X80 F300", S, "B"},
    // dwells: changed, dropped, added (a G84 dwell at the bottom)
    {kDiff, "27_dwell", "27_dwell", 5, "G4 P2", "G4 P2.5", E, "B"},
    {kDiff, "27_dwell", "27_dwell", 9, "G4 P1.25", "(no dwell)", E, "A"},
    {kDiff, "41_cycle_g82_dwell", "41_cycle_g82_dwell", 6, "X20 P1.25", "X20 P1", E, "B"},
    {kEx, "O1004", "O1004", 27, "G99 G84 X-30 Y-20 Z-20 R5 F450",
     "G99 G84 X-30 Y-20 Z-20 R5 P500 F450", E, "B"},
    // return levels G98 <-> G99
    {kEx, "O1003", "O1003", 20, "G98 X80", "G99 X80", G, "B"},
    {kEx, "O1003", "O1003", 35, "G98 X95", "G99 X95", G, "B"},
    {kEx, "O1004", "O1004", 15, "G98 X-30", "G99 X-30", G, "B"},
    // peck depths
    {kEx, "O1003", "O1003", 32, "G99 G83 X20 Y20 Z-54 R3 Q6 E1 F180",
     "G99 G83 X20 Y20 Z-54 R3 Q5 E1 F180", G, "B"},
    {kEx, "O1003", "O1003", 47, "G99 G73 X20 Y60 Z-21.8 R3 Q2 E0.5 F160",
     "G99 G73 X20 Y60 Z-21.8 R3 Q2.5 E0.5 F160", G, "B"},
    // subprogram repeat count
    {kEx, "O1007", "O1007", 14, "M98 P2001 L5", "M98 P2001 L4", G, "chain"},
    // tools
    {kEx, "O1001", "O1001", 8, "T1 M6", "T3 M6", E, "B"},
    {kEx, "O1003", "O1003", 27, "T6 M6", "T4 M6", E, "B"},
    // coolant
    {kEx, "O1001", "O1001", 12, "M8", "M7", S, "set"},
    {kEx, "O1003", "O1003", 13, "M8", "M9", S, "set"},
    // spindle direction and speed
    {kEx, "O1001", "O1001", 9, "S3000 M3", "S3000 M4", S, "set"},
    {kEx, "O1003", "O1003", 28, "S1500 M3", "S1500 M4", S, "set"},
    {kEx, "O1001", "O1001", 25, "S8000 M3", "S7000 M3", S, "set"},
    {kEx, "O1007", "O1007", 8, "S7000 M3", "S7000 M5", S, "set"},
};

/// A copy of the program's folder with one line replaced; returns the main program's path.
fs::path mutate(const Mutation& m, const fs::path& dir) {
  fs::create_directories(dir);
  for (const fs::path& p : filesUnder(sourceDir() / m.dir, {".nct", ".json"}))
    fs::copy_file(p, dir / p.filename(), fs::copy_options::overwrite_existing);
  const fs::path target = dir / (std::string(m.file) + ".nct");
  std::string text = readFile(target), out;
  std::size_t pos = 0;
  for (int line = 1; pos <= text.size(); ++line) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string l = text.substr(pos, eol - pos);
    if (line == m.line) {
      EXPECT_EQ(l, m.from) << m;
      l = m.to;
    }
    out += l;
    if (eol < text.size()) out += '\n';
    pos = eol + 1;
  }
  std::ofstream(target, std::ios::binary) << out;
  return dir / (std::string(m.main) + ".nct");
}

std::string setupOf(const Mutation& m) {
  const fs::path s = sourceDir() / m.dir / (std::string(m.main) + ".setup.json");
  return fs::exists(s) ? s.string() : std::string();
}

class EquivMutation : public testing::TestWithParam<Mutation> {};

TEST_P(EquivMutation, JudgedDifferentAtTheMutatedLine) {
  const Mutation& m = GetParam();
  const fs::path dir =
      fs::temp_directory_path() / ("gcx-equiv-mutation-" + std::to_string(::getpid()) + "-" +
                                   m.file + "-" + std::to_string(m.line));
  const fs::path mutated = mutate(m, dir);
  const ProgramInput a{(sourceDir() / m.dir / (std::string(m.main) + ".nct")).string(), setupOf(m),
                       ProgramInput::Reader::Gcx};
  const ProgramInput b{mutated.string(), setupOf(m), ProgramInput::Reader::Gcx};
  const equiv::EquivOutcome o = equiv::checkEquivalence(a, b, equivOptions());
  fs::remove_all(dir);
  ASSERT_TRUE(o.ok) << m;
  ASSERT_FALSE(o.result.equivalent) << m;
  const equiv::Divergence& d = *o.result.divergence;
  const std::string report = equiv::renderText(o, 0.001);
  EXPECT_EQ(d.kind, m.kind) << m << "\n" << report;
  const std::string named = m.named;
  const std::string file = std::string(m.file) + ".nct";
  if (named == "B") {
    ASSERT_TRUE(d.b.present) << report;
    EXPECT_EQ(d.b.event.from.at.line, static_cast<std::uint32_t>(m.line)) << m << "\n" << report;
    EXPECT_EQ(fs::path(o.b->sources().name(d.b.event.from.at.file)).filename(), file) << report;
  } else if (named == "A") { // the line is gone from B: A's event is the original line
    ASSERT_TRUE(d.a.present) << report;
    EXPECT_EQ(d.a.event.from.at.line, static_cast<std::uint32_t>(m.line)) << m << "\n" << report;
  } else if (named == "set") {
    EXPECT_EQ(d.stateSetB.line, static_cast<std::uint32_t>(m.line)) << m << "\n" << report;
    EXPECT_NE(report.find(file + ":" + std::to_string(m.line) + ":1 (B)"), std::string::npos)
        << report;
  } else { // the call's repeat count: A's extra iteration is named as called from the line
    EXPECT_NE(report.find("from " + sourceDir().string() + "/" + m.dir + "/" + file + ":" +
                          std::to_string(m.line)),
              std::string::npos)
        << m << "\n"
        << report;
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, EquivMutation, testing::ValuesIn(kMutations),
                         [](const testing::TestParamInfo<Mutation>& p) {
                           return std::string(p.param.file) + "_line" +
                                  std::to_string(p.param.line) + "_" + std::to_string(p.index);
                         });

/// The R5 corner G2 X0 Y65 I5 J0 (from X-5 Y60) as 60 chords at equal angles.
constexpr const char* kCornerChords = "G1 X-4.998287 Y60.130885\nG1 X-4.993148 Y60.261680\nG1 "
                                      "X-4.984587 Y60.392295\nG1 X-4.972609 Y60.522642\n"
                                      "G1 X-4.957224 Y60.652631\nG1 X-4.938442 Y60.782172\nG1 "
                                      "X-4.916275 Y60.911178\nG1 X-4.890738 Y61.039558\n"
                                      "G1 X-4.861850 Y61.167227\nG1 X-4.829629 Y61.294095\nG1 "
                                      "X-4.794099 Y61.420077\nG1 X-4.755283 Y61.545085\n"
                                      "G1 X-4.713207 Y61.669034\nG1 X-4.667902 Y61.791840\nG1 "
                                      "X-4.619398 Y61.913417\nG1 X-4.567727 Y62.033683\n"
                                      "G1 X-4.512926 Y62.152555\nG1 X-4.455033 Y62.269952\nG1 "
                                      "X-4.394086 Y62.385794\nG1 X-4.330127 Y62.500000\n"
                                      "G1 X-4.263201 Y62.612493\nG1 X-4.193353 Y62.723195\nG1 "
                                      "X-4.120631 Y62.832031\nG1 X-4.045085 Y62.938926\n"
                                      "G1 X-3.966767 Y63.043807\nG1 X-3.885730 Y63.146602\nG1 "
                                      "X-3.802030 Y63.247240\nG1 X-3.715724 Y63.345653\n"
                                      "G1 X-3.626872 Y63.441773\nG1 X-3.535534 Y63.535534\nG1 "
                                      "X-3.441773 Y63.626872\nG1 X-3.345653 Y63.715724\n"
                                      "G1 X-3.247240 Y63.802030\nG1 X-3.146602 Y63.885730\nG1 "
                                      "X-3.043807 Y63.966767\nG1 X-2.938926 Y64.045085\n"
                                      "G1 X-2.832031 Y64.120631\nG1 X-2.723195 Y64.193353\nG1 "
                                      "X-2.612493 Y64.263201\nG1 X-2.500000 Y64.330127\n"
                                      "G1 X-2.385794 Y64.394086\nG1 X-2.269952 Y64.455033\nG1 "
                                      "X-2.152555 Y64.512926\nG1 X-2.033683 Y64.567727\n"
                                      "G1 X-1.913417 Y64.619398\nG1 X-1.791840 Y64.667902\nG1 "
                                      "X-1.669034 Y64.713207\nG1 X-1.545085 Y64.755283\n"
                                      "G1 X-1.420077 Y64.794099\nG1 X-1.294095 Y64.829629\nG1 "
                                      "X-1.167227 Y64.861850\nG1 X-1.039558 Y64.890738\n"
                                      "G1 X-0.911178 Y64.916275\nG1 X-0.782172 Y64.938442\nG1 "
                                      "X-0.652631 Y64.957224\nG1 X-0.522642 Y64.972609\n"
                                      "G1 X-0.392295 Y64.984587\nG1 X-0.261680 Y64.993148\nG1 "
                                      "X-0.130885 Y64.998287\nG1 X0.000000 Y65.000000";

// Changes of segmentation only: the same path cut differently, M and S words reordered.
const Mutation kSameMotion[] = {
    // a line split into collinear pieces
    {kEx, "O1001", "O1001", 16, "G1 X130 F800", "G1 X10 F800\nG1 X77.5\nG1 X130", G, ""},
    {kEx, "O1001", "O1001", 34, "G1 X90", "G1 X30\nG1 X60\nG1 X90", G, ""},
    // an arc split into arcs on the same circle (R15 about X90 Y50: through 45 degrees)
    {kEx, "O1001", "O1001", 35, "G2 X105 Y50 R15",
     "G2 X100.606602 Y60.606602 I0 J-15\nG2 X105 Y50 I-10.606602 J-10.606602", G, ""},
    {kEx, "O1002", "O1002", 16, "G3 I-7", "G3 X43 Y40 I-7\nG3 X57 Y40 I7", G, ""},
    // an arc as fine chords: the R5 corner as 60 chords (0.0002 mm sagitta)
    {kEx, "O1001", "O1001", 33, "G2 X0 Y65 I5 J0", kCornerChords, G, ""},
    // M and S words reordered, a redundant M5 while stopped
    {kEx, "O1001", "O1001", 9, "S3000 M3", "M3 S3000", S, ""},
    {kEx, "O1001", "O1001", 9, "S3000 M3", "M5\nS3000\nM3", S, ""},
    {kEx, "O1003", "O1003", 10, "S1800 M3", "M3\nS1800", S, ""},
};

class EquivSameMotion : public testing::TestWithParam<Mutation> {};

TEST_P(EquivSameMotion, JudgedEquivalent) {
  const Mutation& m = GetParam();
  const fs::path dir = fs::temp_directory_path() / ("gcx-equiv-same-" + std::to_string(::getpid()) +
                                                    "-" + m.file + "-" + std::to_string(m.line));
  const fs::path changed = mutate(m, dir);
  const ProgramInput a{(sourceDir() / m.dir / (std::string(m.main) + ".nct")).string(), setupOf(m),
                       ProgramInput::Reader::Gcx};
  const ProgramInput b{changed.string(), setupOf(m), ProgramInput::Reader::Gcx};
  const equiv::EquivOutcome o = equiv::checkEquivalence(a, b, equivOptions());
  fs::remove_all(dir);
  ASSERT_TRUE(o.ok) << m;
  EXPECT_TRUE(o.result.equivalent) << m << "\n" << equiv::renderText(o, 0.001);
}

INSTANTIATE_TEST_SUITE_P(Examples, EquivSameMotion, testing::ValuesIn(kSameMotion),
                         [](const testing::TestParamInfo<Mutation>& p) {
                           return std::string(p.param.file) + "_line" +
                                  std::to_string(p.param.line) + "_" + std::to_string(p.index);
                         });

TEST(EquivMutation, AtLeastThirty) {
  EXPECT_GE(std::size(kMutations), 30u);
}

} // namespace
} // namespace gcx::test
