// `gcx equiv` on the command line: exit codes 0 / 1 / 2, the exact first line of the report,
// the JSON object, and located errors for bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include "support/test_support.h"

namespace gcx::test {
namespace {

struct GcxRun {
  int exit = -1;
  std::string out, err;
};

/// Runs gcx with the arguments (each single-quoted), capturing stdout and stderr.
GcxRun gcx(const std::string& args) {
  const fs::path err = fs::temp_directory_path() / ("gcx-equiv-cli-" + std::to_string(::getpid()));
  const std::string cmd = std::string("'") + GCX_BINARY + "' " + args + " 2>'" + err.string() + "'";
  GcxRun r;
  FILE* p = ::popen(cmd.c_str(), "r");
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0)
    r.out.append(buf, n);
  const int status = ::pclose(p);
  r.exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readFile(err);
  fs::remove(err);
  return r;
}

std::string firstLine(const std::string& s) {
  return s.substr(0, s.find('\n'));
}

struct Files {
  fs::path dir = fs::temp_directory_path() / ("gcx-equiv-cli-files-" + std::to_string(::getpid()));
  Files() { fs::create_directories(dir); }
  ~Files() { fs::remove_all(dir); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name, std::ios::binary) << text;
    return "'" + (dir / name).string() + "'";
  }
};

TEST(EquivCli, EquivalentExitsZero) {
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nG1 X10 F100\nG1 Y10\nM30\n");
  const std::string b = f.write("b.nct", "G90 G17 G21\nG1 X4 F100\nX10\nY10\nM30\n");
  const GcxRun r = gcx("equiv " + a + " " + b);
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(firstLine(r.out), "equivalent: " + (f.dir / "a.nct").string() + " and " +
                                  (f.dir / "b.nct").string() +
                                  " move the tool the same (tolerance 0.001 mm, largest deviation "
                                  "0.000000 mm)");
}

TEST(EquivCli, DifferentExitsOneAndNamesBothLines) {
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nG1 X10 F100\nG1 Y10\nM30\n");
  const std::string b = f.write("b.nct", "G90 G17 G21\nG1 X10.5 F100\nG1 Y10\nM30\n");
  const GcxRun r = gcx("equiv " + a + " " + b);
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_EQ(firstLine(r.out), "first difference at " + (f.dir / "a.nct").string() + ":2:1 vs " +
                                  (f.dir / "b.nct").string() +
                                  ":2:1: end point X differs by 0.500 mm");
  EXPECT_NE(r.out.find("  G1 X10.5 F100\n  ^\n"), std::string::npos) << r.out;
  // a larger tolerance accepts it
  EXPECT_EQ(gcx("equiv " + a + " " + b + " --tol 0.6").exit, 0);
}

TEST(EquivCli, MoveOfTheRotaryAxisAloneIsCompared) {
  Files f;
  const std::string a = f.write("a.nct", "G1 F100 A90\n");
  const std::string b = f.write("b.nct", "G1 F100 A45\n");
  const GcxRun r = gcx("equiv " + a + " " + b);
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_EQ(firstLine(r.out), "first difference at " + (f.dir / "a.nct").string() + ":1:1 vs " +
                                  (f.dir / "b.nct").string() +
                                  ":1:1: end point A differs by 45.000 deg; B ended");
}

TEST(EquivCli, RotaryDuringTheTravelIsNotRotaryBeforeIt) {
  Files f;
  const std::string a = f.write("a.nct", "G1 F100 X10 A90\n");
  const std::string b = f.write("b.nct", "G1 F100 A90\nG1 X10\n");
  const std::string c = f.write("c.nct", "G1 F100 X4 A36\nG1 X10 A90\n");
  EXPECT_EQ(gcx("equiv " + a + " " + b).exit, 1);
  EXPECT_EQ(gcx("equiv " + a + " " + c).exit, 0);
  const std::string d = f.write("d.nct", "G0 A90\n");
  const std::string e = f.write("e.nct", "G0 A45\n");
  const GcxRun r = gcx("equiv " + d + " " + e);
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(firstLine(r.out).find(": rapid end point A differs by 45.000 deg"), std::string::npos)
      << r.out;
}

TEST(EquivCli, JsonObject) {
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nS1000 M3\nG1 X10 F100\nM30\n");
  const std::string b = f.write("b.nct", "G90 G17 G21\nS1000 M4\nG1 X10 F100\nM30\n");
  const GcxRun r = gcx("equiv " + a + " " + b + " --json");
  EXPECT_EQ(r.exit, 1) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["equivalent"], false);
  EXPECT_EQ(j["divergence"]["kind"], "state");
  EXPECT_EQ(j["divergence"]["summary"], "spindle differs: S1000 CW vs S1000 CCW");
  EXPECT_EQ(j["divergence"]["a"]["line"], 3);
  EXPECT_EQ(j["divergence"]["b"]["source"], "G1 X10 F100");
  EXPECT_EQ(j["divergence"]["state_set_b"]["line"], 2);
  EXPECT_EQ(j["a"]["segments"], 0);
  EXPECT_EQ(j["a"]["stats"]["length_mm"]["feed"], 0.0); // before the divergent segment
  EXPECT_EQ(j["tolerance_mm"], 0.001);
}

TEST(EquivCli, ProgramErrorExitsTwoWithItsLocatedDiagnostic) {
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nG1 X10 F100\nM30\n");
  const std::string b = f.write("b.nct", "G90 G17 G21\nG1 X10 Y20 X30 F100\nM30\n");
  const GcxRun r = gcx("equiv " + a + " " + b);
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("b.nct:2:12: error: address X appears twice in one block [GCX011]"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(EquivCli, MissingFileExitsTwo) {
  Files f;
  const std::string a = f.write("a.nct", "G1 X10 F100\nM30\n");
  const GcxRun r = gcx("equiv " + a + " '/nonexistent/b.nct'");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("/nonexistent/b.nct: cannot open"), std::string::npos) << r.err;
}

// Without rs274, a full LinuxCNC program is refused at the construct gcx cannot read.
TEST(EquivCli, OWordWithoutRs274IsALocatedError) {
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nG1 X10 F100\nM30\n");
  const std::string b = f.write("b.ngc", "G21 G90\no100 sub\nG1 X10 F100\no100 endsub\nM2\n");
  const GcxRun r = gcx("equiv " + a + " " + b + " --rs274 /nonexistent/rs274");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("b.ngc:2:1: error: O-word subroutines and control flow need LinuxCNC's "
                       "own interpreter rs274, which is not installed; install it with `apt-get "
                       "install linuxcnc-uspace`"),
            std::string::npos)
      << r.err;
}

// rs274's own errors are located at the line it stopped at.
TEST(EquivCli, Rs274ErrorIsLocatedAtItsLine) {
  if (std::system("command -v rs274 > /dev/null 2>&1") != 0) GTEST_SKIP() << "no rs274";
  Files f;
  const std::string a = f.write("a.nct", "G90 G17 G21\nG1 X10 F100\nM30\n");
  const std::string b = f.write("b.ngc", "G21 G90\nG1 X10 F100\nG2 X20 Y0 R-1\nM2\n");
  const GcxRun r = gcx("equiv " + a + " " + b);
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("b.ngc:3:1: error: rs274 could not run the program: rs274 exit code 1"),
            std::string::npos)
      << r.err;
}

} // namespace
} // namespace gcx::test
