// The canonical RS274/NGC writer: extra-axis words, spirals with extra axes, modal-change events,
// and a round trip through rs274 (skipped when it is not installed).
#include "emit/canonical.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sstream>

#include "motion/event_builders.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"

namespace gcx::emit {
namespace {

using motion::Event;
using motion::Extra;
using motion::Kind;
using motion::Plane;
using motion::Vec3;
using namespace motion::test;

const char* const kHeader = "(gcx canonical motion: machine frame, mm, absolute; offsets and tool "
                            "lengths are in the coordinates)\n"
                            "G21 G90 G94 G17 G40 G49 G80 G54\n";

/// The program without the two header lines (which every program starts with).
std::string emit(const std::vector<Event>& events) {
  std::ostringstream out;
  CanonicalEmitter w(out);
  for (const Event& e : events)
    w.event(e);
  w.finish();
  std::string s = out.str();
  if (s.starts_with(kHeader)) s.erase(0, std::char_traits<char>::length(kHeader));
  return s;
}

TEST(Canonical, ThreeAxisProgramsHaveNoExtraWords) {
  EXPECT_EQ(emit({rapid({0, 0, 0}, {10, 0, 5}), feed({10, 0, 5}, {10, 0, 0}, 300),
                  arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, 0, 200)}),
            "G0 X10 Y0 Z5\n"
            "G1 X10 Y0 Z0 F300\n"
            "G3 X0 Y10 Z0 I-10 J0 F200\n");
}

// nct.md §3.5 TV7: `G2 I50 Z-20 L4` from (-50, 0, 0) is four full turns; RS274's P counts the
// turns, the first included (docs/canonical.md)
TEST(Canonical, TurnsOfAHelixAreP) {
  EXPECT_EQ(emit({arc(Plane::XY, {-50, 0, 0}, {-50, 0, -20}, {0, 0, 0}, true, 3, 100)}),
            "G2 X-50 Y0 Z-20 I50 J0 P4 F100\n");
  EXPECT_EQ(emit({arc(Plane::XY, {10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, 1, 100)}),
            "G3 X0 Y10 Z0 I-10 J0 P2 F100\n");
}

// A word repeated from the line before is copied (RepeatedWords): each letter keeps its own
// last number, and a changed number is written anew.
TEST(Canonical, RepeatedWordsKeepEachLettersOwnNumber) {
  EXPECT_EQ(emit({feed({0, 0, -1}, {99.25, 0, -1}, 1200), feed({99.25, 0, -1}, {99.25, 1, -1}, 800),
                  feed({99.25, 1, -1}, {-99.75, 1, -1}, 1200),
                  feed({-99.75, 1, -1}, {-99.75, 1, 0.125}, 1200)}),
            "G1 X99.25 Y0 Z-1 F1200\n"
            "G1 X99.25 Y1 Z-1 F800\n"
            "G1 X-99.75 Y1 Z-1 F1200\n"
            "G1 X-99.75 Y1 Z0.125 F1200\n");
}

TEST(Canonical, NoNegativeZero) {
  EXPECT_EQ(emit({rapid({0, 0, 0}, {-0.0, 10, -0.0})}), "G0 X0 Y10 Z0\n");
}

TEST(Canonical, RotaryWordsFromTheFirstRotaryMoveOn) {
  const Extra a0 = Extra::Zero(), a90 = extra(90, 0, 0), c45 = extra(90, 0, 45);
  EXPECT_EQ(emit({rapid({0, 0, 0}, {10, 0, 0}),
                  withExtra(feed({10, 0, 0}, {10, 0, 0}, 720), a0, a90), // rotary only
                  withExtra(feed({10, 0, 0}, {20, 0, 0}, 300), a90, a90),
                  withExtra(arc(Plane::XY, {20, 0, 0}, {10, 10, 0}, {10, 0, 0}, false), a90, c45),
                  withExtra(rapid({10, 10, 0}, {0, 0, 0}), c45, c45)}),
            "G0 X10 Y0 Z0\n"
            "G1 X10 Y0 Z0 A90 B0 C0 F720\n"
            "G1 X20 Y0 Z0 A90 B0 C0 F300\n"
            "G3 X10 Y10 Z0 A90 B0 C45 I-10 J0 F100\n"
            "G0 X0 Y0 Z0 A90 B0 C45\n");
}

TEST(Canonical, ParallelWordsOnlyOnceAParallelAxisMoved) {
  const Extra w0 = Extra::Zero(), w5 = extra(0, 0, 0, 0, 0, 5), uw = extra(0, 0, 0, 2.5, 0, 5);
  EXPECT_EQ(emit({withExtra(feed({0, 0, 0}, {0, 0, 0}, 100), w0, w5),
                  withExtra(feed({0, 0, 0}, {1, 0, 0}, 100), w5, uw),
                  withExtra(feed({1, 0, 0}, {1, 0, 0}, 100), uw, extra(30, 0, 0, 2.5, 0, 5))}),
            "G1 X0 Y0 Z0 U0 V0 W5 F100\n"
            "G1 X1 Y0 Z0 U2.5 V0 W5 F100\n"
            "G1 X1 Y0 Z0 A30 B0 C0 U2.5 V0 W5 F100\n");
}

TEST(Canonical, SpiralLinesInterpolateTheExtraAxes) {
  // Radius 10 -> 20 over a half turn while A turns 0 -> 90 and W rises 0 -> 4.
  Event spiral = withExtra(arc(Plane::XY, {10, 0, 0}, {-20, 0, 0}, {0, 0, 0}, false, 0, 150),
                           Extra::Zero(), extra(90, 0, 0, 0, 0, 4));
  CanonicalOptions opt;
  opt.chordTolerance = 0.5;
  std::ostringstream out;
  CanonicalEmitter w(out, opt);
  w.event(spiral);
  std::vector<Vec3> pts;
  motion::appendArcPoints(motion::ArcGeometry(spiral), opt.chordTolerance, pts);
  ASSERT_GE(pts.size(), 2u);

  // Each line is written like the emitter writes any G1, with A and W linear in t = i/n.
  std::ostringstream want;
  CanonicalEmitter expected(want, opt);
  const double n = static_cast<double>(pts.size());
  Vec3 prev = spiral.start;
  Extra prevExtra = spiral.extraStart;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double t = (i + 1) / n;
    const Extra x = extra(90 * t, 0, 0, 0, 0, 4 * t);
    expected.event(withExtra(feed(prev, pts[i], 150), prevExtra, x));
    prev = pts[i];
    prevExtra = x;
  }
  EXPECT_EQ(out.str(), want.str());
  // The last line ends exactly at the spiral's end.
  EXPECT_TRUE(out.str().ends_with("G1 X-20 Y0 Z0 A90 B0 C0 U0 V0 W4 F150\n")) << out.str();
}

TEST(Canonical, ModalChangeEventsWriteNothing) {
  Event plane = valueEvent(Kind::PlaneChange, 0);
  plane.plane = Plane::ZX;
  Event uv = valueEvent(Kind::PlaneChange, 0);
  uv.text = "UV";
  EXPECT_EQ(
      emit({plane, uv, valueEvent(Kind::UnitsChange, 20), valueEvent(Kind::FeedModeChange, 95)}),
      "");
  // G18 and G95 come from the moves that need them.
  Event zx = arc(Plane::ZX, {0, 0, 10}, {10, 0, 0}, {0, 0, 0}, true, 0, 0.1);
  zx.perRevolution = true;
  EXPECT_EQ(emit({plane, valueEvent(Kind::FeedModeChange, 95), zx}), "G95\n"
                                                                     "G18\n"
                                                                     "G2 X10 Y0 Z0 I0 K-10 F0.1\n");
}

#define SKIP_WITHOUT_RS274()                                                                       \
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed"

// The contract with rotary axes: rs274 run on the output moves A B C like the events.
TEST(Canonical, Rs274ReproducesRotaryMoves) {
  SKIP_WITHOUT_RS274();
  const Extra a0 = Extra::Zero(), a90 = extra(90, 0, 0), abc = extra(180, -30, 12.5);
  const std::vector<Event> events = {
      rapid({0, 0, 0}, {10, 0, 5}),
      withExtra(feed({10, 0, 5}, {10, 0, 5}, 720), a0, a90),
      withExtra(feed({10, 0, 5}, {10, 0, 0}, 300), a90, a90),
      withExtra(arc(Plane::XY, {10, 0, 0}, {-10, 0, -2}, {0, 0, 0}, true, 0, 200), a90, abc),
      withExtra(rapid({-10, 0, -2}, {0, 0, 20}), abc, a0),
      valueEvent(Kind::End, 2),
  };
  std::ostringstream text;
  CanonicalEmitter w(text);
  for (const Event& e : events)
    w.event(e);
  w.finish();
  const oracle::Rs274Result r = oracle::Rs274().run(text.str());
  ASSERT_TRUE(r.ok()) << r.summary() << "\n" << text.str();
  const std::vector<Event> back = oracle::parseCanon(r.canonLines);
  const oracle::CompareResult c = oracle::compareEvents(events, back);
  EXPECT_TRUE(c.equivalent) << c.report << "\n" << text.str();

  // and a wrong angle is noticed
  std::vector<Event> off = events;
  off[3].extraEnd[1] += 0.01;
  off[4].extraStart[1] += 0.01;
  const oracle::CompareResult d = oracle::compareEvents(off, back);
  EXPECT_FALSE(d.equivalent);
  EXPECT_NE(d.report.find("B at the end differs by 0.010000 deg"), std::string::npos) << d.report;
}

} // namespace
} // namespace gcx::emit

namespace gcx::emit {
namespace {

TEST(Canonical, ProvenanceCommentNamesTheCallChain) {
  std::ostringstream out;
  CanonicalOptions opt;
  opt.provenance = true;
  opt.fileName = [](FileId) { return std::string("O0030.nct"); };
  CanonicalEmitter emitter(out, opt);
  motion::Event e;
  e.kind = motion::Kind::Rapid;
  e.end = motion::Vec3(1, 2, 3);
  e.from.at = SourceLoc{0, 4, 1, 0};
  e.from.chain = {{SourceLoc{0, 1, 1, 0}, "O0020 (M98 P20)"},
                  {SourceLoc{0, 2, 1, 0}, "O0030 (G65 P30)"},
                  {SourceLoc{0, 2, 1, 0}, "loop DO1 iteration 2"}};
  emitter.event(e);
  EXPECT_NE(out.str().find("G0 X1 Y2 Z3 (O0030.nct:4, in loop DO1 iteration 2, in O0030 (G65 P30), "
                           "in O0020 (M98 P20))\n"),
            std::string::npos)
      << out.str();
}

} // namespace
} // namespace gcx::emit

namespace gcx::emit {
namespace {

// The same source line in another hole of an L-repeated cycle gets its own comment.
TEST(Canonical, ProvenanceCommentOnEveryNewFrameOfTheSameLine) {
  std::ostringstream out;
  CanonicalOptions opt;
  opt.provenance = true;
  opt.fileName = [](FileId) { return std::string("O0001.nct"); };
  CanonicalEmitter emitter(out, opt);
  for (int hole = 1; hole <= 2; ++hole)
    for (double z : {3.0, -37.0}) {
      motion::Event e;
      e.kind = motion::Kind::Rapid;
      e.end = motion::Vec3(100 * hole, 0, z);
      e.from.at = SourceLoc{0, 2, 1, 0};
      e.from.chain = {{SourceLoc{0, 2, 1, 0}, fmt::format("G81 hole {}", hole)}};
      emitter.event(e);
    }
  const std::string s = out.str();
  EXPECT_EQ(s.substr(s.find('\n', s.find('\n') + 1) + 1),
            "G0 X100 Y0 Z3 (O0001.nct:2, in G81 hole 1)\n"
            "G0 X100 Y0 Z-37\n"
            "G0 X200 Y0 Z3 (O0001.nct:2, in G81 hole 2)\n"
            "G0 X200 Y0 Z-37\n");
}

} // namespace
} // namespace gcx::emit
