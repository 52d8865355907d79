// Differential tests against LinuxCNC's rs274 (docs/nct-vs-linuxcnc.md), over the programs in
// tests/differential/programs, which stay in the subset NCT and RS274/NGC share:
//  * contract: rs274 run on gcx's canonical output reproduces gcx's machine path (1e-4 mm);
//  * semantics: rs274 run on the program itself (or its .ref.ngc translation where LinuxCNC
//    lacks the G code) moves the gauge point like gcx's interpreter.
#include <gtest/gtest.h>

#include <sstream>

#include "differential/oracle_run.h"
#include "differential/twin_driver.h"
#include "emit/canonical.h"
#include "machine/setup.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "oracle/setup.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

fs::path programs() {
  return sourceDir() / "tests" / "differential" / "programs";
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(programs(), {".nct"}))
    out.push_back(p.stem().string());
  return out;
}

machine::Setup setupOf(const std::string& name) {
  return setupFileOrDefault(programs() / (name + ".setup.json"), "nct");
}

struct Ours {
  ProgramRun run;
  std::string canonical;
};

Ours runGcx(const std::string& name) {
  Ours o;
  std::ostringstream text;
  emit::CanonicalEmitter emitter(text);
  o.run = runNct(readFile(programs() / (name + ".nct")), setupOf(name), &emitter);
  o.canonical = text.str();
  return o;
}

class Differential : public testing::TestWithParam<std::string> {};

oracle::Rs274Options oracleOptions(const std::string& name) {
  oracle::Rs274Options opt;
  const fs::path setup = programs() / (name + ".setup.json");
  if (fs::exists(setup)) {
    oracle::OracleSetup s;
    std::string err;
    EXPECT_TRUE(oracle::parseSetupJson(readFile(setup), s, err)) << err;
    oracle::applySetup(s, opt);
  }
  return opt;
}

TEST_P(Differential, Rs274ReproducesTheCanonicalOutput) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  Ours ours = runGcx(GetParam());
  ASSERT_TRUE(ours.run.errors.empty()) << ours.run.rendered;
  // the same tool table (T M6 needs the tools), no offsets: they are in the coordinates
  oracle::Rs274Options opt = oracleOptions(GetParam());
  opt.workOffsets.clear();
  std::string failure;
  const auto theirs = runOracle(ours.canonical, opt, failure);
  ASSERT_TRUE(failure.empty()) << failure << "\n" << ours.canonical;
  const oracle::CompareResult c = oracle::compareEvents(ours.run.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- canonical:\n" << ours.canonical;
}

TEST_P(Differential, Rs274MovesLikeGcxOnTheProgramItself) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  Ours ours = runGcx(GetParam());
  ASSERT_TRUE(ours.run.errors.empty()) << ours.run.rendered;
  const oracle::Rs274Options opt = oracleOptions(GetParam());
  const fs::path ref = programs() / (GetParam() + ".ref.ngc");
  const std::string text = readFile(fs::exists(ref) ? ref : programs() / (GetParam() + ".nct"));
  std::string failure;
  const auto theirs = runOracle(text, opt, failure);
  ASSERT_TRUE(failure.empty()) << failure;
  const oracle::CompareResult c = oracle::compareEvents(ours.run.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report;
}

INSTANTIATE_TEST_SUITE_P(Programs, Differential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           std::string n = "p" + p.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(Differential, CorpusHasAtLeastThirtyPrograms) {
  EXPECT_GE(names().size(), 30u);
}

} // namespace
} // namespace gcx::test
