// Comparing event lists: kinds in order, tolerance, collinear splits, arcs, reports.
#include <gtest/gtest.h>

#include "motion/describe.h"
#include "oracle/compare.h"

namespace gcx::oracle {
namespace {

using motion::Event;
using motion::Kind;
using motion::Plane;
using motion::Vec3;

Event move(Kind k, Vec3 a, Vec3 b, std::uint32_t line, double feed = 100) {
  Event e;
  e.kind = k;
  e.start = a;
  e.end = b;
  e.from.at.line = line;
  if (k != Kind::Rapid) e.feed = feed;
  return e;
}

Event arc(Vec3 a, Vec3 b, Vec3 c, bool cw, std::uint32_t line, int turns = 0) {
  Event e = move(Kind::Arc, a, b, line);
  e.center = c;
  e.clockwise = cw;
  e.turns = turns;
  e.plane = Plane::XY;
  e.startRadius = (a - c).norm();
  e.endRadius = (b - c).norm();
  return e;
}

Event other(Kind k, double value, std::uint32_t line) {
  Event e;
  e.kind = k;
  e.value = value;
  e.from.at.line = line;
  return e;
}

std::vector<Event> sample() {
  return {move(Kind::Rapid, {0, 0, 0}, {0, 0, 5}, 2), move(Kind::Feed, {0, 0, 5}, {10, 0, 5}, 3),
          arc({10, 0, 5}, {0, 10, 5}, {0, 0, 5}, false, 4), other(Kind::Dwell, 2, 5),
          move(Kind::Feed, {0, 10, 5}, {0, 0, 5}, 6)};
}

TEST(Compare, IdenticalListsAreEquivalent) {
  const CompareResult r = compareEvents(sample(), sample());
  EXPECT_TRUE(r.equivalent) << r.report;
  EXPECT_EQ(r.matched, 5u);
  EXPECT_TRUE(r.report.empty());
}

TEST(Compare, IgnoresNonGeometryKindsAndZeroLengthMoves) {
  std::vector<Event> a = sample(), b = sample();
  a.insert(a.begin() + 1, other(Kind::Spindle, 1000, 2));
  a.push_back(other(Kind::End, 0, 7));
  b.insert(b.begin() + 2, move(Kind::Rapid, {10, 0, 5}, {10, 0, 5}, 3)); // zero length
  b.insert(b.begin(), other(Kind::Coolant, 8, 1));
  const CompareResult r = compareEvents(a, b);
  EXPECT_TRUE(r.equivalent) << r.report;
}

TEST(Compare, WithinToleranceMatchesBeyondDoesNot) {
  std::vector<Event> b = sample();
  b[1].end.x() += 0.00005;
  b[2].start.x() += 0.00005;
  EXPECT_TRUE(compareEvents(sample(), b).equivalent);
  b[1].end.x() += 0.0002;
  b[2].start.x() += 0.0002;
  const CompareResult r = compareEvents(sample(), b);
  EXPECT_FALSE(r.equivalent);
  EXPECT_EQ(r.leftIndex, 1u);
  EXPECT_EQ(r.rightIndex, 1u);
  EXPECT_NE(r.report.find("end points differ"), std::string::npos) << r.report;
  CompareOptions loose;
  loose.tolerance = 1e-3;
  EXPECT_TRUE(compareEvents(sample(), b, loose).equivalent);
}

TEST(Compare, LineMatchesChainOfCollinearPiecesOnEitherSide) {
  std::vector<Event> split = sample();
  split.erase(split.begin() + 1);
  split.insert(split.begin() + 1, {move(Kind::Feed, {0, 0, 5}, {2.5, 0, 5}, 3),
                                   move(Kind::Feed, {2.5, 0, 5}, {7, 0, 5}, 3),
                                   move(Kind::Feed, {7, 0, 5}, {10, 0, 5}, 3)});
  EXPECT_TRUE(compareEvents(sample(), split).equivalent);
  EXPECT_TRUE(compareEvents(split, sample()).equivalent);

  // a chain turning back on itself is not a straight line
  std::vector<Event> back = sample();
  back.erase(back.begin() + 1);
  back.insert(back.begin() + 1, {move(Kind::Feed, {0, 0, 5}, {12, 0, 5}, 3),
                                 move(Kind::Feed, {12, 0, 5}, {10, 0, 5}, 3)});
  EXPECT_FALSE(compareEvents(sample(), back).equivalent);

  // chords bending by more than the tolerance are not merged
  std::vector<Event> bent = sample();
  bent.erase(bent.begin() + 1);
  bent.insert(bent.begin() + 1, {move(Kind::Feed, {0, 0, 5}, {5, 0.001, 5}, 3),
                                 move(Kind::Feed, {5, 0.001, 5}, {10, 0, 5}, 3)});
  const CompareResult r = compareEvents(sample(), bent);
  EXPECT_FALSE(r.equivalent);
  EXPECT_NE(r.report.find("end points differ"), std::string::npos) << r.report;

  // pieces with a different feed are not one move when feeds are compared
  std::vector<Event> feeds = split;
  feeds[2].feed = 50;
  EXPECT_FALSE(compareEvents(sample(), feeds).equivalent);
  CompareOptions noFeed;
  noFeed.compareFeed = false;
  EXPECT_TRUE(compareEvents(sample(), feeds, noFeed).equivalent);
}

TEST(Compare, RapidVersusFeedIsADivergence) {
  std::vector<Event> b = sample();
  b[1].kind = Kind::Rapid;
  const CompareResult r = compareEvents(sample(), b);
  EXPECT_FALSE(r.equivalent);
  EXPECT_NE(r.report.find("different kinds: Feed vs Rapid"), std::string::npos) << r.report;
}

TEST(Compare, ArcsByCentreDirectionAndTurns) {
  std::vector<Event> b = sample();
  b[2].clockwise = true;
  CompareResult r = compareEvents(sample(), b);
  EXPECT_FALSE(r.equivalent);
  EXPECT_NE(r.report.find("arc directions differ: CCW vs CW"), std::string::npos) << r.report;

  b = sample();
  b[2].turns = 1;
  r = compareEvents(sample(), b);
  EXPECT_NE(r.report.find("extra full turns differ"), std::string::npos) << r.report;

  b = sample();
  b[2].center = Vec3(10, 10, 5); // the other centre for the same end points
  r = compareEvents(sample(), b);
  EXPECT_NE(r.report.find("arc centres differ"), std::string::npos) << r.report;
}

TEST(Compare, DwellTimesAndFeeds) {
  std::vector<Event> b = sample();
  b[3].value = 2.5;
  CompareResult r = compareEvents(sample(), b);
  EXPECT_NE(r.report.find("dwell times differ: 2 vs 2.5"), std::string::npos) << r.report;
  b = sample();
  b[4].feed = 200;
  r = compareEvents(sample(), b);
  EXPECT_NE(r.report.find("feeds differ: 100 vs 200"), std::string::npos) << r.report;
}

TEST(Compare, ReportNamesBothSidesAndTheirSourceLines) {
  std::vector<Event> b = sample();
  b[4].end = Vec3(0, 1, 5);
  b[4].from.at.line = 16;
  SourceManager left, right;
  const FileId lf = left.addBuffer("O0001.nct", "L1\nL2\nL3\nL4\nL5\nG1 X0 Y0\n");
  const FileId rf = right.addBuffer("emitted.ngc", std::string(15, '\n') + "G1 X0 Y1\n");
  std::vector<Event> a = sample();
  for (Event& e : a)
    e.from.at.file = lf;
  for (Event& e : b)
    e.from.at.file = rf;
  a[4].from.at.col = 1; // the front end's locations carry col and byte offset
  a[4].from.at.offset = 15;
  b[4].from.at.col = 1;
  b[4].from.at.offset = 15;
  CompareOptions opt;
  opt.leftSources = &left;
  opt.rightSources = &right;
  const CompareResult r = compareEvents(a, b, opt);
  ASSERT_FALSE(r.equivalent);
  EXPECT_EQ(r.matched, 4u);
  EXPECT_NE(r.report.find("gcx"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("rs274"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("O0001.nct:6:1 \"G1 X0 Y0\""), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("emitted.ngc:16:1 \"G1 X0 Y1\""), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("(0.0000, 1.0000, 5.0000)"), std::string::npos) << r.report;
}

TEST(Compare, OneSideLonger) {
  std::vector<Event> b = sample();
  b.pop_back();
  CompareResult r = compareEvents(sample(), b);
  EXPECT_FALSE(r.equivalent);
  EXPECT_EQ(r.leftIndex, 4u);
  EXPECT_EQ(r.rightIndex, CompareResult::npos);
  EXPECT_NE(r.report.find("rs274 ended, gcx has 1 more event(s)"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("line 6"), std::string::npos) << r.report;
  r = compareEvents(b, sample());
  EXPECT_NE(r.report.find("gcx ended, rs274 has 1 more event(s)"), std::string::npos) << r.report;
}

motion::Extra angles(double a, double b = 0, double c = 0) {
  motion::Extra x = motion::Extra::Zero();
  x.head<3>() = Vec3(a, b, c);
  return x;
}

Event turning(Event e, const motion::Extra& from, const motion::Extra& to) {
  e.extraStart = from;
  e.extraEnd = to;
  return e;
}

TEST(Compare, ExtraAxesWithinTolerance) {
  const std::vector<Event> a = {
      turning(move(Kind::Feed, {0, 0, 0}, {0, 0, 0}, 1), angles(0), angles(90)), // rotary only
      turning(move(Kind::Feed, {0, 0, 0}, {10, 0, 0}, 2), angles(90), angles(90, 0, 45)),
  };
  std::vector<Event> b = a;
  b[0].extraEnd[0] += 0.00005;
  b[1].extraStart[0] += 0.00005;
  EXPECT_TRUE(compareEvents(a, b).equivalent);
  b[1].extraEnd[2] += 0.001;
  CompareResult r = compareEvents(a, b);
  EXPECT_FALSE(r.equivalent);
  EXPECT_EQ(r.leftIndex, 1u);
  EXPECT_NE(r.report.find("C at the end differs by 0.001000 deg (tolerance 0.0001)"),
            std::string::npos)
      << r.report;
  EXPECT_NE(r.report.find("C 0.0000 -> 45.0000"), std::string::npos) << r.report;

  // a move of W alone is not zero-length, and U V W are compared in mm
  std::vector<Event> w = {move(Kind::Feed, {0, 0, 0}, {0, 0, 0}, 1)};
  w[0].extraEnd[5] = 5;
  r = compareEvents(w, {});
  EXPECT_FALSE(r.equivalent);
  std::vector<Event> w2 = w;
  w2[0].extraEnd[5] = 4;
  r = compareEvents(w, w2);
  EXPECT_NE(r.report.find("W at the end differs by 1.000000 mm"), std::string::npos) << r.report;
}

TEST(Compare, CollinearMergingIncludesTheExtraAxes) {
  const std::vector<Event> one = {
      turning(move(Kind::Feed, {0, 0, 0}, {10, 0, 0}, 1), angles(0), angles(90))};
  // A turning linearly along the line: one move
  const std::vector<Event> linear = {
      turning(move(Kind::Feed, {0, 0, 0}, {4, 0, 0}, 1), angles(0), angles(36)),
      turning(move(Kind::Feed, {4, 0, 0}, {10, 0, 0}, 1), angles(36), angles(90))};
  EXPECT_TRUE(compareEvents(one, linear).equivalent);
  EXPECT_TRUE(compareEvents(linear, one).equivalent);
  // A turning first and X moving afterwards is not the same move
  const std::vector<Event> stepped = {
      turning(move(Kind::Feed, {0, 0, 0}, {0, 0, 0}, 1), angles(0), angles(90)),
      turning(move(Kind::Feed, {0, 0, 0}, {10, 0, 0}, 1), angles(90), angles(90))};
  EXPECT_FALSE(compareEvents(one, stepped).equivalent);
}

TEST(Compare, ModalChangesOnlyWhenAsked) {
  Event zx = other(Kind::PlaneChange, 0, 1);
  zx.plane = Plane::ZX;
  Event uv = other(Kind::PlaneChange, 0, 1);
  uv.text = "UV";
  std::vector<Event> a = sample(), b = sample();
  a.insert(a.begin(), {zx, other(Kind::UnitsChange, 20, 1), other(Kind::FeedModeChange, 95, 1)});
  EXPECT_TRUE(compareEvents(a, b).equivalent);

  CompareOptions modal;
  modal.kinds = {Kind::PlaneChange, Kind::UnitsChange, Kind::FeedModeChange};
  b = {zx, other(Kind::UnitsChange, 20, 1), other(Kind::FeedModeChange, 95, 1)};
  EXPECT_TRUE(compareEvents(a, b, modal).equivalent);
  b[0] = uv;
  CompareResult r = compareEvents(a, b, modal);
  EXPECT_NE(r.report.find("planes differ"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("PlaneChange G18"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("PlaneChange G17 UV"), std::string::npos) << r.report;
  b = {zx, other(Kind::UnitsChange, 21, 1), other(Kind::FeedModeChange, 95, 1)};
  r = compareEvents(a, b, modal);
  EXPECT_NE(r.report.find("codes differ"), std::string::npos) << r.report;
  EXPECT_NE(r.report.find("UnitsChange G21"), std::string::npos) << r.report;
  EXPECT_EQ(motion::describeEvent(other(Kind::FeedModeChange, 94, 1)), "FeedModeChange G94");
}

} // namespace
} // namespace gcx::oracle
