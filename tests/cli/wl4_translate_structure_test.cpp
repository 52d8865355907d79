// `gcx translate x.wl4 --to wl4` keeps the program's structure (docs/translation.md, issue
// "--to wl4 keeping structure"): variables, IF, jumps, L calls and %-programs come back as
// written, and the translation moves the tool like its source (translate proves it; equiv is
// run again here) for every example, differential program and spec vector.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/cli_folder.h"
#include "support/wl4_programs.h"

namespace gcx::test {
namespace {

class Wl4TranslateStructure : public testing::Test {
protected:
  /// Translates name to WL4, checks the proof and the equivalence; the translated text.
  std::string translate(const std::string& name, const std::string& options = "") {
    const CliResult t =
        folder_.gcx(fmt::format("translate {} --to wl4 -o kept.wl4{}", name, options));
    EXPECT_EQ(t.exitCode, 0) << name << "\n" << t.err;
    EXPECT_NE(t.err.find("verified"), std::string::npos) << name << "\n" << t.err;
    const CliResult q = folder_.gcx(fmt::format("equiv {} kept.wl4{}", name, options));
    EXPECT_EQ(q.exitCode, 0) << name << "\n" << q.out << q.err;
    return readFile(folder_.path() / "kept.wl4");
  }
  /// Each construct of the source is in the translation as often (the printer keeps comments
  /// and normalises only the spacing between words).
  static void keeps(const std::string& source, const std::string& kept, const std::string& what) {
    for (const char* word : {"L0", "IF", "#", "%", "G8", "G7", "G31"}) {
      auto count = [&](const std::string& s) {
        std::size_t n = 0;
        for (std::size_t at = s.find(word); at != std::string::npos; at = s.find(word, at + 1))
          ++n;
        return n;
      };
      EXPECT_EQ(count(kept), count(source)) << what << ": " << word << "\n" << kept;
    }
  }

  CliFolder folder_{"wl4-translate"};
};

TEST_F(Wl4TranslateStructure, EveryExampleAndDifferentialProgram) {
  const std::vector<fs::path> files = wl4Programs();
  ASSERT_GE(files.size(), 28u); // 2 examples, 26 differential programs
  for (const fs::path& f : files)
    folder_.write(f.filename().string(), readFile(f));
  for (const fs::path& f : files) {
    const std::string source = readFile(f);
    keeps(source, translate(f.filename().string()), f.filename().string());
  }
}

TEST_F(Wl4TranslateStructure, TheSpecsVectors) {
  int k = 0;
  for (const std::string& v : wl4SpecVectors()) {
    const std::string name = fmt::format("v{}.wl4", ++k);
    folder_.write(name, v);
    keeps(v, translate(name), name);
  }
}

TEST_F(Wl4TranslateStructure, LatheVectorsOnTheirSetup) {
  folder_.write("lathe.setup.json", R"({"wl4": {"parameters": {"lathe": 1, "b_chamfer": 1}}})");
  folder_.write("tv18.wl4", "%TV18\nG18 G90 G0 X30 Z5\n"
                            "G31 X24 Z-20 F1.5 P0 I0 #1=1 #2=0.25 #3=0 #4=0 #5=1.5\nM2\n%\n");
  folder_.write("tv19.wl4", "%TV19\nG18 G90 G95 G0 X40 Z70\nG1 X100 F0.2 B10\nZ10\nM2\n%\n");
  for (const char* name : {"tv18.wl4", "tv19.wl4"}) {
    const std::string kept = translate(name, " --setup lathe.setup.json");
    EXPECT_EQ(kept.find("G32"), std::string::npos) << kept; // G31 stays one block
  }
}

TEST_F(Wl4TranslateStructure, VectorsOnTheirSetupsAndTheManualsExamples) {
  // TV5, TV6, TV12, TV18, TV19, TV21 and the runnable examples of §7, each on its setup
  const std::vector<Wl4ProgramOnSetup> programs = wl4ProgramsOnSetups();
  ASSERT_EQ(programs.size(), 18u);
  for (const Wl4ProgramOnSetup& p : programs) {
    folder_.write(p.name + ".wl4", p.text);
    std::string setup;
    if (!p.setup.empty()) {
      folder_.write(p.name + ".setup.json", p.setup);
      setup = " --setup " + p.name + ".setup.json";
    }
    keeps(p.text, translate(p.name + ".wl4", setup), p.name);
  }
}

TEST_F(Wl4TranslateStructure, ContourCyclesOnTheLathe) {
  // the manual's examples 21-23 and the spec's worked example (§5.6): the cycle blocks and their
  // contours after M2 come back as written, and the translation moves the tool as they do
  for (const Wl4ProgramOnSetup& p : wl4ContourCyclePrograms()) {
    folder_.write(p.name + ".wl4", p.text);
    folder_.write(p.name + ".setup.json", p.setup);
    const std::string kept = translate(p.name + ".wl4", " --setup " + p.name + ".setup.json");
    keeps(p.text, kept, p.name);
    EXPECT_NE(kept.find("M2\nN"), std::string::npos) << kept; // the contour after M2
  }
}

TEST_F(Wl4TranslateStructure, TheKeptTextIsTheProgramAsWritten) {
  folder_.write("p.wl4", "%P\n#1=0\nN010 #1=(#1+1) G1 X(#1*10) F100\nIF (#1<3) N10\nL0702\n"
                         "M2\n%\n%07\nG91 G1 Y#1\nG90 M99\n%\n");
  EXPECT_EQ(translate("p.wl4"), "%P\n#1=0\nN010 #1=(#1+1) G1 X(#1*10) F100\nIF(#1<3) N10\n"
                                "L0702\nM2\n%\n%07\nG91 G1 Y#1\nG90 M99\n%\n");
}

} // namespace
} // namespace gcx::test
