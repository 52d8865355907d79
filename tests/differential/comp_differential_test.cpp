// Cutter radius compensation against LinuxCNC's rs274 (docs/compensation.md, "LinuxCNC"), over
// the contours in tests/differential/comp (tool 1 of radius 3, comp/setup.json):
//  * contract: rs274 run on gcx's canonical output reproduces gcx's tool-centre path;
//  * semantics: rs274 compensating the program itself moves like gcx, or parts from it first
//    at the block comp/expected.txt names, for the documented reason.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fmt/format.h>
#include <map>
#include <sstream>
#include <sys/wait.h>

#include "cli/setup_dialects.h"
#include "differential/oracle_run.h"
#include "emit/canonical.h"
#include "machine/setup.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "oracle/setup.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

fs::path contours() {
  return sourceDir() / "tests" / "differential" / "comp";
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(contours(), {".nct"}))
    out.push_back(p.stem().string());
  return out;
}

/// name -> "same", "rejected" (by rs274), or the source line of gcx's first divergent move
/// ("line 4").
std::map<std::string, std::string> expected() {
  std::map<std::string, std::string> out;
  std::istringstream in(readFile(contours() / "expected.txt"));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string name, verdict, number;
    words >> name >> verdict;
    if (verdict == "line") words >> number, verdict += " " + number;
    out[name] = verdict;
  }
  return out;
}

struct Runs {
  ProgramRun ours;
  std::string canonical;
  oracle::Rs274Options options;
};

Runs runGcx(const std::string& name) {
  Runs r;
  const std::string json = readFile(contours() / "setup.json");
  SourceManager sm;
  diag::Engine diags;
  const auto setup =
      machine::parseSetup(json, sm.addBuffer("setup.json", json), diags, cli::setupDialects("nct"));
  EXPECT_TRUE(setup.has_value());
  std::ostringstream text;
  emit::CanonicalEmitter emitter(text);
  r.ours =
      runNct(readFile(contours() / (name + ".nct")), setup.value_or(machine::Setup{}), &emitter);
  r.canonical = text.str();
  oracle::OracleSetup s;
  std::string err;
  EXPECT_TRUE(oracle::parseSetupJson(json, s, err)) << err;
  oracle::applySetup(s, r.options);
  return r;
}

class CompDifferential : public testing::TestWithParam<std::string> {};

TEST_P(CompDifferential, Rs274ReproducesTheCompensatedPath) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  Runs r = runGcx(GetParam());
  ASSERT_TRUE(r.ours.errors.empty()) << r.ours.rendered;
  std::string failure;
  const auto theirs = runOracle(r.canonical, r.options, failure);
  ASSERT_TRUE(failure.empty()) << failure << "\n" << r.canonical;
  const oracle::CompareResult c = oracle::compareEvents(r.ours.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- canonical:\n" << r.canonical;
}

TEST_P(CompDifferential, Rs274CompensatingTheProgramAgreesOrPartsWhereDocumented) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  Runs r = runGcx(GetParam());
  ASSERT_TRUE(r.ours.errors.empty()) << r.ours.rendered;
  std::string failure;
  const auto theirs = runOracle(readFile(contours() / (GetParam() + ".nct")), r.options, failure);
  const oracle::CompareResult c = oracle::compareEvents(r.ours.events, theirs);
  std::string verdict = "same";
  if (!failure.empty())
    verdict = "rejected"; // rs274 does not compensate this program at all
  else if (!c.equivalent)
    verdict = c.leftIndex < r.ours.events.size()
                  ? "line " + std::to_string(r.ours.events[c.leftIndex].from.at.line)
                  : "line end";
  const auto want = expected();
  ASSERT_TRUE(want.count(GetParam()))
      << "comp/expected.txt has no line for " << GetParam() << " (" << verdict << ")\n"
      << c.report;
  EXPECT_EQ(verdict, want.at(GetParam())) << c.report;
}

// expand --keep comp: canonical motion keeps the compensation for LinuxCNC (G41.1/G42.1 with
// the diameter), so rs274 compensating gcx's output moves exactly as compensating the program.
TEST_P(CompDifferential, KeptCompensationIsLinuxCncsOwn) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const std::string out =
      (fs::temp_directory_path() / ("gcx_keep_" + GetParam() + ".ngc")).string();
  const std::string cmd = fmt::format(
      "{} expand {} --to canonical --keep comp --setup {} -o {} 2>/dev/null", GCX_BINARY,
      (contours() / (GetParam() + ".nct")).string(), (contours() / "setup.json").string(), out);
  ASSERT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 0) << cmd;
  const std::string kept = readFile(out);
  fs::remove(out);
  EXPECT_TRUE(kept.find(" G41.1 D6\n") != std::string::npos ||
              kept.find(" G42.1 D6\n") != std::string::npos)
      << kept;
  EXPECT_NE(kept.find("\nG40\n"), std::string::npos) << kept;
  Runs r = runGcx(GetParam());
  std::string failure, theirFailure;
  const auto fromKept = runOracle(kept, r.options, failure);
  const auto fromProgram =
      runOracle(readFile(contours() / (GetParam() + ".nct")), r.options, theirFailure);
  EXPECT_EQ(failure.empty(), theirFailure.empty()) << failure << theirFailure;
  if (!failure.empty()) return; // rs274 rejects both (G19)
  const oracle::CompareResult c = oracle::compareEvents(fromKept, fromProgram);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- kept:\n" << kept;
}

INSTANTIATE_TEST_SUITE_P(Contours, CompDifferential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           std::string n = "c" + p.param;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

TEST(CompDifferential, AtLeastFifteenContours) {
  EXPECT_GE(names().size(), 15u);
}

} // namespace
} // namespace gcx::test
