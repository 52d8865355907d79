// An FMS-3000 program to FMS-3000 keeps its structure (docs/fms3000.md "Translating to
// FMS-3000"): `gcx translate --to fms3000` prints it back as written and `gcx expand --to fms3000`
// writes its blocks as read, P calls, G25 ... M25 repeats and cycles kept; the called programs
// are not written, the result calls the same ones. `--expand` still gives the flat form. Each
// result is proven by `gcx equiv` (translate proves it too).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sstream>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

const std::string kMain = "rem part with calls and a repeat\r\n"
                          "N1 G91G25L3\r\n"
                          "G1X10F100\r\n"
                          "M25\r\n"
                          "N5 G90 X0 P19\r\n"
                          "P019\r\n"
                          "G0 Z5\r\n"
                          "X40 G81 U2 Z-5 F100\r\n"
                          "G80\r\n"
                          "M30\r\n";
// as `gcx fmt` prints it: words spaced, CR LF, the rem line and the numbers kept
const std::string kKept = "rem part with calls and a repeat\r\n"
                          "N1 G91 G25 L3\r\n"
                          "G1 X10 F100\r\n"
                          "M25\r\n"
                          "N5 G90 X0 P19\r\n"
                          "P019\r\n"
                          "G0 Z5\r\n"
                          "X40 G81 U2 Z-5 F100\r\n"
                          "G80\r\n"
                          "M30\r\n";

class Fms3000TranslateStructure : public testing::Test {
protected:
  void SetUp() override {
    folder_.write("src/main.fms", kMain);
    folder_.write("src/19.fms", "G91 G1 Y5 F100\r\nG90 M99\r\n");
    folder_.write("src/019.fms", "G91 G1 Y-2 F100\r\nG90 M99\r\n");
  }
  /// equiv of the source and `result` (a path under the folder) succeeds without a word.
  void expectEquivalent(const std::string& result, const std::string& options = "") {
    const CliResult q = folder_.gcx(fmt::format("equiv src/main.fms {}{}", result, options));
    EXPECT_EQ(q.exitCode, 0) << q.out << q.err;
    EXPECT_EQ(q.err, "");
  }
  CliFolder folder_{"fms3000-translate"};
};

TEST_F(Fms3000TranslateStructure, TranslateWritesTheProgramAsWritten) {
  const CliResult t = folder_.gcx("translate src/main.fms --to fms3000 -o src/kept.fms");
  ASSERT_EQ(t.exitCode, 0) << t.err;
  EXPECT_NE(t.err.find("verified"), std::string::npos) << t.err;
  EXPECT_EQ(t.err.find("note"), std::string::npos) << t.err; // nothing expanded to note
  EXPECT_EQ(readFile(folder_.path() / "src/kept.fms"), kKept);
  expectEquivalent("src/kept.fms");
}

TEST_F(Fms3000TranslateStructure, ExpandWritesTheBlocksAsRead) {
  const CliResult e = folder_.gcx("expand src/main.fms --to fms3000 -o src/kept.fms");
  ASSERT_EQ(e.exitCode, 0) << e.err;
  EXPECT_EQ(e.err, "");
  EXPECT_EQ(readFile(folder_.path() / "src/kept.fms"), kKept);
  expectEquivalent("src/kept.fms");
}

TEST_F(Fms3000TranslateStructure, TheCalledProgramsAreNotWrittenButFoundBesideTheSource) {
  // to another folder: the result calls 19 and 019, which stay beside the source; the proof
  // reads them there
  fs::create_directories(folder_.path() / "out");
  const CliResult t = folder_.gcx("translate src/main.fms --to fms3000 -o out/main.fms");
  ASSERT_EQ(t.exitCode, 0) << t.err;
  EXPECT_EQ(readFile(folder_.path() / "out/main.fms"), kKept);
  EXPECT_FALSE(fs::exists(folder_.path() / "out/19.fms"));
  EXPECT_FALSE(fs::exists(folder_.path() / "out/019.fms"));
  expectEquivalent("out/main.fms", " --lib src");
  // without them (no --lib), the result cannot run: a located error
  const CliResult q = folder_.gcx("run out/main.fms");
  EXPECT_NE(q.exitCode, 0);
  EXPECT_NE(q.err.find("out/main.fms:5:"), std::string::npos) << q.err;
}

TEST_F(Fms3000TranslateStructure, ExpandNamesTheFlatForm) {
  // --expand macros,subprograms (expand) and --expand subprograms or all (translate): the
  // calls and the repeat run out, the cycle stays where it is kept
  const CliResult e =
      folder_.gcx("expand src/main.fms --to fms3000 --expand macros,subprograms -o src/flat1.fms");
  ASSERT_EQ(e.exitCode, 0) << e.err;
  for (const char* args :
       {"--expand subprograms -o src/flat2.fms", "--expand all -o src/flat3.fms"}) {
    const CliResult t = folder_.gcx(fmt::format("translate src/main.fms --to fms3000 {}", args));
    ASSERT_EQ(t.exitCode, 0) << args << "\n" << t.err;
    EXPECT_NE(t.err.find("verified"), std::string::npos) << t.err;
  }
  for (const char* name : {"src/flat1.fms", "src/flat2.fms", "src/flat3.fms"}) {
    std::string blocks; // without the rem lines, where translate notes what it ran out
    std::istringstream in(readFile(folder_.path() / name));
    for (std::string line; std::getline(in, line);)
      if (!line.starts_with("rem")) blocks += line + "\n";
    for (const char* word : {"P19", "P019", "G25", "M25"})
      EXPECT_EQ(blocks.find(word), std::string::npos) << name << ": " << word << "\n" << blocks;
    expectEquivalent(name);
  }
  // the expansion keeps the cycle; translate --expand all runs it out too
  EXPECT_NE(readFile(folder_.path() / "src/flat1.fms").find("G81"), std::string::npos);
  EXPECT_NE(readFile(folder_.path() / "src/flat2.fms").find("G81"), std::string::npos);
  EXPECT_EQ(readFile(folder_.path() / "src/flat3.fms").find("G81"), std::string::npos);
}

TEST_F(Fms3000TranslateStructure, ABrokenCalledProgramIsALocatedErrorAndNoFile) {
  // the kept program is proven by running it: an error in a called program stops expand, which
  // writes nothing
  folder_.write("src/019.fms", "G91 G1 Y-2 F0\r\nG90 M99\r\n");
  const CliResult e = folder_.gcx("expand src/main.fms --to fms3000 -o src/kept.fms");
  EXPECT_NE(e.exitCode, 0);
  EXPECT_NE(e.err.find("019.fms:1:"), std::string::npos) << e.err;
  EXPECT_FALSE(fs::exists(folder_.path() / "src/kept.fms"));
}

} // namespace
} // namespace gcx::test
