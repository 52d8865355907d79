// gcx translate (docs/translation.md): a translation is written only when the equivalence engine
// proves it moves the tool like its source; targets gcx cannot translate to yet are refused with
// no file; a batch translates a tree, each program in its own process, with a report.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sys/stat.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

using Result = CliResult;

class TranslateCli : public testing::Test {
protected:
  fs::path write(const std::string& name, const std::string& bytes) {
    return folder_.write(name, bytes);
  }
  Result gcx(const std::string& args) { return folder_.gcx(args); }

  CliFolder folder_{"translate"};
  const fs::path& dir_ = folder_.path();
};

constexpr const char* kProgram = "G90 G0 X10 Y5\nG1 X20 F100\nM30\n";
constexpr const char* kCanonical =
    "(gcx canonical motion: machine frame, mm, absolute; offsets and tool lengths are in the "
    "coordinates)\nG21 G90 G94 G17 G40 G49 G80 G54\nG0 X10 Y5 Z0\nG1 X20 Y5 Z0 F100\nM30\n";

// A jump has no LinuxCNC form (tests/cli/translate_ngc_test.cpp has the structures ngc keeps).
TEST_F(TranslateCli, AVerifiedTranslationIsWrittenWithANoteOnWhatWasExpanded) {
  write("A.nct", "G90 G0 X10 Y5\nG1 X20 F100\nGOTO5\nN5 M30\n");
  const Result r = gcx("translate A.nct --to canonical -o A.ngc");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(dir_ / "A.ngc"), kCanonical);
  const Result n = gcx("translate A.nct --to ngc -o N.ngc");
  EXPECT_EQ(n.exitCode, 0) << n.err;
  const std::string note =
      "written as plain G0-G3 motion: A.nct:3: GOTO: LinuxCNC has no jump to a block number";
  EXPECT_EQ(readFile(dir_ / "N.ngc"), "(" + note + ")\n" + kCanonical);
  EXPECT_EQ(n.err, "gcx: note: A.nct: " + note +
                       "\ngcx: A.nct -> N.ngc: verified, moves the tool like the source within "
                       "0.001 mm\n");
  // nothing staged is left behind
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);
}

TEST_F(TranslateCli, ToStandardOutputAfterTheProof) {
  write("A.nct", kProgram);
  const Result r = gcx("translate A.nct --to canonical");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, kCanonical);
  EXPECT_EQ(r.err, "gcx: A.nct -> standard output: verified, moves the tool like the source "
                   "within 0.001 mm\n");
}

// A reader of the result that disagrees (an rs274 that moves X20 to X21) makes the proof fail:
// exit 1, the first divergence named, and no file.
TEST_F(TranslateCli, ATranslationThatDoesNotHoldIsNotWritten) {
  if (std::system("command -v rs274 >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs rs274";
  write("A.nct", kProgram);
  const fs::path fake =
      write("fake-rs274", "#!/bin/bash\nargs=()\nfor a in \"$@\"; do\n  if [[ $a == *.ngc ]]; then "
                          "sed 's/X20 /X21 /' \"$a\" > \"$a.x.ngc\"; a=\"$a.x.ngc\"; fi\n"
                          "  args+=(\"$a\")\ndone\nexec rs274 \"${args[@]}\"\n");
  ::chmod(fake.c_str(), 0755);
  const Result r = gcx("translate A.nct --to ngc -o A.ngc --rs274 " + fake.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(fs::exists(dir_ / "A.ngc"));
  EXPECT_NE(r.err.find("gcx: error: the translation does not move the tool like A.nct; nothing "
                       "was written:\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("A.nct:2"), std::string::npos) << r.err; // the source line of the move
}

TEST_F(TranslateCli, AnUnknownTargetIsRefused) {
  write("A.nct", kProgram);
  EXPECT_EQ(gcx("translate A.nct --to dxf").err,
            "gcx: error: --to dxf: the targets are canonical, ngc, nct, fms3000, wl4\n");
}

// To itself a program keeps every structure: it is printed back as written (gcx fmt) and
// proven; its subprograms stay where they are, called as before (docs/translation.md).
TEST_F(TranslateCli, TheSameDialectKeepsEveryStructure) {
  write("A.nct", "G90 G0 X0 Y0 Z10\n#1=0\nWHILE [#1 LT 2] DO1\nG99 G81 X[#1*5] R2 Z-3 F100\n"
                 "#1=#1+1\nEND1\nG80\nM98 P20\nM30\n");
  write("O0020.nct", "O20\nG91 G1 X1 F100\nG90\nM99\n");
  const Result r = gcx("translate A.nct --to nct -o B.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(dir_ / "B.nct"), "G90 G0 X0 Y0 Z10\n#1=0\nWHILE[#1 LT 2] DO1\n"
                                      "G99 G81 X[#1*5] R2 Z-3 F100\n#1=#1+1\nEND1\nG80\n"
                                      "M98 P20\nM30\n");
  EXPECT_EQ(r.err, "gcx: A.nct -> B.nct: verified, moves the tool like the source within 0.001 "
                   "mm\n");
}

// --expand subprograms runs the calls out into the blocks they run; cycles stay.
TEST_F(TranslateCli, TheSameDialectExpandsWhatExpandNames) {
  write("A.nct", "G90 G0 X0 Y0 Z10\nG99 G81 X5 R2 Z-3 F100\nX10\nG80\nM98 P20\nM30\n");
  write("O0020.nct", "O20\nG91 G1 X1 F100\nG90\nM99\n");
  const Result r = gcx("translate A.nct --to nct --expand subprograms -o B.nct");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(dir_ / "B.nct"),
            "G90 G0 X0 Y0 Z10\nG99 G81 X5 R2 Z-3 F100\nX10\nG80\nO20\nG91 G1 X1 F100\nG90\nM30\n");
  EXPECT_NE(r.err.find("gcx: note: A.nct: subprograms, loops, variables and modal calls expanded "
                       "into the blocks they run\n"),
            std::string::npos)
      << r.err;
}

// A tree: each program in its own process, a failure reported without stopping the rest, the
// program's own setup beside it, other files skipped; report.csv names every program.
TEST_F(TranslateCli, ABatchTranslatesATreeAndReportsEachProgram) {
  write("in/a/ONE.nct", kProgram);
  write("in/a/ONE.setup.json", R"({"work_offsets": {"G54": [100, 0, 0]}})");
  write("in/b/TWO.nct", "G0 X1\nG1 X2\nM30\n"); // G1 without F: an error
  write("in/b/THREE.wl4", "%THREE\nG0 X5 Y5\nM2\n%\n");
  write("in/notes.txt", "not a program\n");
  const Result r = gcx("translate in --to ngc -o out --jobs 2");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.out.find("3 programs to ngc with 2 jobs in "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": 2 verified, 1 failed; 2 other files skipped;"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("failed: b/TWO.nct: "), std::string::npos) << r.out;
  // kept as written: the program runs in the frame of its setup beside it, as the proof did
  EXPECT_NE(readFile(dir_ / "out/a/ONE.ngc").find("\nG90 G0 X10 Y5\nG1 X20 F100\nM30\n"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out/b/THREE.ngc"));
  EXPECT_FALSE(fs::exists(dir_ / "out/b/TWO.ngc"));
  const std::string csv = readFile(dir_ / "out/report.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "program,output,status,exit,seconds,peak_rss_kb,reason,kept,expanded");
  EXPECT_NE(csv.find("\na/ONE.nct,out/a/ONE.ngc,verified,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nb/THREE.wl4,out/b/THREE.ngc,verified,0,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nb/TWO.nct,out/b/TWO.ngc,failed,1,"), std::string::npos) << csv;
  EXPECT_NE(readFile(dir_ / "out/report.html").find("<td>b/TWO.nct</td><td>failed</td>"),
            std::string::npos);
}

// A subprogram is not run alone, where its M99 would restart it until a limit stops it: one
// the batch's programs call is translated with its caller, one that nobody calls is reported.
TEST_F(TranslateCli, ABatchTranslatesASubprogramWithItsCallerOnly) {
  write("in/O0001.nct", "G90 G0 X0 Y0 Z5\nM98 P2 L2\nM30\n");
  write("in/O0002.nct", "(CALLED TWICE)\nG91 G1 X10 F100\nG90\nM99\n");
  write("in/O0003.nct", "G0 X1\nM99\n");
  const Result r = gcx("translate in --to canonical -o out --jobs 2");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("3 programs to canonical with 2 jobs in "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": 1 verified, 0 failed, 2 subprograms not run on their own; 0 other "
                       "files skipped;"),
            std::string::npos)
      << r.out;
  // the caller's translation holds the subprogram's two passes
  const std::string one = readFile(dir_ / "out/O0001.ngc");
  EXPECT_NE(one.find("\nG1 X10 Y0 Z5 F100\nG1 X20 Y0 Z5 F100\nM30\n"), std::string::npos) << one;
  EXPECT_FALSE(fs::exists(dir_ / "out/O0002.ngc"));
  EXPECT_FALSE(fs::exists(dir_ / "out/O0003.ngc"));
  const std::string csv = readFile(dir_ / "out/report.csv");
  EXPECT_NE(csv.find("\nO0002.nct,,subprogram,0,0.000,0,called by O0001.nct: "
                     "translated with its caller,,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nO0003.nct,,subprogram,0,0.000,0,\"ends in M99, a return to "
                     "its caller, and no program of the folder calls it: a subprogram runs only "
                     "when called\",,\n"),
            std::string::npos)
      << csv;
}

// FMS-3000 runs a program that ends in M99 alone as if it ended in M02 (fms3000.md §2.2): a
// batch translates it as a main program.
TEST_F(TranslateCli, ABatchRunsAnUncalledFms3000ProgramEndingInM99) {
  write("in/7.fms", "G90 G00 X10 Y5\nM99\n");
  const Result r = gcx("translate in --to canonical -o out");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(readFile(dir_ / "out/report.csv").find("\n7.fms,out/7.ngc,verified,0,"),
            std::string::npos);
}

TEST_F(TranslateCli, ABatchNeedsAnOutputFolder) {
  write("in/ONE.nct", kProgram);
  const Result r = gcx("translate in --to ngc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(
      r.err,
      "gcx: error: translating a folder needs -o OUTDIR, the folder the translations go to\n");
}

} // namespace
} // namespace gcx::test
