// The two-thread streaming loop (--jobs 2) reports exactly what the one-thread loop reports:
// the same canonical output, the same diagnostics in the same order, the same stop. Programs
// span several batches of the reader thread, with warnings, errors and stops placed inside them.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "cli/execute.h"
#include "cli/session.h"
#include "emit/canonical.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

struct RunResult {
  bool ok = false;
  std::string output;
  std::vector<std::string> diagnostics; // "line:col severity code"
};

class BlockPipeline : public testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("gcx-block-pipeline-{}", getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RunResult run(const std::string& text, unsigned jobs, std::size_t maxErrors = 50) {
    const fs::path path = dir_ / "O0001.nct";
    std::ofstream(path, std::ios::binary) << text;
    cli::CommonOptions opt;
    opt.jobs = jobs;
    opt.maxErrors = maxErrors;
    cli::Session s(opt);
    EXPECT_TRUE(s.open(path.string()));
    std::ostringstream out, print;
    emit::CanonicalEmitter emitter(out);
    RunResult r;
    r.ok = cli::executeProgram(s, opt, machine::Setup{}, emitter, print);
    r.output = out.str();
    for (const diag::Diagnostic& d : s.diags().all())
      r.diagnostics.push_back(fmt::format("{}:{} {} {}", d.range.begin.line, d.range.begin.col,
                                          static_cast<int>(d.severity), d.code));
    return r;
  }

  // Runs with both settings and returns the one-thread result after checking they agree.
  RunResult runBoth(const std::string& text, std::size_t maxErrors = 50) {
    const RunResult one = run(text, 1, maxErrors), two = run(text, 2, maxErrors);
    EXPECT_EQ(one.ok, two.ok);
    EXPECT_EQ(one.output, two.output);
    EXPECT_EQ(one.diagnostics, two.diagnostics);
    return one;
  }

  fs::path dir_;
};

// Block k (1-based line k) of a zigzag; `special(k)` may replace it.
template <class F> std::string program(int blocks, F special) {
  std::string text;
  for (int k = 1; k <= blocks; ++k) {
    const std::string s = special(k);
    text += s.empty() ? fmt::format("G1 X{} Y{} F1000\n", k % 50, k % 7) : s + "\n";
  }
  return text;
}

int count(const std::vector<std::string>& list, const std::string& code) {
  int n = 0;
  for (const std::string& d : list)
    n += d.size() >= code.size() && d.compare(d.size() - code.size(), code.size(), code) == 0;
  return n;
}

TEST_F(BlockPipeline, WarningsAcrossBatchesKeepTheirOrder) {
  // '!' is read as a minus sign with a warning (nct.md §0.1), every 97th block
  const RunResult r = runBoth(program(3000, [](int k) {
    return k == 3000 ? std::string("M30") : k % 97 == 0 ? fmt::format("G1 X!{}", k) : "";
  }));
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 30);
  EXPECT_EQ(r.diagnostics.front(), "97:5 1 GCXW01");
  EXPECT_EQ(r.diagnostics.back(), "2910:5 1 GCXW01");
}

TEST_F(BlockPipeline, RunTimeErrorDropsWhatTheReaderReadBeyondIt) {
  // an arc whose radius cannot reach its end point stops the run at line 1500; the warnings the
  // reader thread met further on were never reached by a one-thread run
  const RunResult r = runBoth(program(3000, [](int k) {
    return k == 1500    ? std::string("G2 X100 Y0 R1")
           : k % 5 == 0 ? fmt::format("G1 X!{}", k % 50)
                        : "";
  }));
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.back().substr(0, 7), "1500:1 ");
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 299); // lines 5 ... 1495
}

TEST_F(BlockPipeline, StaticCheckErrorStopsBeforeTheBlockRuns) {
  const RunResult r = runBoth(program(3000, [](int k) {
    return k == 1234 ? std::string("G0 G1 X1") : k % 11 == 0 ? std::string("G1 X!1") : "";
  }));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(count(r.diagnostics, "GCX012"), 1);
  EXPECT_EQ(count(r.diagnostics, "GCXW01"), 112); // lines 11 ... 1232
}

TEST_F(BlockPipeline, EndOfProgramStopsReading) {
  const RunResult r = runBoth(program(2000, [](int k) {
    return k == 600 ? std::string("M30") : k > 600 && k % 3 == 0 ? std::string("G1 X!1") : "";
  }));
  EXPECT_TRUE(r.ok);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.output.substr(r.output.size() - 4), "M30\n");
}

TEST_F(BlockPipeline, SyntaxErrorsAndTheErrorLimit) {
  // a syntax error every 13th block: the reader skips each one, the error limit caps the list
  const RunResult r =
      runBoth(program(2000, [](int k) { return k % 13 == 0 ? std::string("G1 X1..2") : ""; }), 20);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(count(r.diagnostics, "GCX009"), 1); // "too many errors" once, at the limit
}

TEST_F(BlockPipeline, ErrorAtTheLastReadReportsAfterEveryBlock) {
  const RunResult r = runBoth(program(1000, [](int k) {
    return k == 1000 ? std::string("G1 X1 (open comment") : k % 100 == 0 ? "G1 X!2" : "";
  }));
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.back(), "1000:7 2 GCX006");
}

TEST_F(BlockPipeline, PackedAndWholeBlocksInterleaved) {
  // numbered blocks travel packed, those with a comment whole (cli/packed_blocks.h); the
  // interpreter's error is located inside a packed block, at its X word (NCT's G4 takes P)
  const RunResult r = runBoth(program(2000, [](int k) {
    return k == 1700    ? std::string("N1700 G4 X-1")
           : k % 7 == 0 ? fmt::format("N{} G1 X{} (seven)", k, k % 40)
                        : fmt::format("N{} G1 X{} Y{} F900", k, k % 50, k % 3);
  }));
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics.back(), "1700:10 2 GCX035");
}

TEST_F(BlockPipeline, AVariableInEitherHalfSendsTheProgramToTheExpansionPass) {
  // each thread scans half of the file for what needs the expansion pass while the reader
  // starts; a find in either half drops what was read and expands the whole program
  for (const int at : {2, 2990}) {
    const RunResult r = runBoth(program(3000, [&](int k) {
      return k == at       ? std::string("#1=7")
             : k == at + 1 ? std::string("G1 X#1 Y0")
             : k == 3000   ? std::string("M30")
                           : "";
    }));
    EXPECT_TRUE(r.ok) << "variable at line " << at;
    EXPECT_TRUE(r.diagnostics.empty()) << "variable at line " << at;
    EXPECT_NE(r.output.find("G1 X7 Y0"), std::string::npos) << "variable at line " << at;
  }
}

TEST_F(BlockPipeline, WhatASinkThrowsReachesTheCallerWithTheReaderStopped) {
  // an output that gives up (a cap, no memory) throws from the executing thread while the reader
  // thread is still reading: it must be stopped and joined, not left to end the process
  struct Full : std::runtime_error {
    Full() : std::runtime_error("output full") {}
  };
  struct ThrowingSink : motion::Sink {
    int events = 0;
    void event(const motion::Event&) override {
      if (++events == 1000) throw Full();
    }
  };
  const fs::path path = dir_ / "O0002.nct";
  std::ofstream(path, std::ios::binary) << program(5000, [](int) { return std::string(); });
  for (const unsigned jobs : {1u, 2u}) {
    cli::CommonOptions opt;
    opt.jobs = jobs;
    cli::Session s(opt);
    ASSERT_TRUE(s.open(path.string()));
    ThrowingSink sink;
    std::ostringstream print;
    EXPECT_THROW(cli::executeProgram(s, opt, machine::Setup{}, sink, print), Full)
        << "jobs " << jobs;
    EXPECT_EQ(sink.events, 1000) << "jobs " << jobs;
  }
}

} // namespace
} // namespace gcx::test
