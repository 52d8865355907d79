// The two checks of a program with a hand-written LinuxCNC twin, for any dialect:
//  * the twin: rs274 on the hand-written RS274/NGC program moves like gcx on the program;
//  * the contract: rs274 on gcx's canonical output reproduces gcx's path (1e-4 mm).
#pragma once
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/setup_dialects.h"
#include "differential/oracle_run.h"
#include "emit/canonical.h"
#include "machine/setup.h"
#include "motion/event.h"
#include "oracle/compare.h"
#include "support/test_support.h"

namespace gcx::test {

inline void expectTwinMovesTheSame(const std::vector<motion::Event>& ours,
                                   const std::string& twinText) {
  std::string failure;
  const auto twin = runOracle(twinText, oracle::Rs274Options{}, failure);
  ASSERT_TRUE(failure.empty()) << failure;
  const oracle::CompareResult c = oracle::compareEvents(ours, twin);
  EXPECT_TRUE(c.equivalent) << c.report;
}

inline void expectRs274ReproducesTheCanonicalOutput(const std::vector<motion::Event>& ours) {
  std::ostringstream text;
  emit::CanonicalEmitter canonical(text);
  for (const motion::Event& e : ours)
    canonical.event(e);
  canonical.finish();
  std::string failure;
  const auto theirs = runOracle(text.str(), oracle::Rs274Options{}, failure);
  ASSERT_TRUE(failure.empty()) << failure << "\n" << text.str();
  const oracle::CompareResult c = oracle::compareEvents(ours, theirs);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- canonical:\n" << text.str();
}

/// The machine setup of a program of `dialect` (a `.setup.json` beside it), or the default one.
inline machine::Setup setupFileOrDefault(const fs::path& file, const std::string& dialect) {
  if (!fs::exists(file)) return {};
  SourceManager sm;
  diag::Engine diags;
  auto s = machine::parseSetup(readFile(file), sm.addBuffer(file.string(), readFile(file)), diags,
                               cli::setupDialects(dialect));
  EXPECT_TRUE(s.has_value()) << file;
  return s.value_or(machine::Setup{});
}

/// A gtest parameter name from a file stem ("01_arcs" -> "p01_arcs").
inline std::string twinTestName(const std::string& stem) {
  std::string n = "p" + stem;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

} // namespace gcx::test
