// Round trip through `gcx expand --to wl4` (wl4.md §5.1, §7, §8): every WL4 example, every
// differential program, the spec's vectors (on their setups: block skip, work offsets, the
// lathe) and the runnable examples of the manual, expanded (calls, cycles and macro statements
// flattened into plain WL4 blocks), read back and run, move the tool as the original does by
// `gcx equiv`; and a KOI8-R file and its UTF-8 twin give identical results.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/cli_folder.h"
#include "support/wl4_programs.h"

namespace gcx::test {
namespace {

class Wl4ExpandRoundTrip : public testing::Test {
protected:
  void write(const std::string& name, const std::string& bytes) { folder_.write(name, bytes); }
  CliResult gcx(const std::string& args) { return folder_.gcx(args); }
  /// Expands name to WL4 and compares both runs; the expanded text.
  std::string roundTrip(const std::string& name) {
    const CliResult e = gcx(fmt::format("expand {} --to wl4 -o expanded.wl4", name));
    EXPECT_EQ(e.exitCode, 0) << name << "\n" << e.err;
    const CliResult q = gcx(fmt::format("equiv {} expanded.wl4", name));
    const std::string text = readFile(folder_.path() / "expanded.wl4");
    EXPECT_EQ(q.exitCode, 0) << name << "\n" << q.out << q.err << text;
    return text;
  }

  CliFolder folder_{"wl4-roundtrip"};
};

TEST_F(Wl4ExpandRoundTrip, EveryExampleAndDifferentialProgram) {
  const std::vector<fs::path> files = wl4Programs();
  ASSERT_GE(files.size(), 28u); // 2 examples, 26 differential programs
  for (const fs::path& f : files) {
    write(f.filename().string(), readFile(f));
    const std::string text = roundTrip(f.filename().string());
    // flattened: no call, no cycle selection and no jump is left to run twice
    EXPECT_EQ(text.find(" L0"), std::string::npos) << f << "\n" << text;
    EXPECT_EQ(text.find("G8"), std::string::npos) << f << "\n" << text;
  }
}

TEST_F(Wl4ExpandRoundTrip, TheSpecsVectors) {
  int k = 0;
  for (const std::string& v : wl4SpecVectors()) {
    const std::string name = fmt::format("v{}.wl4", ++k);
    write(name, v);
    roundTrip(name);
  }
}

TEST_F(Wl4ExpandRoundTrip, VectorsOnTheirSetupsAndTheManualsExamples) {
  const std::vector<Wl4ProgramOnSetup> programs = wl4ProgramsOnSetups();
  ASSERT_EQ(programs.size(), 18u);
  for (const Wl4ProgramOnSetup& p : programs) {
    const std::string name = p.name + ".wl4";
    write(name, p.text);
    std::string setup;
    if (!p.setup.empty()) {
      write(p.name + ".setup.json", p.setup);
      setup = " --setup " + p.name + ".setup.json";
    }
    const CliResult e = gcx(fmt::format("expand {} --to wl4 -o expanded.wl4{}", name, setup));
    ASSERT_EQ(e.exitCode, 0) << name << "\n" << e.err;
    const std::string text = readFile(folder_.path() / "expanded.wl4");
    const CliResult q = gcx(fmt::format("equiv {} expanded.wl4{}", name, setup));
    EXPECT_EQ(q.exitCode, 0) << name << "\n" << q.out << q.err << text;
    EXPECT_EQ(text.find(" L0"), std::string::npos) << name << "\n" << text; // flattened
  }
}

TEST_F(Wl4ExpandRoundTrip, AContourCycleKeptWithoutItsContourIsAnErrorNotAWrongProgram) {
  // expand keeps a machine cycle as its block; the contour P..Q after M2 is never reached, so
  // the flattened text would lose it: GCX042 at the cycle (`translate --to wl4` keeps it all)
  for (const Wl4ProgramOnSetup& p : wl4ContourCyclePrograms()) {
    write(p.name + ".wl4", p.text);
    write(p.name + ".setup.json", p.setup);
    const CliResult e =
        gcx(fmt::format("expand {0}.wl4 --to wl4 -o expanded.wl4 --setup {0}.setup.json", p.name));
    EXPECT_EQ(e.exitCode, 1) << p.name << "\n" << e.err;
    EXPECT_NE(e.err.find("[GCX042]"), std::string::npos) << p.name << "\n" << e.err;
    EXPECT_FALSE(fs::exists(folder_.path() / "expanded.wl4")) << p.name; // no partial output
    const CliResult c =
        gcx(fmt::format("expand {0}.wl4 --to canonical --setup {0}.setup.json", p.name));
    EXPECT_EQ(c.exitCode, 0) << p.name << "\n" << c.err;
  }
}

// fmt keeps the comments of a unit's lines (found by the fmt_wl4 fuzz target: `%P$PLATE`
// came out as `%P`).
TEST_F(Wl4ExpandRoundTrip, FmtKeepsTheCommentsOfUnitLines) {
  write("c.wl4", "%P$PLATE 60\nG0 X1\nM2\n% $END\n");
  const CliResult r = gcx("fmt c.wl4");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "%P $PLATE 60\nG0 X1\nM2\n% $END\n");
}

TEST_F(Wl4ExpandRoundTrip, AKoi8rFileAndItsUtf8TwinGiveIdenticalResults) {
  // "$ ДЕТАЛЬ ВАЛ" in KOI8-R bytes and in UTF-8: comments are the only place for Cyrillic (§1.1)
  const std::string koi8 = "%P\n$ \xE4\xE5\xF4\xE1\xEC\xF8 \xF7\xE1\xEC\nG0 X10 Y5\n"
                           "G1 X20 F100 $ \xF3\xF4\xEF\xF0\nM2\n%\n";
  const std::string utf8 = "%P\n$ \u0414\u0415\u0422\u0410\u041B\u042C \u0412\u0410\u041B\n"
                           "G0 X10 Y5\nG1 X20 F100 $ \u0421\u0422\u041E\u041F\nM2\n%\n";
  write("k.wl4", koi8);
  write("u.wl4", utf8);
  const CliResult a = gcx("expand k.wl4 --to canonical");
  const CliResult b = gcx("expand u.wl4 --to canonical --encoding utf-8");
  EXPECT_EQ(a.exitCode, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out.find("G1 X20"), std::string::npos) << a.out;
  // fmt writes each in the encoding it was read in: KOI8-R, WL4's media code (wl4.md §1.1),
  // unless --encoding named another; so its output reads back as written
  const CliResult fa = gcx("fmt k.wl4 -o k2.wl4");
  const CliResult fb = gcx("fmt u.wl4 --encoding utf-8 -o u2.wl4");
  EXPECT_EQ(fa.exitCode, 0) << fa.err;
  EXPECT_EQ(fb.exitCode, 0) << fb.err;
  const std::string k2 = readFile(folder_.path() / "k2.wl4");
  const std::string u2 = readFile(folder_.path() / "u2.wl4");
  EXPECT_NE(k2.find("$ \xE4\xE5\xF4\xE1\xEC\xF8 \xF7\xE1\xEC"), std::string::npos) << k2;
  EXPECT_NE(u2.find("$ \u0414\u0415\u0422\u0410\u041B\u042C \u0412\u0410\u041B"), std::string::npos)
      << u2;
  EXPECT_EQ(gcx("fmt k2.wl4").out, k2);
  EXPECT_EQ(gcx("fmt u2.wl4 --encoding utf-8").out, u2);
}

} // namespace
} // namespace gcx::test
