// NCT turning cycles (cycles.md §4): the vectors TV-17 to TV-25 and the turning rows of TV-32,
// built as the interpreter will build the requests (turning.h), plus the rules of §4.2-§4.13
// the vectors do not reach: planes, arcs, the other quadrants, parameters and errors (§7).
#include <gtest/gtest.h>

#include "cycles/turning_harness.h"
#include "diag/codes.h"

namespace gcx::test {
namespace {

using cycles::TurningCycle;

// --- §8 vectors -----------------------------------------------------------------------------

// §4.8 G71.7, TV-17: four levels 27, 24, 21, 18 (radius), then the final pass along C'.
TEST(CyclesSpec_8_TV17, G71RoughingTableAndFinalPass) {
  EXPECT_EQ(contourCycle(60, 2, 0.3, {"G0 X30", "G1 Z-20 F0.15", "X50 Z-30", "Z-40", "X60"},
                         "G71.7 U3 R1", "G71.7 P50 Q90 U0.4 W0.1 F0.3"),
            "G0 X54 | G1 Z-39.9 F0.3 | G0 X56 Z-38.9 | G0 Z2 | "
            "G0 X48 | G1 Z-28.7 F0.3 | G0 X50 Z-27.7 | G0 Z2 | "
            "G0 X42 | G1 Z-25.7 F0.3 | G0 X44 Z-24.7 | G0 Z2 | "
            "G0 X36 | G1 Z-22.7 F0.3 | G0 X38 Z-21.7 | G0 Z2 | "
            "G0 X30.4 Z2.1 | G1 Z-19.9 F0.3 | G1 X50.4 Z-29.9 F0.3 | G1 Z-39.9 F0.3 | "
            "G1 X60.4 F0.3 | G0 X60 Z2");
}

// §4.11: after the interpreter re-ran N50-N90 (ending at X60 Z-40), G70.7 returns to its start.
TEST(CyclesSpec_8_TV17, G70ReturnsToItsStartPoint) {
  auto req = request(60, 2);
  req.end = cycles::Vec3(30, 0, -40);
  diag::Engine diags;
  const auto ops = cycles::expandTurning(req, {}, words("G70.7 P50 Q90"), diags);
  ASSERT_TRUE(ops);
  EXPECT_EQ(cycles::opsText(req.end, *ops, "XYZ", 1), "G0 Z2");
}

// §4.9 G72.7, TV-18: levels z = 0, -2, -4; cuts along -X to C'.
TEST(CyclesSpec_8_TV18, G72RoughingTableAndFinalPass) {
  EXPECT_EQ(contourCycle(62, 2, 0.25, {"G0 Z-6", "G1 X40 F0.1", "X20 Z-2", "Z2"}, "G72.7 W2 R0.5",
                         "G72.7 P50 Q80 U0.2 W0.1 F0.25"),
            "G0 Z0 | G1 X20.2 F0.25 | G0 X21.2 Z0.5 | G0 X62 | "
            "G0 Z-2 | G1 X20.7 F0.25 | G0 X21.7 Z-1.5 | G0 X62 | "
            "G0 Z-4 | G1 X30.7 F0.25 | G0 X31.7 Z-3.5 | G0 X62 | "
            "G0 X62.2 Z-5.9 | G1 X40.2 F0.25 | G1 X20.2 Z-1.9 F0.25 | G1 Z2.1 F0.25 | G0 X62 Z2");
}

// §4.10 G73.7, TV-19: offsets (8.4, 2.1), (4.4, 1.1), (0.4, 0.1) in diameter/Z.
TEST(CyclesSpec_8_TV19, G73ThreePassesWithFanucSpacing) {
  EXPECT_EQ(contourCycle(60, 5, 0.25, {"G0 X30 Z2", "G1 Z-15 F0.1", "X50 Z-25", "X60"},
                         "G73.7 U4 W2 R3", "G73.7 P50 Q80 U0.4 W0.1 F0.25"),
            "G0 X38.4 Z4.1 | G1 Z-12.9 F0.25 | G1 X58.4 Z-22.9 F0.25 | G1 X68.4 F0.25 | "
            "G0 X60 Z5 | "
            "G0 X34.4 Z3.1 | G1 Z-13.9 F0.25 | G1 X54.4 Z-23.9 F0.25 | G1 X64.4 F0.25 | "
            "G0 X60 Z5 | "
            "G0 X30.4 Z2.1 | G1 Z-14.9 F0.25 | G1 X50.4 Z-24.9 F0.25 | G1 X60.4 F0.25 | "
            "G0 X60 Z5");
}

// Q-15 as a dialect choice: without the final pass the roughing ends with a rapid to A from
// the last retract.
TEST(CyclesSpec_9_Q15, RoughingWithoutTheFinalPass) {
  CycleChoices noFinal;
  noFinal.roughingFinalPass = false;
  EXPECT_EQ(contourCycle(60, 2, 0.3, {"G0 X30", "G1 Z-20 F0.15", "X50 Z-30", "Z-40", "X60"},
                         "G71.7 U3 R1", "G71.7 P50 Q90 U0.4 W0.1 F0.3", noFinal),
            "G0 X54 | G1 Z-39.9 F0.3 | G0 X56 Z-38.9 | G0 Z2 | "
            "G0 X48 | G1 Z-28.7 F0.3 | G0 X50 Z-27.7 | G0 Z2 | "
            "G0 X42 | G1 Z-25.7 F0.3 | G0 X44 Z-24.7 | G0 Z2 | "
            "G0 X36 | G1 Z-22.7 F0.3 | G0 X38 Z-21.7 | G0 Z2 | G0 X60");
}

// Q-16 as a dialect choice: the textbook's step Δi/d (003:8930-8931). Offsets in diameter/Z:
// 2·4·(3-k)/3 + 0.4 and 2·(3-k)/3 + 0.1 = (5.7333, 1.4333), (3.0667, 0.7667), (0.4, 0.1).
TEST(CyclesSpec_9_Q16, PatternRepeatWithTheTextbookStep) {
  CycleChoices book;
  book.patternStepByPassCount = true;
  EXPECT_EQ(contourCycle(60, 5, 0.25, {"G0 X30 Z2", "G1 Z-15 F0.1", "X50 Z-25", "X60"},
                         "G73.7 U4 W2 R3", "G73.7 P50 Q80 U0.4 W0.1 F0.25", book),
            "G0 X35.7333 Z3.4333 | G1 Z-13.5667 F0.25 | G1 X55.7333 Z-23.5667 F0.25 | "
            "G1 X65.7333 F0.25 | G0 X60 Z5 | "
            "G0 X33.0667 Z2.7667 | G1 Z-14.2333 F0.25 | G1 X53.0667 Z-24.2333 F0.25 | "
            "G1 X63.0667 F0.25 | G0 X60 Z5 | "
            "G0 X30.4 Z2.1 | G1 Z-14.9 F0.25 | G1 X50.4 Z-24.9 F0.25 | G1 X60.4 F0.25 | "
            "G0 X60 Z5");
}

// §4.12 G74.7 peck drilling, TV-20: pecks of Q4 from Z3, retract e = 0.5, last clipped at -12.
TEST(CyclesSpec_8_TV20, G74PeckDrillingWithoutX) {
  auto req = request(0, 3);
  req.end[2] = -12;
  req.feed = 0.1;
  EXPECT_EQ(expand(req, "G74.7 R0.5", "G74.7 Z-12 Q4 F0.1", 0),
            "G1 Z-1 F0.1 | G0 Z-0.5 | G1 Z-5 F0.1 | G0 Z-4.5 | G1 Z-9 F0.1 | G0 Z-8.5 | "
            "G1 Z-12 F0.1 | G0 Z3");
}

// §4.12 G75.7 grooving, TV-21: pecks P3 (radius) along X, columns Q2.5 along Z.
TEST(CyclesSpec_8_TV21, G75GroovingColumns) {
  EXPECT_EQ(cycleTo(32, -5, 10, -10, 0.05, "G75.7 R0.5", "G75.7 X20 Z-10 P3 Q2.5 F0.05"),
            "G1 X26 F0.05 | G0 X27 | G1 X20 F0.05 | G0 X32 | "
            "G0 Z-7.5 | G1 X26 F0.05 | G0 X27 | G1 X20 F0.05 | G0 X32 | "
            "G0 Z-10 | G1 X26 F0.05 | G0 X27 | G1 X20 F0.05 | G0 X32 | G0 Z-5");
}

// §4.13 G76.7, TV-22. The spec rounds to 3 decimals; opsText prints 4 (4.654 -> 4.6536 ...).
TEST(CyclesSpec_8_TV22, G76PassTable) {
  auto req = request(32, 5);
  req.end = cycles::Vec3(13.7, 0, -20);
  req.feed = 2;
  const std::string tail = " | G33 Z-20 F2 | G0 X32 | G0 Z5";
  EXPECT_EQ(expand(req, "G76.7 P010060 Q0.1 R0.05", "G76.7 X27.4 Z-20 P1.3 Q0.6 F2"),
            "G0 X28.8 Z4.6536" + tail + " | G0 X28.3029 Z4.5101" + tail + " | G0 X27.9215 Z4.4" +
                tail + " | G0 X27.6 Z4.3072" + tail + " | G0 X27.5 Z4.2783" + tail +
                " | G0 X27.4 Z4.2494" + tail);
}

// §4.4 G77.7, TV-23 (000:7221-7231): three modal repeats, taper R-3 is a radius.
TEST(CyclesSpec_8_TV23, G77ModalRepeats) {
  const std::pair<double, const char*> rows[] = {
      {90, "G0 X84 | G1 X90 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1"},
      {80, "G0 X74 | G1 X80 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1"},
      {70, "G0 X64 | G1 X70 Z-30 F0.5 | G1 X101 F0.5 | G0 Z1"},
  };
  for (const auto& [x, expected] : rows) {
    auto req = request(101, 1);
    req.end = cycles::Vec3(x / 2, 0, -30);
    req.taper = -3;
    req.feed = 0.5;
    EXPECT_EQ(expand(req, "", "G77.7 X90 Z-30 R-3 F0.5"), expected) << x;
  }
}

// §4.5 G78.7, TV-24: step 2 is a G33 with F = lead, step 3 a rapid; no chamfer.
TEST(CyclesSpec_8_TV24, G78ThreadCycle) {
  for (double x : {29.2, 28.6}) {
    auto req = request(32, 5);
    req.end = cycles::Vec3(x / 2, 0, -20);
    req.feed = 2;
    const std::string xs = x == 29.2 ? "X29.2" : "X28.6";
    EXPECT_EQ(expand(req, "", "G78.7 X29.2 Z-20 F2"),
              "G0 " + xs + " | G33 Z-20 F2 | G0 X32 | G0 Z5");
  }
}

// §4.6 G79.7, TV-25.
TEST(CyclesSpec_8_TV25, G79FacingCycle) {
  for (double z : {-2.0, -4.0}) {
    auto req = request(52, 2);
    req.end = cycles::Vec3(10, 0, z);
    req.feed = 0.2;
    const std::string zs = z == -2 ? "Z-2" : "Z-4";
    EXPECT_EQ(expand(req, "", "G79.7 X20 Z-2 F0.2"),
              "G0 " + zs + " | G1 X20 F0.2 | G1 Z2 F0.2 | G0 X52");
  }
}

// --- TV-32 and §7 errors, located ------------------------------------------------------------

// TV-32 E8: the P2 coordinate turns back at `X20 Z-20` (contour line 52).
TEST(CyclesSpec_8_TV32, E8NonMonotonicAtTheBlockThatTurns) {
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G0 X30", "G1 Z-10", "X20 Z-20", "X40"}, "G71.7 U2 R1",
                         "G71.7 P900 Q910 U0.2 W0.1 F0.2"),
            "52:1 CYC-NONMONOTONIC");
}

TEST(CyclesSpec_7, NsBlockWithoutG0OrG1) {
  EXPECT_EQ(
      contourCycle(60, 2, 0.2, {"X30", "G1 Z-10", "X40"}, "G71.7 U2 R1", "G71.7 P50 Q70 F0.2"),
      "50:1 CYC-NS-MODE");
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G2 X30 Z-5 R20", "G1 Z-10", "X40"}, "G71.7 U2 R1",
                         "G71.7 P50 Q70 F0.2"),
            "50:1 CYC-NS-MODE");
}

TEST(CyclesSpec_7, TypeTwoIsRejectedAtTheNsBlock) {
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G0 X30 Z1", "G1 Z-10", "X60"}, "G71.7 U2 R1",
                         "G71.7 P50 Q70 F0.2"),
            "50:1 CYC-TYPE2-UNSUPPORTED");
}

TEST(CyclesSpec_7, MonotonicityAlongTheCutAxis) {
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G0 X30", "G1 Z-10", "X40 Z-5", "X60"}, "G71.7 U2 R1",
                         "G71.7 P50 Q70 F0.2"),
            "52:1 CYC-NONMONOTONIC");
}

TEST(CyclesSpec_7, ArcThatTurnsBackIsNonMonotonic) {
  // a half circle bulging past X40 between X30 Z-10 and X30 Z-30
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G0 X30", "G1 Z-10", "G3 X30 Z-30 R10", "G1 X60"},
                         "G71.7 U2 R1", "G71.7 P50 Q70 F0.2"),
            "52:1 CYC-NONMONOTONIC");
}

TEST(CyclesSpec_7, DegenerateContours) {
  auto req = request(60, 2);
  req.feed = 0.2;
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 Q70 F0.2"), "40:1 CYC-CONTOUR-DEGENERATE");
  req.contour = contour(req.start, {"G0 X60", "G1 Z-10"}); // ns does not move along X
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 Q70 F0.2"), "50:1 CYC-CONTOUR-DEGENERATE");
  req.contour = contour(req.start, {"G0 X30", "G1 X60"}); // no length along Z
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 Q70 F0.2"), "50:1 CYC-CONTOUR-DEGENERATE");
}

TEST(CyclesSpec_7, ZeroRadiusArcIsAnError) {
  auto req = request(60, 2);
  req.feed = 0.2;
  req.contour = contour(req.start, {"G0 X30", "G1 Z-10", "G2 X40 Z-15 R5", "G1 X60"});
  req.contour[2].center = req.contour[2].from;
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 Q80 F0.2"), "52:1 GCX037");
}

TEST(CyclesSpec_7, ParametersAreCheckedAtTheirWord) {
  auto req = request(60, 2);
  req.feed = 0.2;
  req.contour = contour(req.start, {"G0 X30", "G1 Z-10", "X60"});
  EXPECT_EQ(expand(req, "G71.7 U0 R1", "G71.7 P50 Q70 F0.2"), "30:7 CYC-PARAM");
  EXPECT_EQ(expand(req, "G71.7 U2 R-1", "G71.7 P50 Q70 F0.2"), "30:10 CYC-PARAM");
  EXPECT_EQ(expand(req, "", "G71.7 P50 Q70 F0.2"), "40:1 CYC-PARAM"); // Δd never given
  EXPECT_EQ(expand(req, "G73.7 U4 W2 R0", "G73.7 P50 Q70 F0.2"), "30:13 CYC-PARAM");
  EXPECT_EQ(expand(req, "G73.7 U4 W2 R2.5", "G73.7 P50 Q70 F0.2"), "30:13 CYC-PARAM");
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 F0.2"), "40:1 CYC-PQ-NOTFOUND");
  EXPECT_EQ(expand(req, "G71.7 U0.00001 R0", "G71.7 P50 Q70 F0.2"), "40:1 CYC-PARAM");
  req.feed = 0;
  EXPECT_EQ(expand(req, "G71.7 U2 R1", "G71.7 P50 Q70"), "40:1 2004");
}

TEST(CyclesSpec_7, ThreadParameters) {
  auto thread = [](const std::string& first, const std::string& run, double lead = 2) {
    return cycleTo(32, 5, 13.7, -20, lead, first, run);
  };
  EXPECT_EQ(thread("G76.7 P010045 Q0.1 R0.05", "G76.7 X27.4 Z-20 P1.3 Q0.6 F2"),
            "30:7 CYC-PARAM"); // tool angle 45
  EXPECT_EQ(thread("G76.7 P000060", "G76.7 X27.4 Z-20 P1.3 Q0.6 F2"),
            "30:7 CYC-PARAM"); // m = 0
  EXPECT_EQ(thread("", "G76.7 X27.4 Z-20 P0 Q0.6 F2"), "40:18 CYC-PARAM");
  EXPECT_EQ(thread("", "G76.7 X27.4 Z-20 P1.3 Q-1 F2"), "40:23 CYC-PARAM");
  EXPECT_EQ(thread("", "G76.7 X27.4 Z-20 P1.3 Q0.00001 F2"), "40:23 CYC-PARAM");
  EXPECT_EQ(thread("", "G76.7 X27.4 Z-20 P1.3 Q0.6 F0", 0), "40:28 2021");
  EXPECT_EQ(thread("", "G78.7 X27.4 Z-20 F0", 0), "40:18 2021");
}

TEST(CyclesSpec_7, GroovingParameters) {
  auto groove = [](const std::string& first, const std::string& run) {
    return cycleTo(32, -5, 10, -10, 0.05, first, run);
  };
  EXPECT_EQ(groove("G75.7 R0.5", "G75.7 X20 Z-10 P0 Q2.5 F0.05"), "40:16 CYC-PARAM");
  EXPECT_EQ(groove("G75.7 R0.5", "G75.7 X20 Z-10 P3 F0.05"), "40:1 CYC-PARAM");
  EXPECT_EQ(groove("G75.7 R-0.5", "G75.7 X20 Z-10 P3 Q2.5 F0.05"), "30:7 CYC-PARAM");
  EXPECT_EQ(groove("G75.7 R0.5", "G75.7 X20 Z-10 P1e-300 Q2.5 F0.05"), "40:16 CYC-PARAM");
}

// --- rules beyond the vectors -----------------------------------------------------------------

// §4.2: G19 maps P1 = Y, P2 = Z; lathe U' is W and lathe W' is V (000:10474-10512).
TEST(CyclesSpec_4_2, LetterMappingPerPlane) {
  const auto g18 = cycles::latheAxes(motion::Plane::ZX);
  const auto g19 = cycles::latheAxes(motion::Plane::YZ);
  const auto g17 = cycles::latheAxes(motion::Plane::XY);
  EXPECT_EQ(std::string({g18.z, g18.x, g18.w, g18.u}), "ZXWU");
  EXPECT_EQ(std::string({g19.z, g19.x, g19.w, g19.u}), "YZVW");
  EXPECT_EQ(std::string({g17.z, g17.x, g17.w, g17.u}), "XYUV");
}

// §4.2 in G19: `G71.7 W5 R1` stores Δd = 5 along Z; the cut runs along Y (the TV-26 shape).
TEST(CyclesSpec_4_2, G71InG19CutsAlongY) {
  cycles::TurningRequest req;
  req.plane = motion::Plane::YZ;
  req.start = cycles::Vec3(0, -56, 80);
  req.feed = 1;
  // contour: Z50 (ns, along Z), then Y-80 Z50 -> Y-80 Z80 style profile, made by hand
  auto seg = [](cycles::OpKind k, cycles::Vec3 f, cycles::Vec3 t, unsigned line) {
    cycles::ContourSegment s;
    s.kind = k, s.from = f, s.to = t, s.range = at(line);
    return s;
  };
  req.contour = {seg(cycles::OpKind::Rapid, {0, -56, 80}, {0, -56, 62}, 50),
                 seg(cycles::OpKind::Feed, {0, -56, 62}, {0, -70, 62}, 51),
                 seg(cycles::OpKind::Feed, {0, -70, 62}, {0, -70, 80}, 52)};
  EXPECT_EQ(expand(req, "G71.7 W5 R1", "G71.7 P50 Q52 F1", 0),
            "G0 Z75 | G1 Y-70 F1 | G0 Y-69 Z76 | G0 Y-56 | G0 Z70 | G1 Y-70 F1 | G0 Y-69 Z71 | "
            "G0 Y-56 | G0 Z65 | G1 Y-70 F1 | G0 Y-69 Z66 | G0 Y-56 | G0 Z62 | G1 Y-70 F1 | "
            "G1 Z80 F1 | G0 Y-56");
}

// TV-26 (c) (000:10464-10531) in G19 with Y a diameter axis: `G71.7 W5 R1` then
// `G71.7 P220 Q310 W1 V2 F1.2` makes 5 cuts at Z75..Z55, each a feed in -Y from Y-56, then the
// final pass, then G0 Y-56 Z80. The contour keeps the manual's corners; the `,C`/`,R` corners
// and the N270 arc are the interpreter's to resolve and are left out (a line for N270). Δw = V2
// is a diameter value: 1 in radius.
TEST(CyclesSpec_8_TV26, G71InG19MakesFiveCuts) {
  cycles::TurningRequest req;
  req.plane = motion::Plane::YZ;
  req.start = cycles::Vec3(0, -28, 80);
  req.feed = 1.2;
  const double yz[][2] = {{-56, 50},  {-76, 50},  {-80, 50},  {-80, 55},    {-130, 55},
                          {-150, 65}, {-150, 70}, {-170, 70}, {-170, 77.5}, {-170, 80}};
  cycles::Vec3 from = req.start;
  for (unsigned i = 0; i < std::size(yz); ++i) {
    cycles::ContourSegment s;
    s.kind = i < 2 ? cycles::OpKind::Rapid : cycles::OpKind::Feed;
    s.from = from, s.to = cycles::Vec3(0, yz[i][0] / 2, yz[i][1]), s.range = at(220 + i);
    req.contour.push_back(s);
    from = s.to;
  }
  EXPECT_EQ(expand(req, "G71.7 W5 R1", "G71.7 P220 Q310 W1 V2 F1.2", 2),
            "G0 Z75 | G1 Y-168 F1.2 | G0 Y-166 Z76 | G0 Y-56 | "
            "G0 Z70 | G1 Y-148 F1.2 | G0 Y-146 Z71 | G0 Y-56 | "
            "G0 Z65 | G1 Y-146 F1.2 | G0 Y-144 Z66 | G0 Y-56 | "
            "G0 Z60 | G1 Y-136 F1.2 | G0 Y-134 Z61 | G0 Y-56 | "
            "G0 Z55 | G1 Y-78 F1.2 | G0 Y-76 Z56 | G0 Y-56 | "
            "G0 Y-54 Z51 | G1 Y-74 F1.2 | G1 Y-78 F1.2 | G1 Z56 F1.2 | G1 Y-128 F1.2 | "
            "G1 Y-148 Z66 F1.2 | G1 Z71 F1.2 | G1 Y-168 F1.2 | G1 Z78.5 F1.2 | G1 Z81 F1.2 | "
            "G0 Y-56 Z80");
}

// §4.8 with an arc: the level cuts end on the circle, the final pass keeps the arc (G2 R10).
TEST(CyclesSpec_4_8, ArcsAreIntersectedAndKept) {
  // quarter circle (x15, z-10) -> (x25, z-20) about (x25, z-10), a cove: level 26 misses it
  // and ends on X60; 22 and 18 end at z = -10 - sqrt(100 - (25 - x)^2)
  EXPECT_EQ(contourCycle(60, 2, 0.3, {"G0 X30", "G1 Z-10", "G2 X50 Z-20 R10", "G1 X60"},
                         "G71.7 U4 R1", "G71.7 P50 Q80 F0.3"),
            "G0 X52 | G1 Z-20 F0.3 | G0 X54 Z-19 | G0 Z2 | "
            "G0 X44 | G1 Z-19.5394 F0.3 | G0 X46 Z-18.5394 | G0 Z2 | "
            "G0 X36 | G1 Z-17.1414 F0.3 | G0 X38 Z-16.1414 | G0 Z2 | "
            "G0 X30 | G1 Z-10 F0.3 | G2 X50 Z-20 R10 F0.3 | G1 X60 F0.3 | G0 Z2");
}

// §4.8, other quadrant: an ID (boring) contour, A inside the stock; levels go +X.
TEST(CyclesSpec_4_8, InsideDiameterLevelsGoOutward) {
  EXPECT_EQ(contourCycle(20, 2, 0.2, {"G0 X40", "G1 Z-10", "X30 Z-20", "X20"}, "G71.7 U3 R0.5",
                         "G71.7 P50 Q80 U-0.4 W0.1 F0.2"),
            "G0 X26 | G1 Z-19.9 F0.2 | G0 X25 Z-19.4 | G0 Z2 | "
            "G0 X32 | G1 Z-17.5 F0.2 | G0 X31 Z-17 | G0 Z2 | "
            "G0 X38 | G1 Z-11.5 F0.2 | G0 X37 Z-11 | G0 Z2 | "
            "G0 X39.6 Z2.1 | G1 Z-9.9 F0.2 | G1 X29.6 Z-19.9 F0.2 | G1 X19.6 F0.2 | "
            "G0 X20 Z2");
}

// §4.7: a G1 ns block approaches every level at the roughing feed.
TEST(CyclesSpec_4_7, FeedApproachWhenNsIsG1) {
  EXPECT_EQ(
      contourCycle(60, 2, 0.3, {"G1 X40", "Z-10", "X60"}, "G71.7 U5 R1", "G71.7 P50 Q70 F0.3"),
      "G1 X50 F0.3 | G1 Z-10 F0.3 | G0 X52 Z-9 | G0 Z2 | "
      "G1 X40 F0.3 | G1 Z-10 F0.3 | G1 X60 F0.3 | G0 Z2");
}

// §4.8 Δd larger than the stock: no level, only the final pass.
TEST(CyclesSpec_4_8, DepthLargerThanTheStock) {
  EXPECT_EQ(
      contourCycle(60, 2, 0.3, {"G0 X50", "G1 Z-10", "X60"}, "G71.7 U8 R1", "G71.7 P50 Q70 F0.3"),
      "G0 X50 | G1 Z-10 F0.3 | G1 X60 F0.3 | G0 Z2");
}

// §4.8 with e >= Δd: each approach climbs from x_(k-1) + e; well defined, no overlap check.
TEST(CyclesSpec_4_8, RetractLargerThanTheDepth) {
  EXPECT_EQ(
      contourCycle(60, 2, 0.2, {"G0 X50", "G1 Z-10", "X60"}, "G71.7 U1 R2", "G71.7 P50 Q70 F0.2"),
      "G0 X58 | G1 Z-10 F0.2 | G0 X62 Z-8 | G0 Z2 | G0 X56 | G1 Z-10 F0.2 | G0 X60 Z-8 | "
      "G0 Z2 | G0 X54 | G1 Z-10 F0.2 | G0 X58 Z-8 | G0 Z2 | G0 X52 | G1 Z-10 F0.2 | "
      "G0 X56 Z-8 | G0 Z2 | G0 X50 | G1 Z-10 F0.2 | G1 X60 F0.2 | G0 Z2");
}

// §4.10: G73.7 needs no monotonicity; the TV-32 E8 contour runs as programmed.
TEST(CyclesSpec_4_10, PatternRepeatAcceptsAPocket) {
  EXPECT_EQ(contourCycle(60, 2, 0.2, {"G0 X30", "G1 Z-10", "X20 Z-20", "X40"}, "G73.7 R1",
                         "G73.7 P50 Q80 F0.2"),
            "G0 X30 | G1 Z-10 F0.2 | G1 X20 Z-20 F0.2 | G1 X40 F0.2 | G0 X60 Z2");
}

// §4.10 d = 1: one pass with the finishing allowance only.
TEST(CyclesSpec_4_10, OnePassUsesTheAllowanceOnly) {
  EXPECT_EQ(contourCycle(60, 5, 0.25, {"G0 X30 Z2", "G1 Z-15", "X60"}, "G73.7 U4 W2 R1",
                         "G73.7 P50 Q70 U0.4 W0.1 F0.25"),
            "G0 X30.4 Z2.1 | G1 Z-14.9 F0.25 | G1 X60.4 F0.25 | G0 X60 Z5");
}

// §4.12 G74.7 with X: columns stepped by P along X, relief R against the step direction.
TEST(CyclesSpec_4_12, G74FaceGroovingColumnsWithRelief) {
  EXPECT_EQ(cycleTo(20, 1, 7, -4, 0.1, "G74.7 R1", "G74.7 X14 Z-4 P2 Q3 R0.5 F0.1"),
            "G1 Z-2 F0.1 | G0 Z-1 | G1 Z-4 F0.1 | G0 X21 | G0 Z1 | "
            "G0 X16 | G1 Z-2 F0.1 | G0 Z-1 | G1 Z-4 F0.1 | G0 X17 | G0 Z1 | "
            "G0 X14 | G1 Z-2 F0.1 | G0 Z-1 | G1 Z-4 F0.1 | G0 X15 | G0 Z1 | G0 X20");
}

// §4.13 with a chamfer (r = 10: one lead at 45°) and a taper i: the thread ends at Z.
TEST(CyclesSpec_4_13, ChamferAndTaper) {
  auto req = request(32, 5);
  req.end = cycles::Vec3(14, 0, -20);
  req.feed = 2;
  req.taper = -1;
  // depths 0.8 (k - d) and 1 (k); a = 0: no flank shift; chamfer 2 from Z-18, taper 13 -> 14
  EXPECT_EQ(expand(req, "G76.7 P011000 Q0.1 R0.2", "G76.7 X28 Z-20 P1 Q1 R-1 F2"),
            "G0 X26.4 | G33 X28.24 Z-18 F2 | G33 X32.24 Z-20 F2 | G0 X32 | G0 Z5 | "
            "G0 X26 | G33 X27.84 Z-18 F2 | G33 X31.84 Z-20 F2 | G0 X32 | G0 Z5");
}

} // namespace
} // namespace gcx::test
