// NCT G71.7/G70.7 (cycles.md §4.7, §4.8, §4.11) against LinuxCNC's G71/G70 on three profiles
// (tests/differential/lathe/README.md): each profile is an NCT program (.nct, run by gcx's
// expansion pass and interpreter) and a hand-written LinuxCNC translation (.ngc, run by rs274).
//  * G70.7 finishing and LinuxCNC's G70 coincide: the finishing part of both runs is identical
//    within 1e-4 mm (feeds included) once the .ngc spells out §4.11's return to the start point
//    with an explicit `G0` after its G70;
//  * G71.7 roughing and LinuxCNC's G71 differ (docs/nct-vs-linuxcnc.md, "Turning cycles"): the
//    comparer's exact first divergence is asserted for each difference, and what both sides share
//    (the cut end of every common level, the region they never cut into) is asserted on both.
// The .ngc files also spell out the returns to the start point of §4.8 step 6 after the G71.
//
// How the streams are cut: gcx labels every roughing event with the line of the G71.7 P/Q block
// and the finishing events with the contour lines and the G70.7 line. rs274 labels the first
// canonical call of a G7x block with the block's line and the others with the line of the
// sub's `endsub` (measured, 2.9.0~pre1), so its G71 part runs from the first event of the G71
// line to the first event of the explicit return after it, and its G70 part from the first event
// of the G70 line to the first event of the line after the G70 (or after the explicit return).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "motion/describe.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using motion::Event;
using motion::Kind;

fs::path latheDir() {
  return sourceDir() / "tests" / "differential" / "lathe";
}

/// Source lines (1-based) that cut both event streams; see the file comment.
struct Lines {
  std::uint32_t roughing;      // .nct: the G71.7 P/Q block (every roughing event)
  std::uint32_t afterG70;      // .nct: the block after G70.7
  std::uint32_t g71;           // .ngc: the G71 block
  std::uint32_t returnAfter71; // .ngc: the explicit G0 to the start point after G71 (§4.8 step 6)
  std::uint32_t g70;           // .ngc: the G70 block
  std::uint32_t returnAfter70; // .ngc: the explicit G0 to the start point after G70 (§4.11)
  std::uint32_t afterReturn;   // .ngc: the block after that
};

/// A profile: its files (tests/differential/lathe/<name>.nct and .ngc), lines and side.
struct Profile {
  std::string name;
  Lines lines;
  bool inside; // ID: the material is outside the contour (larger radius)
};

const Profile kShaft{"l01_shaft_taper", {5, 12, 11, 12, 14, 15, 16}, false};
const Profile kArc{"l02_convex_arc", {5, 13, 12, 13, 15, 16, 17}, false};
const Profile kBore{"l03_bore_id", {5, 12, 11, 12, 14, 15, 16}, true};

struct Both {
  std::vector<Event> ours;
  std::vector<Event> theirs;
};

Both runBoth(const Profile& p) {
  Both b;
  const MacroRun run =
      runMacro({{"O0001.nct", readFile(latheDir() / (p.name + ".nct"))}}, "O0001.nct");
  EXPECT_TRUE(run.errors.empty()) << run.rendered;
  b.ours = run.events;
  const std::string ngc = readFile(latheDir() / (p.name + ".ngc"));
  const oracle::Rs274Result raw = oracle::Rs274().run(ngc);
  EXPECT_TRUE(raw.ok()) << raw.summary();
  oracle::CanonOptions copt;
  copt.programText = ngc;
  b.theirs = oracle::parseCanon(raw.canonLines, copt);
  return b;
}

bool isMotion(const Event& e) {
  return e.kind == Kind::Rapid || e.kind == Kind::Feed || e.kind == Kind::Arc;
}

std::size_t firstOf(const std::vector<Event>& ev, std::uint32_t line, std::size_t from = 0) {
  for (std::size_t i = from; i < ev.size(); ++i)
    if (isMotion(ev[i]) && ev[i].from.at.line == line) return i;
  ADD_FAILURE() << "no motion from line " << line;
  return ev.size();
}

std::size_t lastOf(const std::vector<Event>& ev, std::uint32_t line) {
  for (std::size_t i = ev.size(); i-- > 0;)
    if (isMotion(ev[i]) && ev[i].from.at.line == line) return i;
  ADD_FAILURE() << "no motion from line " << line;
  return 0;
}

/// The motion events of ev[begin, end).
std::vector<Event> range(const std::vector<Event>& ev, std::size_t begin, std::size_t end) {
  std::vector<Event> out;
  for (std::size_t i = begin; i < end && i < ev.size(); ++i)
    if (isMotion(ev[i])) out.push_back(ev[i]);
  return out;
}

struct Parts {
  std::vector<Event> gcxRoughing, gcxFinishing;
  std::vector<Event> rsRoughing, rsFinishing, rsFinishingAndReturn;
};

Parts parts(const Both& b, const Lines& l) {
  Parts p;
  const std::size_t roughBegin = firstOf(b.ours, l.roughing);
  const std::size_t roughEnd = lastOf(b.ours, l.roughing) + 1;
  p.gcxRoughing = range(b.ours, roughBegin, roughEnd);
  p.gcxFinishing = range(b.ours, roughEnd, firstOf(b.ours, l.afterG70, roughEnd));
  const std::size_t g71 = firstOf(b.theirs, l.g71);
  const std::size_t g70 = firstOf(b.theirs, l.g70, g71);
  const std::size_t ret = firstOf(b.theirs, l.returnAfter70, g70);
  p.rsRoughing = range(b.theirs, g71, firstOf(b.theirs, l.returnAfter71, g71));
  p.rsFinishing = range(b.theirs, g70, ret);
  p.rsFinishingAndReturn = range(b.theirs, g70, firstOf(b.theirs, l.afterReturn, ret));
  return p;
}

std::string dump(const std::vector<Event>& ev) {
  std::string s;
  for (const Event& e : ev)
    s += fmt::format("  line {}: {}\n", e.from.at.line, motion::describeEvent(e));
  return s;
}

/// The level cuts of a roughing: feeds along Z at constant X followed by a rapid (the retract),
/// as "x -> z" (4 decimals).
std::vector<std::string> levelCuts(const std::vector<Event>& roughing) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < roughing.size(); ++i) {
    const Event& e = roughing[i];
    if (e.kind == Kind::Feed && std::abs(e.start.x() - e.end.x()) < 1e-9 &&
        std::abs(e.start.z() - e.end.z()) > 1e-9 && roughing[i + 1].kind == Kind::Rapid)
      out.push_back(fmt::format("{} -> {}", n4(e.start.x()), n4(e.end.z())));
  }
  return out;
}

/// The events from the first feed that starts at (x, z) on.
std::vector<Event> fromFeedAt(const std::vector<Event>& ev, double x, double z) {
  for (std::size_t i = 0; i < ev.size(); ++i)
    if (ev[i].kind == Kind::Feed && std::abs(ev[i].start.x() - x) < 1e-4 &&
        std::abs(ev[i].start.z() - z) < 1e-4)
      return {ev.begin() + static_cast<std::ptrdiff_t>(i), ev.end()};
  ADD_FAILURE() << "no feed from x " << x << " z " << z;
  return {};
}

/// The comparer's report on both roughings from the first feed that starts at (x, z) on.
std::string roughingFrom(const Profile& prof, double x, double z) {
  const Both b = runBoth(prof);
  const Parts p = parts(b, prof.lines);
  return oracle::compareEvents(fromFeedAt(p.gcxRoughing, x, z), fromFeedAt(p.rsRoughing, x, z))
      .report;
}

// --- region checks ---------------------------------------------------------------------------

/// A point in the turning plane: x radius, z.
struct XZ {
  double x, z;
};

/// Points along a feed or arc (its end points included).
std::vector<XZ> samples(const Event& e) {
  std::vector<XZ> out;
  constexpr int kN = 200;
  if (e.kind == Kind::Feed) {
    for (int i = 0; i <= kN; ++i) {
      const double t = double(i) / kN;
      out.push_back({e.start.x() + t * (e.end.x() - e.start.x()),
                     e.start.z() + t * (e.end.z() - e.start.z())});
    }
  } else if (e.kind == Kind::Arc) { // G18: angles in the (z, x) frame, CCW seen from +Y
    const double cz = e.center.z(), cx = e.center.x();
    const double a0 = std::atan2(e.start.x() - cx, e.start.z() - cz);
    double sweep = std::atan2(e.end.x() - cx, e.end.z() - cz) - a0;
    constexpr double kTwoPi = 6.283185307179586;
    if (!e.clockwise && sweep <= 0) sweep += kTwoPi;
    if (e.clockwise && sweep >= 0) sweep -= kTwoPi;
    for (int i = 0; i <= kN; ++i) {
      const double a = a0 + sweep * i / kN;
      const double r = e.startRadius + (e.endRadius - e.startRadius) * i / kN;
      out.push_back({cx + r * std::sin(a), cz + r * std::cos(a)});
    }
  }
  return out;
}

/// The contour (x radius, z) densely as a polyline: the finishing run's feeds and arcs.
std::vector<XZ> polyline(const std::vector<Event>& finishing, double dx = 0, double dz = 0) {
  std::vector<XZ> out;
  for (const Event& e : finishing)
    for (const XZ& p : samples(e))
      out.push_back({p.x + dx, p.z + dz});
  return out;
}

double distance(const XZ& p, const std::vector<XZ>& poly) {
  double best = 1e300;
  for (std::size_t i = 1; i < poly.size(); ++i) {
    const XZ a = poly[i - 1], b = poly[i];
    const double vx = b.x - a.x, vz = b.z - a.z, len2 = vx * vx + vz * vz;
    double t = len2 > 0 ? ((p.x - a.x) * vx + (p.z - a.z) * vz) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - (a.x + t * vx), p.z - (a.z + t * vz)));
  }
  return best;
}

/// How far p lies inside the material bounded by the contour (OD: below it, ID: above it) at
/// p's z; <= 0 when it does not, or when z is outside the contour's span.
double depthInside(const XZ& p, const std::vector<XZ>& poly, bool inside) {
  double depth = -1e300;
  for (std::size_t i = 1; i < poly.size(); ++i) {
    const XZ a = poly[i - 1], b = poly[i];
    // a face (constant z) bounds nothing at its own z: the neighbours give the surface there
    if (std::abs(b.z - a.z) < 1e-12) continue;
    if (p.z < std::min(a.z, b.z) - 1e-12 || p.z > std::max(a.z, b.z) + 1e-12) continue;
    const double xs = a.x + (p.z - a.z) / (b.z - a.z) * (b.x - a.x);
    depth = std::max(depth, inside ? p.x - xs : xs - p.x);
  }
  return depth;
}

/// The deepest cut of the feeds and arcs of a run into the material behind `poly`.
double deepestCut(const std::vector<Event>& run, const std::vector<XZ>& poly, bool inside) {
  double worst = -1e300;
  for (const Event& e : run)
    for (const XZ& p : samples(e))
      worst = std::max(worst, depthInside(p, poly, inside));
  return worst;
}

/// The smallest distance of the feeds and arcs of a run from `poly`.
double closest(const std::vector<Event>& run, const std::vector<XZ>& poly) {
  double best = 1e300;
  for (const Event& e : run)
    for (const XZ& p : samples(e))
      best = std::min(best, distance(p, poly));
  return best;
}

/// "x [lo, hi] z [lo, hi]" of the feeds and arcs' sample points.
std::string feedBox(const std::vector<Event>& run) {
  double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (const Event& e : run)
    for (const XZ& p : samples(e)) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
    }
  return fmt::format("x [{}, {}] z [{}, {}]", n4(x0), n4(x1), n4(z0), n4(z1));
}

std::string endOf(const std::vector<Event>& run) {
  if (run.empty()) return "empty";
  return fmt::format("x {} z {}", n4(run.back().end.x()), n4(run.back().end.z()));
}

#define SKIP_WITHOUT_RS274()                                                                       \
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed"

// ---------------------------------------------------------------------------------------------
// §4.11 / §4.7: G70.7 runs the contour blocks with their own F, from the start point; LinuxCNC's
// G70 (one pass, D0) rapids to the start point, rapids to the sub's first point and feeds along
// the rest at the modal F (set to the contour's F before the G70). With §4.11's return to the
// start point spelt out as a G0 after the G70, the two are identical, arcs included.

void expectFinishingIdentical(const Profile& prof, std::size_t events) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(prof);
  const Parts p = parts(b, prof.lines);
  const oracle::CompareResult c = oracle::compareEvents(p.gcxFinishing, p.rsFinishingAndReturn);
  EXPECT_TRUE(c.equivalent) << c.report << "\ngcx:\n"
                            << dump(p.gcxFinishing) << "rs274:\n"
                            << dump(p.rsFinishingAndReturn);
  EXPECT_EQ(c.matched, events);
}

TEST(LatheDifferential, CyclesSpec_4_11_G70FinishingIdentical_ShaftWithTaper) {
  expectFinishingIdentical(kShaft, 6);
}

TEST(LatheDifferential, CyclesSpec_4_11_G70FinishingIdentical_ConvexArc) {
  expectFinishingIdentical(kArc, 7);
}

TEST(LatheDifferential, CyclesSpec_4_11_G70FinishingIdentical_Bore) {
  expectFinishingIdentical(kBore, 6);
}

// §4.11: "Then RAPID back to the start point of the G70.7 block". LinuxCNC's G70 stays at the
// end of the contour: without the explicit G0 the comparison ends one event early.
TEST(LatheDifferential, CyclesSpec_4_11_G70ReturnsToTheStartPoint_LinuxCncStaysAtTheEnd) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(kShaft);
  const Parts p = parts(b, kShaft.lines);
  const oracle::CompareResult c = oracle::compareEvents(p.gcxFinishing, p.rsFinishing);
  EXPECT_EQ(c.report,
            "first divergence after 5 matching events: rs274 ended, gcx has 1 more event(s):\n"
            "  gcx    #5 line 11:\n"
            "           Rapid (30.0000, 0.0000, -40.0000) -> (31.0000, 0.0000, 2.0000)");
}

// ---------------------------------------------------------------------------------------------
// §4.8 G71.7 against LinuxCNC's G71 (I = Δd, R = e, D0 = no allowance except on l02).

// §4.8 step 3: the levels are x_A - k·Δd for k >= 1. LinuxCNC's first level is the start X itself
// (k = 0), cut along the contour extended to the start X: the whole programs part at the first
// roughing move.
void expectFirstDivergence(const Profile& prof, const std::string& report) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(prof);
  const oracle::CompareResult c = oracle::compareEvents(b.ours, b.theirs);
  EXPECT_EQ(c.report, report);
}

TEST(LatheDifferential, CyclesSpec_4_8_3_FirstLevel_ShaftWithTaper) {
  expectFirstDivergence(
      kShaft, "first divergence after 1 matching events: different kinds: Rapid vs Feed\n"
              "  gcx    #4 line 5 (in G71.7 pass 1 from line 5):\n"
              "           Rapid (31.0000, 0.0000, 2.0000) -> (29.0000, 0.0000, 2.0000)\n"
              "  rs274  #5 line 10:\n"
              "           Feed (31.0000, 0.0000, 2.0000) -> (31.0000, 0.0000, -40.0000) F0.25/rev");
}
TEST(LatheDifferential, CyclesSpec_4_8_3_FirstLevel_ConvexArc) {
  expectFirstDivergence(
      kArc, "first divergence after 1 matching events: different kinds: Rapid vs Feed\n"
            "  gcx    #4 line 5 (in G71.7 pass 1 from line 5):\n"
            "           Rapid (31.0000, 0.0000, 2.0000) -> (28.0000, 0.0000, 2.0000)\n"
            "  rs274  #5 line 11:\n"
            "           Feed (31.0000, 0.0000, 2.0000) -> (31.0000, 0.0000, -34.8000) F0.25/rev");
}
TEST(LatheDifferential, CyclesSpec_4_8_3_FirstLevel_Bore) {
  expectFirstDivergence(
      kBore, "first divergence after 1 matching events: different kinds: Rapid vs Feed\n"
             "  gcx    #4 line 5 (in G71.7 pass 1 from line 5):\n"
             "           Rapid (8.0000, 0.0000, 2.0000) -> (10.0000, 0.0000, 2.0000)\n"
             "  rs274  #5 line 10:\n"
             "           Feed (8.0000, 0.0000, 2.0000) -> (8.0000, 0.0000, -40.0000) F0.2/rev");
}

// §4.8 steps 3-4.2: where both have a level, both cut to the first crossing with the contour
// (without an allowance, l01 and l03: the same end; l02: gcx's contour is shifted by Δu/2, Δw,
// LinuxCNC's offset by D along the normal, so the ends differ slightly).
struct Cuts {
  std::vector<std::string> gcx, rs274;
};
void expectLevelCuts(const Profile& prof, const Cuts& want) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(prof);
  const Parts p = parts(b, prof.lines);
  EXPECT_EQ(levelCuts(p.gcxRoughing), want.gcx);
  EXPECT_EQ(levelCuts(p.rsRoughing), want.rs274);
}

TEST(LatheDifferential, CyclesSpec_4_8_4_LevelCuts_ShaftWithTaper) {
  const std::vector<std::string> common = {
      "29 -> -40", "27 -> -40",      "25 -> -40",      "23 -> -40", "21 -> -40",
      "19 -> -40", "17 -> -24.3333", "15 -> -21.6667", "13 -> -19", "11 -> -16.3333"};
  std::vector<std::string> linuxcnc = {"31 -> -40"}; // its level at the start X
  linuxcnc.insert(linuxcnc.end(), common.begin(), common.end());
  expectLevelCuts(kShaft, {common, linuxcnc});
}
TEST(LatheDifferential, CyclesSpec_4_8_4_LevelCuts_ConvexArc) {
  expectLevelCuts(kArc, {{"28 -> -34.9", "25 -> -34.7", "22 -> -31.7", "19 -> -15.1503",
                          "16 -> -11.7538", "13 -> -10.3"},
                         {"31 -> -34.8", "28 -> -34.8", "25 -> -34.7172", "22 -> -31.7172",
                          "19 -> -15.2", "16 -> -11.7514", "13 -> -10.2512"}});
}
TEST(LatheDifferential, CyclesSpec_4_8_4_LevelCuts_Bore) {
  const std::vector<std::string> common = {"10 -> -40", "12 -> -40", "14 -> -40", "16 -> -23",
                                           "18 -> -19"};
  std::vector<std::string> linuxcnc = {"8 -> -40"};
  linuxcnc.insert(linuxcnc.end(), common.begin(), common.end());
  expectLevelCuts(kBore, {common, linuxcnc});
}

// §4.8 steps 4.3-4.4: RAPID 45° retract by e, then RAPID along Z back to z_A at x_k + e; the next
// level is approached from there. LinuxCNC makes the same 45° retract, but returns to z_A - e and
// then rapids diagonally down to (x_k, z_A) before the next level. Compared from the cut at
// level 29 (gcx's first, LinuxCNC's second).
TEST(LatheDifferential, CyclesSpec_4_8_4_RetractAndReturn_ShaftWithTaper) {
  SKIP_WITHOUT_RS274();
  EXPECT_EQ(roughingFrom(kShaft, 29, 2),
            "first divergence after 2 matching events: end points differ by 0.500000 mm "
            "(tolerance 0.0001)\n"
            "  gcx    #2 line 5 (in G71.7 pass 1 from line 5):\n"
            "           Rapid (29.5000, 0.0000, -39.5000) -> (29.5000, 0.0000, 2.0000)\n"
            "  rs274  #2 line 10:\n"
            "           Rapid (29.5000, 0.0000, -39.5000) -> (29.5000, 0.0000, 1.5000)");
}

// §4.8 steps 5-6: the final pass runs along the (shifted) contour from A'' and ends with a RAPID
// to A. LinuxCNC's final pass also follows its (offset) contour, but extends it with a feed to the
// start X and stays there (no return to the start point).
TEST(LatheDifferential, CyclesSpec_4_8_5_FinalPass_ShaftWithTaper) {
  SKIP_WITHOUT_RS274();
  EXPECT_EQ(roughingFrom(kShaft, 10, 2),
            "first divergence after 3 matching events: end points differ by 1.000000 mm "
            "(tolerance 0.0001)\n"
            "  gcx    #3 line 5 (in G71.7 pass 11 from line 5):\n"
            "           Feed (17.5000, 0.0000, -40.0000) -> (30.0000, 0.0000, -40.0000) F0.25/rev\n"
            "  rs274  #3 line 10:\n"
            "           Feed (17.5000, 0.0000, -40.0000) -> (31.0000, 0.0000, -40.0000) F0.25/rev "
            "[2 collinear pieces, events #3..#4]");
}

TEST(LatheDifferential, CyclesSpec_4_8_5_FinalPass_Bore) {
  SKIP_WITHOUT_RS274();
  EXPECT_EQ(roughingFrom(kBore, 20, 2),
            "first divergence after 3 matching events: end points differ by 2.000000 mm "
            "(tolerance 0.0001)\n"
            "  gcx    #3 line 5 (in G71.7 pass 6 from line 5):\n"
            "           Feed (15.0000, 0.0000, -40.0000) -> (10.0000, 0.0000, -40.0000) F0.2/rev\n"
            "  rs274  #3 line 10:\n"
            "           Feed (15.0000, 0.0000, -40.0000) -> (8.0000, 0.0000, -40.0000) F0.2/rev "
            "[2 collinear pieces, events #3..#4]");
}

// §4.8 step 1, Q-11: U0.4 W0.1 shift the contour by (+0.2 radius, +0.1); LinuxCNC's D0.2 offsets
// it by 0.2 along its normal (the convex arc grows to r 10.2 about the same centre; the Z faces
// move by 0.2, not 0.1). The final passes part at the approach to A''.
TEST(LatheDifferential, CyclesSpec_4_8_1_AllowanceShiftVersusNormalOffset_ConvexArc) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(kArc);
  const Parts p = parts(b, kArc.lines);
  // from the last level's return on: gcx at (14, 2), LinuxCNC at (13, 2)
  const std::vector<Event> gcxFinal(p.gcxRoughing.end() - 7, p.gcxRoughing.end());
  const std::vector<Event> rsFinal(p.rsRoughing.end() - 7, p.rsRoughing.end());
  EXPECT_EQ(dump(gcxFinal),
            "  line 5: Rapid (14.0000, 0.0000, 2.0000) -> (10.2000, 0.0000, 2.1000)\n"
            "  line 5: Feed (10.2000, 0.0000, 2.1000) -> (10.2000, 0.0000, -9.9000) F0.25/rev\n"
            "  line 5: Arc G18 CCW (10.2000, 0.0000, -9.9000) -> (20.2000, 0.0000, -19.9000) "
            "centre (10.2000, 0.0000, -19.9000) r 10.0000 F0.25/rev\n"
            "  line 5: Feed (20.2000, 0.0000, -19.9000) -> (20.2000, 0.0000, -29.9000) F0.25/rev\n"
            "  line 5: Feed (20.2000, 0.0000, -29.9000) -> (25.2000, 0.0000, -34.9000) F0.25/rev\n"
            "  line 5: Feed (25.2000, 0.0000, -34.9000) -> (30.2000, 0.0000, -34.9000) F0.25/rev\n"
            "  line 5: Rapid (30.2000, 0.0000, -34.9000) -> (31.0000, 0.0000, 2.0000)\n");
  EXPECT_EQ(
      dump(rsFinal),
      "  line 11: Rapid (13.0000, 0.0000, 2.0000) -> (10.2000, 0.0000, 2.0000)\n"
      "  line 11: Feed (10.2000, 0.0000, 2.0000) -> (10.2000, 0.0000, -9.8020) F0.25/rev\n"
      "  line 11: Arc G18 CCW (10.2000, 0.0000, -9.8020) -> (20.2000, 0.0000, -20.0000) "
      "centre (10.0000, 0.0000, -20.0000) r 10.2000 F0.25/rev\n"
      "  line 11: Feed (20.2000, 0.0000, -20.0000) -> (20.2000, 0.0000, -29.9172) F0.25/rev\n"
      "  line 11: Feed (20.2000, 0.0000, -29.9172) -> (25.0828, 0.0000, -34.8000) F0.25/rev\n"
      "  line 11: Feed (25.0828, 0.0000, -34.8000) -> (30.0000, 0.0000, -34.8000) F0.25/rev\n"
      "  line 11: Feed (30.0000, 0.0000, -34.8000) -> (31.0000, 0.0000, -34.8000) F0.25/rev\n");
  // the comparer, from the first feed of the final passes on: they part at once
  const oracle::CompareResult c = oracle::compareEvents({gcxFinal.begin() + 1, gcxFinal.end()},
                                                        {rsFinal.begin() + 1, rsFinal.end()});
  EXPECT_EQ(c.report,
            "first divergence after 0 matching events: start points differ by 0.100000 mm "
            "(tolerance 0.0001)\n"
            "  gcx    #0 line 5 (in G71.7 pass 7 from line 5):\n"
            "           Feed (10.2000, 0.0000, 2.1000) -> (10.2000, 0.0000, -9.9000) F0.25/rev\n"
            "  rs274  #0 line 11:\n"
            "           Feed (10.2000, 0.0000, 2.0000) -> (10.2000, 0.0000, -9.8020) F0.25/rev");
}

// What must hold on both sides: the roughing never cuts into the finished part (nor, for gcx,
// into the contour shifted by the allowance; for LinuxCNC, nearer to the contour than D), the
// feeds span the same Z range; gcx ends at A, LinuxCNC at the end of its extended final pass.
struct Region {
  double gcxDeepest, rsDeepest; // deepest cut into the finished part (<= 0: none)
  std::string gcxBox, rsBox;    // feed bounding boxes
  std::string gcxEnd, rsEnd;    // where the roughing ends
};
void expectRegion(const Profile& prof, double du, double dw, double d, const Region& want) {
  SKIP_WITHOUT_RS274();
  const Both b = runBoth(prof);
  const Parts p = parts(b, prof.lines);
  const std::vector<XZ> part = polyline(p.gcxFinishing);
  const double gcxDeepest = deepestCut(p.gcxRoughing, part, prof.inside);
  const double rsDeepest = deepestCut(p.rsRoughing, part, prof.inside);
  EXPECT_NEAR(gcxDeepest, want.gcxDeepest, 1e-4);
  EXPECT_NEAR(rsDeepest, want.rsDeepest, 1e-4);
  // gcx: outside the contour shifted by (Δu/2, Δw)
  EXPECT_LE(deepestCut(p.gcxRoughing, polyline(p.gcxFinishing, du / 2, dw), prof.inside), 1e-4);
  // LinuxCNC: never nearer to the contour than D
  EXPECT_GE(closest(p.rsRoughing, part), d - 1e-4);
  EXPECT_EQ(feedBox(p.gcxRoughing), want.gcxBox);
  EXPECT_EQ(feedBox(p.rsRoughing), want.rsBox);
  EXPECT_EQ(endOf(p.gcxRoughing), want.gcxEnd);
  EXPECT_EQ(endOf(p.rsRoughing), want.rsEnd);
}

TEST(LatheDifferential, CyclesSpec_4_8_RoughingRegion_ShaftWithTaper) {
  expectRegion(kShaft, 0, 0, 0,
               {0, 0, "x [10, 30] z [-40, 2]", "x [10, 31] z [-40, 2]", "x 31 z 2", "x 31 z -40"});
}
TEST(LatheDifferential, CyclesSpec_4_8_RoughingRegion_ConvexArc) {
  expectRegion(kArc, 0.4, 0.1, 0.2,
               {-0.2, -0.2, "x [10.2, 30.2] z [-34.9, 2.1]", "x [10.2, 31] z [-34.8, 2]",
                "x 31 z 2", "x 31 z -34.8"});
}
TEST(LatheDifferential, CyclesSpec_4_8_RoughingRegion_Bore) {
  expectRegion(kBore, 0, 0, 0,
               {0, 0, "x [10, 20] z [-40, 2]", "x [8, 20] z [-40, 2]", "x 8 z 2", "x 8 z -40"});
}

} // namespace
} // namespace gcx::test
