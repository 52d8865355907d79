// gcx check on two threads (--jobs 2) reads the two halves of a large file at once and reports
// exactly what one thread reports: the same diagnostics in the same order, the same counts. The
// second half's own reading is taken only where it cannot differ; where state crosses the cut
// (a comment, G10 data records, an open loop, a '%'), the half is read again in sequence.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

#include "cli/check_in_parts.h"
#include "cli/session.h"
#include "dialects/nct/profile.h"
#include "passes/check/static_checks.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

struct CheckResult {
  cli::CheckedBlocks read;
  std::vector<std::string> diagnostics; // "line:col severity code message"
};

class CheckInParts : public testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("gcx-check-in-parts-{}", getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CheckResult run(const std::string& text, unsigned jobs, std::size_t maxErrors = 50,
                  unsigned partsPerJob = 1) {
    const fs::path path = dir_ / "O0001.nct";
    std::ofstream(path, std::ios::binary) << text;
    cli::CommonOptions opt;
    opt.maxErrors = maxErrors;
    cli::Session s(opt);
    EXPECT_TRUE(s.open(path.string()));
    check::StaticChecker checker(s.dialect().profile(), s.diags());
    CheckResult r;
    r.read = cli::checkBlocks(s, checker, jobs, partsPerJob);
    checker.finish(s.file(), r.read.failed > 0);
    for (const diag::Diagnostic& d : s.diags().all())
      r.diagnostics.push_back(fmt::format("{}:{} {} {} {}", d.range.begin.line, d.range.begin.col,
                                          static_cast<int>(d.severity), d.code, d.message));
    return r;
  }

  // Checks with one and two threads; returns the two-thread result after comparing them. One
  // part a thread by default: the cut falls in the middle, where the tests put what crosses it.
  CheckResult runBoth(const std::string& text, std::size_t maxErrors = 50,
                      unsigned partsPerJob = 1) {
    const CheckResult one = run(text, 1, maxErrors), two = run(text, 2, maxErrors, partsPerJob);
    EXPECT_EQ(one.read.blocks, two.read.blocks);
    EXPECT_EQ(one.read.failed, two.read.failed);
    EXPECT_EQ(one.read.partsTaken, 0u);
    EXPECT_EQ(one.diagnostics, two.diagnostics);
    return two;
  }

  fs::path dir_;
};

constexpr int kLines = 160000;      // 3.2 MB: two parts of more than the 1 MB minimum
constexpr int kMiddle = kLines / 2; // the cut falls within a few lines of it
constexpr int kNear = 40;           // lines either side of the middle that surely hold the cut

// Line k (1-based) of a program of 20-byte lines; `special(k)` may replace one.
template <class F> std::string program(F special) {
  std::string text;
  text.reserve(static_cast<std::size_t>(kLines) * 22);
  for (int k = 1; k <= kLines; ++k) {
    const std::string s = special(k);
    text += s.empty() ? fmt::format("G1 X{:05} Y{:05} F9\n", k % 90000, k % 7) : s + "\n";
  }
  return text;
}

int count(const std::vector<std::string>& list, const std::string& code) {
  int n = 0;
  for (const std::string& d : list)
    n += d.find(" " + code + " ") != std::string::npos;
  return n;
}

TEST_F(CheckInParts, PlainProgramIsReadInTwoPartsWithDiagnosticsInOrder) {
  // '!' is read as a minus sign with a warning, and G0 G1 is a modal conflict: both halves
  const CheckResult r = runBoth(program([](int k) {
    return k % 9973 == 0 ? std::string("G1 X!1") : k % 30011 == 0 ? "G0 G1 X1" : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 1u);
  EXPECT_EQ(r.read.blocks, static_cast<std::size_t>(kLines));
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 16); // lines 9973 ... 159568
  EXPECT_EQ(count(r.diagnostics, "GCX012"), 5);  // lines 30011 ... 150055
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.front().substr(0, 8), "9973:5 1");
  EXPECT_EQ(r.diagnostics.back().substr(0, 10), "159568:5 1");
}

TEST_F(CheckInParts, CommentAcrossTheCutIsReadInSequence) {
  // a comment over the lines near the middle holds the cut: LF ends no block inside it
  const CheckResult r = runBoth(program([](int k) {
    return k == kMiddle - kNear                         ? std::string("G1 X1 (a comment")
           : k > kMiddle - kNear && k < kMiddle + kNear ? "G1 X!1 inside it"
           : k == kMiddle + kNear                       ? ") G1 X2"
           : k % 7919 == 0                              ? "G1 X!1"
                                                        : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 0u);
  EXPECT_EQ(r.read.blocks, static_cast<std::size_t>(kLines - 2 * kNear));
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 20); // lines 7919 ... 158380, none in the comment
}

TEST_F(CheckInParts, DataRecordsAcrossTheCutAreReadInSequence) {
  // G10 L52 ... G11 over the cut: N is a parameter number in between, R its value
  const CheckResult r = runBoth(program([](int k) {
    return k == kMiddle - kNear                         ? std::string("G10 L52")
           : k == kMiddle + kNear                       ? "G11"
           : k > kMiddle - kNear && k < kMiddle + kNear ? fmt::format("N{} R{}", 100 + k % 9, k % 5)
                                                        : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 0u);
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST_F(CheckInParts, LoopOpenAcrossTheCutIsReadInSequence) {
  // DO1 before the cut, END1 after it: no "END1 without DO1" from the second part's own reading
  const CheckResult r = runBoth(program([](int k) {
    return k == kMiddle - kNear   ? std::string("WHILE[#1LT3]DO1")
           : k == kMiddle + kNear ? "END1"
                                  : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 0u);
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST_F(CheckInParts, JumpsAcrossTheCutFindTheirTargets) {
  // GOTO targets in the other half, and one target nowhere (an error at the end, once)
  const CheckResult r = runBoth(program([](int k) {
    return k == 10                    ? std::string("GOTO150")
           : k == 150000              ? "N150 G1 X1"
           : k == 150001              ? "GOTO20"
           : k == 20                  ? "N20 G1 X2"
           : k == kMiddle + 2 * kNear ? "GOTO77"
                                      : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 1u);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0],
            fmt::format("{}:1 2 2125 block N77 not found in this file", kMiddle + 2 * kNear));
}

TEST_F(CheckInParts, PercentAfterBlocksInTheSecondPart) {
  // '%' between blocks is an error, reported where it stands
  const CheckResult r =
      runBoth(program([](int k) { return k == kMiddle + 2 * kNear ? std::string("%") : ""; }));
  EXPECT_EQ(r.read.partsTaken, 1u);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].rfind(fmt::format("{}:1 2 GCX007", kMiddle + 2 * kNear), 0), 0u);
}

TEST_F(CheckInParts, PercentAtTheStartOfTheSecondPartIsReadInSequence) {
  // the second part's own checker, having seen no block, would take its first '%' for the
  // program's opening one
  const CheckResult r = runBoth(program(
      [](int k) { return k > kMiddle - kNear && k < kMiddle + kNear ? std::string("%") : ""; }));
  EXPECT_EQ(r.read.partsTaken, 0u);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].rfind(fmt::format("{}:1 2 GCX007", kMiddle - kNear + 1), 0), 0u);
}

TEST_F(CheckInParts, ErrorLimitReachedInTheFirstPart) {
  const CheckResult r =
      runBoth(program([](int k) { return k % 1000 == 0 ? std::string("G1 X1..2") : ""; }), 20);
  EXPECT_EQ(r.read.partsTaken, 1u);
  EXPECT_EQ(count(r.diagnostics, "GCX009"), 1); // "too many errors" once, at the limit
  EXPECT_EQ(r.read.failed, static_cast<std::size_t>(kLines / 1000));
}

TEST_F(CheckInParts, BinaryByteInTheFirstPartEndsTheRead) {
  const CheckResult r = runBoth(program([](int k) {
    return k == 1000 ? std::string("G1 X1\0", 6) : k % 5000 == 0 ? "G1 X!1" : "";
  }));
  EXPECT_EQ(r.read.partsTaken, 0u);
  EXPECT_EQ(count(r.diagnostics, "GCX003"), 1);
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 0);
}

TEST_F(CheckInParts, PartsTakenByWhicheverThreadIsFreeReportAtTheirOwnLines) {
  // three parts (3.2 MB in parts of at least 1 MB), each numbering its lines from 1 until the
  // parts before it are read: warnings and errors in every part, a missing GOTO target and a
  // '%' after blocks in the last part, all at the lines one thread reports
  const CheckResult r = runBoth(program([](int k) {
                                  return k == 150001      ? std::string("GOTO77")
                                         : k == 150002    ? "%"
                                         : k % 9973 == 0  ? "G1 X!1"
                                         : k % 30011 == 0 ? "G0 G1 X1"
                                                          : "";
                                }),
                                50, 4);
  EXPECT_EQ(r.read.partsTaken, 2u);
  EXPECT_EQ(r.read.blocks, static_cast<std::size_t>(kLines)); // the % too
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 16);
  EXPECT_EQ(count(r.diagnostics, "GCX012"), 5);
  EXPECT_EQ(count(r.diagnostics, "GCX007"), 1);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.back(), "150001:1 2 2125 block N77 not found in this file");
}

} // namespace
} // namespace gcx::test
