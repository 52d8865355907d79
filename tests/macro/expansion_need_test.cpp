// macro::mayNeedExpansion decides, before a run, whether a program streams or goes through the
// expansion pass: any of the dialect's markers (NCT: M98, GOTO, WHILE, ...), '#' or '[' anywhere,
// in any case, also across the chunks the file is read in.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

#include "dialects/nct/profile.h"
#include "passes/macro/expander.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

class ExpansionNeed : public testing::Test {
protected:
  void SetUp() override {
    path_ = fs::temp_directory_path() / fmt::format("gcx-expansion-need-{}.nct", getpid());
  }
  void TearDown() override { fs::remove(path_); }

  bool needs(const std::string& text) {
    std::ofstream(path_, std::ios::binary) << text;
    return macro::mayNeedExpansion(path_.string(), nct::profile());
  }

  fs::path path_;
};

TEST_F(ExpansionNeed, PlainMotionStreams) {
  EXPECT_FALSE(needs("G0 X0 Y0\nG1 X10 F100\nG2 X20 I5 J0\nM30\n"));
  EXPECT_FALSE(needs(""));
  EXPECT_FALSE(needs("M9 G6 D1 E5 I0 B1 P2 W0\n")); // first letters of markers only
}

TEST_F(ExpansionNeed, MarkersInAnyCase) {
  EXPECT_TRUE(needs("G1 X1\nM98 P12\n"));
  EXPECT_TRUE(needs("g1 x1\nm98 p12\n"));
  EXPECT_TRUE(needs("WHILE[#1 LT 3] DO1\n"));
  EXPECT_TRUE(needs("goto 10\n"));
  EXPECT_TRUE(needs("G71.7 P10 Q20\n"));
  EXPECT_TRUE(needs("G1 X#1\n"));
  EXPECT_TRUE(needs("G1 X[1+2]\n"));
  EXPECT_FALSE(needs("G71 P10 Q20\n"));
}

TEST_F(ExpansionNeed, MarkerAcrossTheChunkBoundary) {
  // the file is read in chunks of 65,536 bytes: a marker may start in one and end in the next
  for (std::size_t at : {65533u, 65534u, 65535u, 65536u, 131070u}) {
    std::string text(at, ' ');
    for (std::size_t i = 99; i < at; i += 100)
      text[i] = '\n';
    text += "GOTO 5\n";
    EXPECT_TRUE(needs(text)) << "marker at byte " << at;
    text.replace(at, 4, "GOT ");
    EXPECT_FALSE(needs(text)) << "no marker at byte " << at;
  }
}

TEST_F(ExpansionNeed, TwoHalvesSeeEachMarkerOnce) {
  // a marker counts in the part where it begins, read past the part's end if it must; so the
  // two halves a two-thread run scans at once agree with one scan wherever the cut falls
  for (std::size_t marker : {10u, 65533u, 65536u, 70000u}) {
    std::string text(marker, ' ');
    for (std::size_t i = 99; i < marker; i += 100)
      text[i] = '\n';
    text += "GOTO 5\n";
    text += std::string(200000 - text.size(), ' ');
    std::ofstream(path_, std::ios::binary) << text;
    for (std::size_t cut : {marker - 1, marker, marker + 1, marker + 3, marker + 4}) {
      const bool first = macro::mayNeedExpansion(path_.string(), nct::profile(), 0, cut);
      const bool second = macro::mayNeedExpansion(path_.string(), nct::profile(), cut);
      EXPECT_EQ(first, cut > marker) << "marker at " << marker << ", cut at " << cut;
      EXPECT_EQ(second, cut <= marker) << "marker at " << marker << ", cut at " << cut;
    }
  }
}

} // namespace
} // namespace gcx::test
