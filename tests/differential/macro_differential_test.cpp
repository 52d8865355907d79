// Differential tests of the macro expansion pass against LinuxCNC's rs274, over the corpus in
// tests/differential/macro/NAME/: O0001.nct (NCT main program) with the O####.nct subprograms
// and macros it calls, and expected.ngc, a hand-written LinuxCNC program (o-word subs, while
// loops, if/else, bracketed expressions) that moves the tool as the NCT program means per
// docs nct-macro.md. For each folder:
//  * the oracle half: rs274 runs expected.ngc cleanly and prints only calls the canon reader
//    models (this checks the corpus itself, independently of gcx);
//  * the differential half: `gcx expand O0001.nct --to canonical -o tmp.ngc` succeeds, rs274
//    runs tmp.ngc, and its motion equals the motion of expected.ngc within 1e-4 mm.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <filesystem>

#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

fs::path corpus() {
  return sourceDir() / "tests" / "differential" / "macro";
}

/// Every subfolder of the corpus, sorted by name.
std::vector<std::string> folders() {
  std::vector<std::string> out;
  if (!fs::is_directory(corpus())) return out;
  for (const fs::directory_entry& e : fs::directory_iterator(corpus()))
    if (e.is_directory()) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// A private scratch directory for one test (ctest runs tests in parallel processes), removed
/// at the end of the test.
struct ScratchDir {
  explicit ScratchDir(const std::string& name) {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() / ("gcx-macro-diff-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(counter++) + "-" + name);
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  fs::path path;
};

struct CommandResult {
  int exitCode = -1;  // -1: did not exit normally (or could not start)
  std::string output; // stdout and stderr together
};

/// Runs argv[0] with the arguments (no shell), stdout and stderr captured into `log`.
CommandResult runCommand(const std::vector<std::string>& argv, const fs::path& log) {
  CommandResult r;
  std::vector<char*> args;
  for (const std::string& a : argv)
    args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    r.output = "fork failed";
    return r;
  }
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = ::open("/dev/null", O_RDONLY);
    if (fd >= 0) {
      ::dup2(fd, STDOUT_FILENO);
      ::dup2(fd, STDERR_FILENO);
    }
    if (in >= 0) ::dup2(in, STDIN_FILENO);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) break;
  }
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (fs::exists(log)) r.output = readFile(log);
  return r;
}

struct OracleRun {
  bool ok = false;
  std::string failure; // rs274's summary, when it did not run cleanly
  std::vector<motion::Event> events;
  std::vector<std::string> unsupported; // calls the canon reader could not model
};

OracleRun runRs274(const std::string& program) {
  OracleRun o;
  const oracle::Rs274Result r = oracle::Rs274().run(program);
  if (!r.ok()) {
    o.failure = r.summary();
    return o;
  }
  oracle::CanonOptions copt;
  copt.programText = program;
  oracle::CanonReader reader(copt);
  reader.lines(r.canonLines);
  o.unsupported = reader.unsupported();
  o.events = reader.take();
  o.ok = true;
  return o;
}

std::size_t motionCount(const std::vector<motion::Event>& events) {
  return static_cast<std::size_t>(std::count_if(events.begin(), events.end(), [](const auto& e) {
    return e.kind == motion::Kind::Rapid || e.kind == motion::Kind::Feed ||
           e.kind == motion::Kind::Arc;
  }));
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines)
    s += l + "\n";
  return s;
}

TEST(MacroDifferential, CorpusHasAtLeastTenFolders) {
  const std::vector<std::string> names = folders();
  EXPECT_GE(names.size(), 10u) << corpus();
  for (const std::string& name : names) {
    const fs::path dir = corpus() / name;
    EXPECT_TRUE(fs::exists(dir / "O0001.nct")) << dir << " has no main program O0001.nct";
    EXPECT_TRUE(fs::exists(dir / "expected.ngc")) << dir << " has no expected.ngc";
    if (fs::exists(dir / "O0001.nct")) {
      EXPECT_TRUE(readFile(dir / "O0001.nct").starts_with("("))
          << name << ": O0001.nct must start with a comment saying what it tests";
    }
  }
}

class MacroDifferential : public testing::TestWithParam<std::string> {};

// The corpus itself: expected.ngc is a clean LinuxCNC program with motion we model.
TEST_P(MacroDifferential, ExpectedRunsCleanlyOnRs274) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const fs::path expected = corpus() / GetParam() / "expected.ngc";
  const OracleRun o = runRs274(readFile(expected));
  ASSERT_TRUE(o.ok) << expected << ": " << o.failure;
  EXPECT_TRUE(o.unsupported.empty()) << expected << ":\n" << joined(o.unsupported);
  EXPECT_GT(motionCount(o.events), 2u) << expected << " moves the tool hardly at all";
}

// gcx's expansion of the NCT program moves like the hand-written LinuxCNC translation.
TEST_P(MacroDifferential, GcxExpansionMovesLikeExpected) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const fs::path dir = corpus() / GetParam();
  const ScratchDir scratch(GetParam());
  const fs::path out = scratch.path / "expanded.ngc";
  const CommandResult gcx = runCommand(
      {GCX_BINARY, "expand", (dir / "O0001.nct").string(), "--to", "canonical", "-o", out.string()},
      scratch.path / "gcx.log");
  ASSERT_EQ(gcx.exitCode, 0) << "gcx expand " << (dir / "O0001.nct") << " failed:\n" << gcx.output;
  ASSERT_TRUE(fs::exists(out)) << "gcx expand wrote no " << out;
  const std::string expanded = readFile(out);

  const OracleRun ours = runRs274(expanded);
  ASSERT_TRUE(ours.ok) << "rs274 rejects gcx's expansion: " << ours.failure << "\n--- expanded:\n"
                       << expanded;
  EXPECT_TRUE(ours.unsupported.empty()) << joined(ours.unsupported);
  const OracleRun theirs = runRs274(readFile(dir / "expected.ngc"));
  ASSERT_TRUE(theirs.ok) << "expected.ngc: " << theirs.failure;

  oracle::CompareOptions copt;
  copt.tolerance = 1e-4;
  copt.leftName = "gcx expand";
  copt.rightName = "expected.ngc";
  const oracle::CompareResult c = oracle::compareEvents(ours.events, theirs.events, copt);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- gcx expand output:\n" << expanded;
}

INSTANTIATE_TEST_SUITE_P(Corpus, MacroDifferential, testing::ValuesIn(folders()),
                         [](const testing::TestParamInfo<std::string>& p) {
                           std::string n = "m" + p.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

} // namespace
} // namespace gcx::test
