// The differential corpus (tests/differential/programs) checked against rs274 itself: every
// NCT program there is in the subset common with LinuxCNC, so rs274 must run it unchanged
// (with its setup sidecar as parameter file and tool table) and print only motion we model.
// Programs using G68 (which LinuxCNC lacks) carry a line-by-line NAME.ref.ngc translation
// that uses a G10 L2 R rotation instead, drilling programs with an E word (rejected by rs274,
// whose peck distance is fixed at 0.254 mm) one without it; the translation is run.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "motion/describe.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "oracle/setup.h"
#include "support/test_support.h"

namespace gcx::oracle {
namespace {

using motion::Event;
using motion::Kind;
using motion::Vec3;
namespace fs = std::filesystem;

fs::path corpusDir() {
  return test::sourceDir() / "tests" / "differential" / "programs";
}

std::vector<std::string> programNames() {
  std::vector<std::string> names;
  if (!fs::exists(corpusDir())) return names;
  for (const fs::path& p : test::filesUnder(corpusDir(), {".nct"}))
    names.push_back(p.stem().string());
  return names;
}

std::size_t countLines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text)
    n += c == '\n';
  return n + (!text.empty() && text.back() != '\n');
}

struct Loaded {
  std::string text; // what rs274 runs
  Rs274Options options;
  bool usesReference = false;
};

Loaded load(const std::string& name) {
  Loaded l;
  const fs::path nct = corpusDir() / (name + ".nct");
  l.text = test::readFile(nct);
  const fs::path setup = corpusDir() / (name + ".setup.json");
  if (fs::exists(setup)) {
    OracleSetup s;
    std::string err;
    EXPECT_TRUE(parseSetupJson(test::readFile(setup), s, err)) << setup << ": " << err;
    applySetup(s, l.options);
  }
  const fs::path ref = corpusDir() / (name + ".ref.ngc");
  if (l.text.find("G68") != std::string::npos) {
    EXPECT_TRUE(fs::exists(ref)) << "G68 program without " << ref;
  }
  if (fs::exists(ref)) {
    const std::string refText = test::readFile(ref);
    EXPECT_EQ(countLines(refText), countLines(l.text)) << ref << " must match line by line";
    l.text = refText;
    l.usesReference = true;
  }
  return l;
}

TEST(DifferentialCorpus, Shape) {
  const std::vector<std::string> names = programNames();
  EXPECT_GE(names.size(), 32u);
  for (const std::string& name : names) {
    const std::string text = test::readFile(corpusDir() / (name + ".nct"));
    EXPECT_TRUE(text.starts_with("("))
        << name << ": must start with a comment saying what it tests";
    EXPECT_LE(countLines(text), 30u) << name;
    EXPECT_TRUE(text.ends_with("\n")) << name;
  }
}

class DifferentialProgram : public ::testing::TestWithParam<std::string> {};

TEST_P(DifferentialProgram, RunsUnchangedOnRs274) {
  if (!rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const Loaded l = load(GetParam());
  const Rs274Result r = Rs274(l.options).run(l.text);
  ASSERT_TRUE(r.ok()) << GetParam() << ": " << r.summary();
  CanonOptions copt;
  copt.programText = l.text;
  CanonReader reader(copt);
  reader.lines(r.canonLines);
  EXPECT_TRUE(reader.unsupported().empty()) << reader.unsupported().front();
  const std::vector<Event>& ev = reader.events();
  std::size_t motion = 0;
  const std::size_t lines = countLines(l.text);
  for (const Event& e : ev) {
    if (e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc) ++motion;
    EXPECT_GE(e.from.at.line, 2u) << motion::describeEvent(e); // line 1 is the comment
    EXPECT_LE(e.from.at.line, lines) << motion::describeEvent(e);
  }
  EXPECT_GE(motion, 3u);
  ASSERT_FALSE(ev.empty());
  EXPECT_EQ(ev.back().kind, Kind::End);
  // Itself, split differently or not, is equivalent (exercises the comparator on real data).
  const CompareResult same = compareEvents(ev, ev);
  EXPECT_TRUE(same.equivalent) << same.report;
}

INSTANTIATE_TEST_SUITE_P(Programs, DifferentialProgram, ::testing::ValuesIn(programNames()),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           std::string n = "p" + p.param;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// The G68 references really rotate about the programmed centre: first rotated move.
TEST(DifferentialCorpus, G68ReferencesRotateAboutTheCentre) {
  if (!rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  struct Case {
    const char* name;
    Vec3 want; // machine end of the first move after G68 (line 5)
  };
  const double r = std::sqrt(0.5);
  const Case cases[] = {
      // G68 X0 Y0 R30, G0 X10 Y0
      {"28_g68_rotation", Vec3(10 * std::cos(std::numbers::pi / 6), 5, 5)},
      // G68 X20 Y10 R-45, G0 X40 Y10: (20,10) + Rot(-45)(20, 0)
      {"29_g68_center", Vec3(20 + 20 * r, 10 - 20 * r, 5)},
  };
  for (const Case& c : cases) {
    const Loaded l = load(c.name);
    ASSERT_TRUE(l.usesReference) << c.name;
    const Rs274Result res = Rs274(l.options).run(l.text);
    ASSERT_TRUE(res.ok()) << c.name << ": " << res.summary();
    const std::vector<Event> ev = parseCanon(res.canonLines);
    const Event* first = nullptr;
    for (const Event& e : ev)
      if (e.from.at.line == 5) {
        first = &e;
        break;
      }
    ASSERT_NE(first, nullptr) << c.name;
    EXPECT_LT((first->end - c.want).cwiseAbs().maxCoeff(), 1e-4)
        << c.name << ": " << motion::describeEvent(*first);
  }
}

} // namespace
} // namespace gcx::oracle
