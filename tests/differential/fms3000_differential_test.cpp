// FMS-3000 programs with hand-written LinuxCNC twins (tests/differential/fms3000: NN_name.fms,
// NN_name.ngc, optionally NN_name.setup.json for the machine parameters such as N3021). The
// program units a P call finds (`19.fms`, `019.fms`: a stem of digits) sit beside them and are
// visible to every program. Checked by the shared twin driver (differential/twin_driver.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>
#include <map>

#include "differential/twin_driver.h"
#include "machine/setup.h"
#include "oracle/rs274.h"
#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

fs::path folder() {
  return sourceDir() / "tests" / "differential" / "fms3000";
}

bool isProgramUnit(const fs::path& p) {
  const std::string s = p.stem().string();
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::vector<std::string> names() {
  std::vector<std::string> out;
  for (const fs::path& p : filesUnder(folder(), {".fms"}))
    if (!isProgramUnit(p)) out.push_back(p.stem().string());
  return out;
}

machine::Setup setupOf(const std::string& name) {
  return setupFileOrDefault(folder() / (name + ".setup.json"), "fms3000");
}

/// `text` as the main program among the folder's program units, on the setup of program `name`.
MacroRun runAmongUnits(const std::string& text, const std::string& name) {
  std::map<std::string, std::string> files{{"main.fms", text}};
  for (const fs::path& p : filesUnder(folder(), {".fms"}))
    if (isProgramUnit(p)) files[p.filename().string()] = readFile(p);
  return runFms(files, setupOf(name));
}

MacroRun runProgram(const std::string& name) {
  return runAmongUnits(readFile(folder() / (name + ".fms")), name);
}

class Fms3000Differential : public testing::TestWithParam<std::string> {};

TEST(Fms3000Differential, AtLeastTwentyPrograms) {
  EXPECT_GE(names().size(), 20u);
}

TEST_P(Fms3000Differential, TheHandWrittenTwinMovesTheSameOnRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectTwinMovesTheSame(ours.events, readFile(folder() / (GetParam() + ".ngc")));
}

TEST_P(Fms3000Differential, Rs274ReproducesTheCanonicalOutput) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const MacroRun ours = runProgram(GetParam());
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  expectRs274ReproducesTheCanonicalOutput(ours.events);
}

TEST_P(Fms3000Differential, ExpandedToFms3000ItMovesTheSame) {
  // the round trip of issue 12: parse -> `gcx expand --to fms3000` (cycles, P calls and repeats
  // kept; with --expand macros,subprograms calls and repeats run out) -> parse among the same
  // program units gives the same motion
  const MacroRun a = runProgram(GetParam());
  ASSERT_TRUE(a.errors.empty()) << a.rendered;
  for (const char* form : {"", " --expand macros,subprograms"}) {
    const fs::path out = fs::temp_directory_path() / ("gcx-fms-roundtrip-" + GetParam() + ".fms");
    const fs::path setup = folder() / (GetParam() + ".setup.json");
    const std::string command =
        fmt::format("cd {} && {} expand {}.fms --to fms3000{} {} -o {} >/dev/null 2>&1",
                    folder().string(), GCX_BINARY, GetParam(), form,
                    fs::exists(setup) ? "--setup " + setup.string() : std::string(), out.string());
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string text = readFile(out);
    fs::remove(out);
    const MacroRun b = runAmongUnits(text, GetParam());
    ASSERT_TRUE(b.errors.empty()) << form << b.rendered << text;
    EXPECT_EQ(b.motion(), a.motion()) << form << text;
  }
}

INSTANTIATE_TEST_SUITE_P(Fms3000, Fms3000Differential, testing::ValuesIn(names()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           return twinTestName(p.param);
                         });

} // namespace
} // namespace gcx::test
