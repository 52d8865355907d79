// The streaming comparison on synthetic event streams (docs/equivalence.md): segmentation,
// state, events, rapids and the tolerance boundary, each with its exact report.
#include <gtest/gtest.h>

#include <cmath>

#include "equiv/walker.h"
#include "motion/interpolator.h"

namespace gcx::equiv {
namespace {

using motion::Event;
using motion::Kind;

/// Builds a stream like a program: each call continues from the last end point; line numbers
/// count up from 1 so reports can be checked.
struct Stream {
  std::vector<Event> ev;
  Vec3 pos = Vec3::Zero();
  std::uint32_t line = 0;

  Event base(Kind k) {
    Event e;
    e.kind = k;
    e.from.at = SourceLoc{0, ++line, 1};
    return e;
  }
  Stream& rapid(double x, double y, double z) {
    Event e = base(Kind::Rapid);
    e.start = pos;
    e.end = pos = Vec3(x, y, z);
    ev.push_back(e);
    return *this;
  }
  Stream& feed(double x, double y, double z, double f = 100) {
    Event e = base(Kind::Feed);
    e.start = pos;
    e.end = pos = Vec3(x, y, z);
    e.extraStart = e.extraEnd = extra;
    e.feed = f;
    ev.push_back(e);
    return *this;
  }
  /// A feed line that also turns the A axis to a (degrees).
  Stream& feedA(double x, double y, double z, double a) {
    feed(x, y, z);
    ev.back().extraEnd[0] = extra[0] = a;
    return *this;
  }
  motion::Extra extra = motion::Extra::Zero();
  /// An XY arc about (cx, cy) at the current height.
  Stream& arc(double x, double y, double cx, double cy, bool cw, double f = 100, int turns = 0) {
    Event e = base(Kind::Arc);
    e.start = pos;
    e.end = pos = Vec3(x, y, pos.z());
    e.center = Vec3(cx, cy, e.start.z());
    e.clockwise = cw;
    e.turns = turns;
    e.startRadius = std::hypot(e.start.x() - cx, e.start.y() - cy);
    e.endRadius = std::hypot(x - cx, y - cy);
    e.feed = f;
    ev.push_back(e);
    return *this;
  }
  /// The last arc replaced by chords within tol (the interpolator gcx writes spirals with).
  Stream& asChords(double tol) {
    const Event a = ev.back();
    ev.pop_back();
    Vec3 from = a.start;
    for (const Vec3& p : motion::samplePoints(a, tol)) {
      if (p == a.start) continue;
      Event e = a;
      e.kind = Kind::Feed;
      e.start = from;
      e.end = from = p;
      ev.push_back(e);
    }
    return *this;
  }
  Stream& spindle(double s, int dir) {
    Event e = base(Kind::Spindle);
    e.value = s;
    e.direction = dir;
    ev.push_back(e);
    return *this;
  }
  Stream& coolant(int m) {
    Event e = base(Kind::Coolant);
    e.value = m;
    ev.push_back(e);
    return *this;
  }
  Stream& dwell(double s) {
    Event e = base(Kind::Dwell);
    e.value = s;
    ev.push_back(e);
    return *this;
  }
  Stream& tool(int t) {
    Event e = base(Kind::ToolChange);
    e.value = t;
    ev.push_back(e);
    return *this;
  }
  Stream& stop(bool optional) {
    Event e = base(Kind::Stop);
    e.optional = optional;
    ev.push_back(e);
    return *this;
  }
  Stream& skipLine() {
    ++line;
    return *this;
  }
};

EquivResult compare(const Stream& a, const Stream& b, WalkOptions o = {}) {
  ListSource sa(a.ev), sb(b.ev);
  return walk(sa, sb, o);
}

/// "geometry A:3 B:4 end point X differs by 0.500 mm"
std::string brief(const EquivResult& r) {
  if (r.equivalent) return "equivalent";
  const Divergence& d = *r.divergence;
  return std::string(kindName(d.kind)) +
         " A:" + (d.a.present ? std::to_string(d.a.event.from.at.line) : "-") +
         " B:" + (d.b.present ? std::to_string(d.b.event.from.at.line) : "-") + " " + d.summary;
}

// --- segmentation -----------------------------------------------------------------------------

TEST(EquivSegmentation, LineSplitIntoCollinearPieces) {
  Stream a, b;
  a.feed(10, 0, 0).feed(10, 10, 0);
  b.feed(2.5, 0, 0).feed(7, 0, 0).feed(10, 0, 0).feed(10, 4, 0).feed(10, 10, 0);
  const EquivResult r = compare(a, b);
  EXPECT_EQ(brief(r), "equivalent");
  EXPECT_EQ(r.a.segments, 2u);
  EXPECT_EQ(r.b.segments, 5u);
  EXPECT_DOUBLE_EQ(r.a.stats.feedLength, 20);
  EXPECT_DOUBLE_EQ(r.b.stats.feedLength, 20);
}

TEST(EquivSegmentation, ArcSplitIntoArcsOnTheSameCircle) {
  Stream a, b;
  a.feed(10, 0, 0).arc(-10, 0, 0, 0, false); // a half circle CCW
  b.feed(10, 0, 0).arc(0, 10, 0, 0, false).arc(-10, 0, 0, 0, false);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivSegmentation, FullCircleAgainstTwoHalves) {
  Stream a, b;
  a.feed(10, 0, 0).arc(10, 0, 0, 0, true);
  b.feed(10, 0, 0).arc(-10, 0, 0, 0, true).arc(10, 0, 0, 0, true);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivSegmentation, ArcAgainstChordsWithinTheTolerance) {
  Stream a, b;
  a.feed(10, 0, 0).arc(0, 10, 0, 0, false);
  b.feed(10, 0, 0).arc(0, 10, 0, 0, false).asChords(0.0005);
  const EquivResult r = compare(a, b);
  EXPECT_EQ(brief(r), "equivalent");
  EXPECT_GT(r.maxDeviation, 0.0004);
  EXPECT_LE(r.maxDeviation, 0.0005 + 1e-9);
}

TEST(EquivSegmentation, SpiralWithTurnsAgainstChords) {
  Stream a, b;
  a.feed(63, 40, -3).arc(41, 40, 60, 40, false, 800, 2); // r 3 -> 19, 2.5 turns
  b.feed(63, 40, -3).arc(41, 40, 60, 40, false, 800, 2).asChords(0.0005);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivSegmentation, ChordsCoarserThanTheToleranceDiffer) {
  Stream a, b;
  a.feed(10, 0, 0).arc(0, 10, 0, 0, false);
  b.feed(10, 0, 0).arc(0, 10, 0, 0, false).asChords(0.01);
  EXPECT_EQ(brief(compare(a, b)).substr(0, 31), "geometry A:2 B:2 path deviates ");
}

// The sagitta of the chord of a quarter circle of radius r is r(1 - cos 45°): the tolerance
// either side of it decides.
TEST(EquivTolerance, ChordOfAQuarterCircleAtTheBoundary) {
  Stream a, b;
  a.feed(10, 0, 0).arc(0, 10, 0, 0, false);
  b.feed(10, 0, 0).feed(0, 10, 0);
  const double sagitta = 10 * (1 - std::cos(M_PI / 4));
  WalkOptions o;
  o.tolerance = sagitta * 1.001;
  EXPECT_EQ(brief(compare(a, b, o)), "equivalent");
  o.tolerance = sagitta * 0.999;
  EXPECT_EQ(brief(compare(a, b, o)), "geometry A:2 B:2 path deviates by 2.9289 mm (tolerance "
                                     "2.926 mm)");
}

TEST(EquivTolerance, EndPointJustInsideAndOutside) {
  Stream a, b, c;
  a.feed(10, 0, 0).feed(10, 10, 0);
  b.feed(10.0009, 0, 0).feed(10, 10, 0);
  c.feed(10.0011, 0, 0).feed(10, 10, 0);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
  EXPECT_EQ(brief(compare(a, c)), "geometry A:1 B:1 end point X differs by 0.001 mm");
}

// --- where the paths part ----------------------------------------------------------------------

TEST(EquivGeometry, ShorterLineNamesItsOwnBlock) {
  Stream a, b;
  a.feed(12, 0, 0).feed(12, 10, 0);
  b.feed(10, 0, 0).feed(12, 10, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point X differs by 2.000 mm");
}

TEST(EquivGeometry, LongerLineNamesItsOwnBlock) {
  Stream a, b;
  a.feed(12, 0, 0).feed(12, 10, 0);
  b.feed(12.5, 0, 0).feed(12, 10, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point X differs by 0.500 mm");
}

TEST(EquivGeometry, ArcDirection) {
  Stream a, b;
  a.feed(10, 0, 0).arc(0, 10, 0, 0, false);
  b.feed(10, 0, 0).arc(0, 10, 0, 0, true);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:2 B:2 path deviates by 18.4776 mm (tolerance "
                                  "0.001 mm)");
}

TEST(EquivGeometry, OneSideEndsEarly) {
  Stream a, b;
  a.feed(10, 0, 0).feed(10, 10, 0);
  b.feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "ended A:2 B:1 B ended; A continues with Feed (10.0000, "
                                  "0.0000, 0.0000) -> (10.0000, 10.0000, 0.0000) F100");
}

TEST(EquivGeometry, ReversedLineIsNotTheSamePath) {
  Stream a, b;
  a.feed(10, 0, 0);
  b.feed(5, 0, 0).feed(0, 0, 0).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point X differs by 5.000 mm");
}

// --- rapids ---------------------------------------------------------------------------------

TEST(EquivRapids, RunComparedByItsEndPoint) {
  Stream a, b;
  a.rapid(10, 0, 0).rapid(10, 10, 5).feed(10, 10, 0);
  b.rapid(10, 10, 5).feed(10, 10, 0);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
  WalkOptions strict;
  strict.strictRapids = true;
  EXPECT_EQ(brief(compare(a, b, strict)).substr(0, 16), "geometry A:1 B:1");
}

TEST(EquivRapids, EndOfARunNamesTheBlockThatSetTheAxis) {
  Stream a, b;
  a.rapid(10, 0, 0).rapid(10, 0, 5).feed(10, 0, 0);
  b.rapid(11, 0, 0).rapid(11, 0, 5).feed(11, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 rapid end point X differs by 1.000 mm");
}

TEST(EquivRapids, RapidAgainstFeed) {
  Stream a, b;
  a.rapid(10, 0, 0).feed(10, 10, 0);
  b.feed(10, 0, 0).feed(10, 10, 0);
  EXPECT_EQ(brief(compare(a, b)), "state A:1 B:1 motion differs: rapid vs feed");
}

// --- state attached to segments -----------------------------------------------------------------

TEST(EquivState, OrderOfSpindleWordsDoesNotMatter) {
  Stream a, b;
  a.spindle(1000, 0).spindle(1000, 1).feed(10, 0, 0);
  b.spindle(0, 1).spindle(1000, 1).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivState, StopWhileStoppedDoesNotMatter) {
  Stream a, b;
  a.feed(10, 0, 0);
  b.spindle(0, 0).coolant(9).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivState, SpindleDirection) {
  Stream a, b;
  a.spindle(1000, 1).feed(10, 0, 0);
  b.spindle(1000, -1).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "state A:2 B:2 spindle differs: S1000 CW vs S1000 CCW");
}

TEST(EquivState, FeedDiffersOnTheSecondHalfOfASplitLine) {
  Stream a, b;
  a.feed(10, 0, 0, 100);
  b.feed(5, 0, 0, 100).feed(10, 0, 0, 200);
  EXPECT_EQ(brief(compare(a, b)), "state A:1 B:2 feed differs: 100 vs 200 mm/min");
}

TEST(EquivState, CoolantAfterTheMoveIsADifference) {
  Stream a, b;
  a.coolant(8).feed(10, 0, 0).feed(20, 0, 0);
  b.feed(10, 0, 0).coolant(8).feed(20, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "state A:2 B:1 coolant differs: flood vs off");
}

// --- discrete events ----------------------------------------------------------------------------

TEST(EquivEvents, DwellTimes) {
  Stream a, b;
  a.feed(10, 0, 0).dwell(1).feed(0, 0, 0);
  b.feed(10, 0, 0).dwell(2).feed(0, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "event A:2 B:2 dwell differs: Dwell 1 s vs Dwell 2 s");
}

TEST(EquivEvents, DroppedDwell) {
  Stream a, b;
  a.feed(10, 0, 0).dwell(1).feed(0, 0, 0);
  b.feed(10, 0, 0).skipLine().feed(0, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "event A:2 B:3 A has Dwell 1 s where B moves");
}

TEST(EquivEvents, DwellWhereTheOtherStillMoves) {
  Stream a, b;
  a.feed(10, 0, 0).dwell(1).feed(20, 0, 0);
  b.feed(20, 0, 0).dwell(1);
  EXPECT_EQ(brief(compare(a, b)),
            "geometry A:1 B:1 end point X differs by 10.000 mm (A has Dwell 1 s next)");
}

TEST(EquivEvents, ToolChangeAndStop) {
  Stream a, b, c;
  a.tool(1).feed(10, 0, 0).stop(false);
  b.tool(2).feed(10, 0, 0).stop(false);
  c.tool(1).feed(10, 0, 0).stop(true);
  EXPECT_EQ(brief(compare(a, b)), "event A:1 B:1 tool change differs: T1 vs T2");
  EXPECT_EQ(brief(compare(a, c)), "event A:3 B:3 stop differs: M0 vs M1");
}

// --- extra axes (docs/equivalence.md, "Extra axes") ----------------------------------------------

TEST(EquivExtraAxes, MoveOfTheExtraAxesAloneIsCompared) {
  Stream a, b;
  a.feedA(0, 0, 0, 90);
  b.feedA(0, 0, 0, 45);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point A differs by 45.000 deg; B ended");
}

TEST(EquivExtraAxes, RotaryMoveSplitIntoCollinearPiecesInAxisSpace) {
  Stream a, b;
  a.feedA(10, 0, 0, 90);
  b.feedA(4, 0, 0, 36).feedA(10, 0, 0, 90);
  EXPECT_EQ(brief(compare(a, b)), "equivalent");
}

TEST(EquivExtraAxes, TurningBeforeTheTravelIsNotTurningDuringIt) {
  Stream a, b;
  a.feedA(10, 0, 0, 90);
  b.feedA(0, 0, 0, 90).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point X differs by 10.000 mm");
}

TEST(EquivExtraAxes, TurningInTheFirstHalfIsNotTurningAlongTheWhole) {
  Stream a, b;
  a.feedA(10, 0, 0, 90);
  b.feedA(5, 0, 0, 90).feed(10, 0, 0);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point X differs by 5.000 mm");
}

TEST(EquivExtraAxes, SameEndInXYZDifferentTurn) {
  Stream a, b;
  a.feedA(10, 0, 0, 90);
  b.feedA(10, 0, 0, 45);
  EXPECT_EQ(brief(compare(a, b)), "geometry A:1 B:1 end point A differs by 45.000 deg");
}

// --- the summary up to the difference ----------------------------------------------------------

// Each side counts what came before the segment its report names: an identical prefix counts
// the same, although the side whose segment ended first has read on (here into a rapid run).
TEST(EquivSummary, IdenticalPrefixCountsTheSameOnBothSides) {
  Stream a, b;
  a.feed(10, 0, 0).feed(20, 0, 0).rapid(20, 10, 0).feed(0, 10, 0);
  b.feed(10, 0, 0).feed(21, 0, 0).rapid(21, 10, 0).feed(0, 10, 0);
  const EquivResult r = compare(a, b);
  EXPECT_EQ(brief(r), "geometry A:2 B:2 end point X differs by 1.000 mm");
  EXPECT_EQ(r.a.segments, 1u);
  EXPECT_EQ(r.b.segments, 1u);
  EXPECT_EQ(r.a.stats.feedLength, 10.0);
  EXPECT_EQ(r.b.stats.feedLength, 10.0);
  EXPECT_EQ(r.a.stats.rapidLength, 0.0);
  EXPECT_EQ(r.b.stats.rapidLength, 0.0);
}

} // namespace
} // namespace gcx::equiv
