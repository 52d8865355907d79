// WL4 programs with hand-written LinuxCNC twins (tests/differential/wl4: NN.wl4 and NN.ngc):
//  * the twin: rs274 on the hand-written RS274/NGC program moves like gcx on the WL4 program;
//  * the contract: rs274 on gcx's canonical output reproduces gcx's path (1e-4 mm).
#include <gtest/gtest.h>

#include <sstream>

#include "emit/canonical.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

fs::path folder() {
  return sourceDir() / "tests" / "differential" / "wl4";
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(folder(), {".wl4"}))
    out.push_back(p.stem().string());
  return out;
}

std::vector<motion::Event> rs274(const std::string& text, std::string& failure) {
  const oracle::Rs274Result r = oracle::Rs274(oracle::Rs274Options{}).run(text);
  if (!r.ok()) {
    failure = r.summary();
    return {};
  }
  oracle::CanonOptions opt;
  opt.programText = text;
  return oracle::parseCanon(r.canonLines, opt);
}

class Wl4Differential : public testing::TestWithParam<std::string> {};

TEST_P(Wl4Differential, TheHandWrittenTwinMovesTheSameOnRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  MacroRun ours = runWl4(readFile(folder() / (GetParam() + ".wl4")));
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  std::string failure;
  const auto twin = rs274(readFile(folder() / (GetParam() + ".ngc")), failure);
  ASSERT_TRUE(failure.empty()) << failure;
  const oracle::CompareResult c = oracle::compareEvents(ours.events, twin);
  EXPECT_TRUE(c.equivalent) << c.report;
}

TEST_P(Wl4Differential, Rs274ReproducesTheCanonicalOutput) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  MacroRun ours = runWl4(readFile(folder() / (GetParam() + ".wl4")));
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  std::ostringstream text;
  emit::CanonicalEmitter canonical(text);
  for (const motion::Event& e : ours.events)
    canonical.event(e);
  canonical.finish();
  std::string failure;
  const auto theirs = rs274(text.str(), failure);
  ASSERT_TRUE(failure.empty()) << failure << "\n" << text.str();
  const oracle::CompareResult c = oracle::compareEvents(ours.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- canonical:\n" << text.str();
}

TEST_P(Wl4Differential, PrintedBackAsWl4ItMovesTheSame) {
  // parse -> gcx fmt's WL4 text -> parse: the same motion (the round trip of the printer)
  const std::string text = readFile(folder() / (GetParam() + ".wl4"));
  std::string printed;
  for (const std::string& line : printedWl4(parseWl4(text)))
    printed += line + "\n";
  MacroRun a = runWl4(text);
  MacroRun b = runWl4(printed);
  ASSERT_TRUE(a.errors.empty()) << a.rendered;
  ASSERT_TRUE(b.errors.empty()) << b.rendered << printed;
  EXPECT_EQ(a.all(), b.all()) << printed;
}

INSTANTIATE_TEST_SUITE_P(Wl4, Wl4Differential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           std::string n = "p" + p.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

TEST(Wl4DifferentialCorpus, HasAtLeastTwentyProgramsEachWithItsTwin) {
  const std::vector<std::string> programs = names();
  EXPECT_GE(programs.size(), 20u);
  for (const std::string& n : programs)
    EXPECT_TRUE(fs::exists(folder() / (n + ".ngc"))) << n;
}

} // namespace
} // namespace gcx::test
