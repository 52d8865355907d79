// Every plane-dependent rule in G17, G18 and G19 (nct.md §3.6: the plane governs arcs, polar
// input, G68, drilling-cycle positioning and turning cycles). G17 = (X, Y) about Z, G18 = (Z, X)
// about Y, G19 = (Y, Z) about X; "counter-clockwise" and positive angles go from the plane's
// first axis toward its second. Expected positions are worked by hand from those rules; they
// are machine-frame gauge points (no offsets), rounded to 4 decimals. Arcs print their centre
// as (first, second) plane coordinates.
#include <gtest/gtest.h>

#include "cycles/cycle_harness.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

V motionOf(const std::string& program) {
  ProgramRun r = runNct(program);
  EXPECT_TRUE(r.errors.empty()) << program << "\n" << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

// --- §3.15 rotation G68: (p, q) are the plane's first and second axis words, R counter-
// clockwise from the first axis toward the second ------------------------------------------

TEST(NctSpec_3_15, G68QuarterTurnAboutTheOriginInEachPlane) {
  EXPECT_EQ(motionOf("G17 G90 G68 X0 Y0 R90\nG1 X10 F100\n"), V{"L 0,10,0 F100"});
  EXPECT_EQ(motionOf("G18 G90 G68 X0 Z0 R90\nG1 Z10 F100\n"), V{"L 10,0,0 F100"}); // Z toward X
  EXPECT_EQ(motionOf("G19 G90 G68 Y0 Z0 R90\nG1 Y10 F100\n"), V{"L 0,0,10 F100"}); // Y toward Z
}

TEST(NctSpec_3_15, G68AboutACentreLeavesTheNormalAxisAlone) {
  // x' = p + (x-p)cosR - (y-q)sinR, y' = q + (x-p)sinR + (y-q)cosR in (first, second)
  // G17: (p,q) = (X10,Y20); (30,20) -> (10, 40); Z5 is not in the plane
  EXPECT_EQ(motionOf("G17 G90 G68 X10 Y20 R90\nG1 X30 Y20 Z5 F100\n"), V{"L 10,40,5 F100"});
  // G18: (p,q) = (Z20,X10); (z,x) = (30,10) -> (20, 20); Y5 is not in the plane
  EXPECT_EQ(motionOf("G18 G90 G68 X10 Z20 R90\nG1 X10 Y5 Z30 F100\n"), V{"L 20,5,20 F100"});
  // G19: (p,q) = (Y10,Z20); (y,z) = (30,20) -> (10, 40); X5 is not in the plane
  EXPECT_EQ(motionOf("G19 G90 G68 Y10 Z20 R90\nG1 X5 Y30 Z20 F100\n"), V{"L 5,10,40 F100"});
}

TEST(NctSpec_3_15, G68ThirtyDegreesInEachPlane) {
  // (10, 0) in (first, second) turned by 30°: (8.6603, 5)
  EXPECT_EQ(motionOf("G17 G68 X0 Y0 R30\nG1 X10 F100\n"), V{"L 8.6603,5,0 F100"});
  EXPECT_EQ(motionOf("G18 G68 X0 Z0 R30\nG1 Z10 F100\n"), V{"L 5,0,8.6603 F100"});
  EXPECT_EQ(motionOf("G19 G68 Y0 Z0 R30\nG1 Y10 F100\n"), V{"L 0,8.6603,5 F100"});
  // an incremental R adds to the angle in force: 30 + 60 = 90 (000:8541-8551)
  EXPECT_EQ(motionOf("G18 G68 X0 Z0 R30\nG68 X0 Z0 RI60\nG1 Z10 F100\n"), V{"L 10,0,0 F100"});
}

TEST(NctSpec_3_15, G68IncrementalCentreCountsFromTheProgrammedPosition) {
  // XI0 ZI0: the centre is the current point (z,x) = (20,10); (30,10) turns to (20,20)
  EXPECT_EQ(motionOf("G18 G90 G0 X10 Z20\nG68 XI0 ZI0 R90\nG1 X10 Z30 F100\n"),
            (V{"R 10,0,20", "L 20,0,20 F100"}));
  // G91: the centre is (y,z) = (10,20) + (0,5) = (10,25); (20,25) turns to (10,35)
  EXPECT_EQ(motionOf("G19 G90 G0 Y10 Z20\nG91 G68 Y0 Z5 R90\nG90 G1 Y20 Z25 F100\n"),
            (V{"R 0,10,20", "L 0,10,35 F100"}));
}

TEST(NctSpec_3_15, G68TurnsArcsWithTheirPlane) {
  // G18: a G3 quarter from (z,x) = (10,0) to (0,10) about the origin, turned by 90°: it starts
  // at (0,10), ends at (-10,0) and stays counter-clockwise; G19 likewise in (y,z)
  EXPECT_EQ(motionOf("G18 G90 G68 X0 Z0 R90\nG0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 10,0,0", "CCW 0,0,-10 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G19 G90 G68 Y0 Z0 R90\nG0 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R 0,0,10", "CCW 0,-10,0 C0,0 r10 θ90"}));
}

// --- §3.15 scaling G51 ------------------------------------------------------------------------

TEST(NctSpec_3_15, G51ScalesArcsInEachPlane) {
  // P2 about the origin: a quarter of radius 10 becomes one of radius 20
  EXPECT_EQ(motionOf("G51 X0 Y0 Z0 P2\nG17 G0 X10 Y0\nG3 X0 Y10 R10 F100\n"),
            (V{"R 20,0,0", "CCW 0,20,0 C0,0 r20 θ90"}));
  EXPECT_EQ(motionOf("G51 X0 Y0 Z0 P2\nG18 G0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,0,20", "CCW 20,0,0 C0,0 r20 θ90"}));
  EXPECT_EQ(motionOf("G51 X0 Y0 Z0 P2\nG19 G0 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R 0,20,0", "CCW 0,0,20 C0,0 r20 θ90"}));
}

TEST(NctSpec_3_15, G51PerAxisFactorsAboutACentre) {
  // x' = x0 + I(x - x0): centre (10, 20, 30), I2 J3 K4
  EXPECT_EQ(motionOf("G51 X10 Y20 Z30 I2 J3 K4\nG1 X15 Y25 Z35 F100\n"), V{"L 20,35,50 F100"});
}

TEST(NctSpec_3_15, UnequalFactorsOnlyMatterInTheArcsPlane) {
  // I = K: the circle stays a circle in G18 (Z, X), whatever J does to Y
  EXPECT_EQ(motionOf("G51 X0 Y0 Z0 I2 J3 K2\nG18 G0 X0 Y1 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,3,20", "CCW 20,3,0 C0,0 r20 θ90"}));
  // I != J in G17: the arc would be an ellipse (nct.md Q19), refused at the arc block
  EXPECT_EQ(runNct("G51 X0 Y0 Z0 I2 J3 K2\nG17 G0 X10 Y0\nG3 X0 Y10 R10 F100\n").errors,
            V{"3:1 GCX033"});
  EXPECT_EQ(runNct("G51 X0 Y0 Z0 I2 J3 K2\nG19 G0 Y10 Z0\nG3 Y0 Z10 R10 F100\n").errors,
            V{"3:1 GCX033"});
}

// --- §3.15 mirror G51.1: an odd number of mirrored plane axes swaps G2 and G3 ----------------

TEST(NctSpec_3_15, MirrorOfOnePlaneAxisSwapsTheArcDirectionInG17) {
  EXPECT_EQ(motionOf("G51.1 X0\nG17 G0 X10 Y0\nG3 X0 Y10 R10 F100\n"),
            (V{"R -10,0,0", "CW 0,10,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 Y0\nG17 G0 X10 Y0\nG2 X0 Y-10 R10 F100\n"),
            (V{"R 10,0,0", "CCW 0,10,0 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorOfOnePlaneAxisSwapsTheArcDirectionInG18) {
  EXPECT_EQ(motionOf("G51.1 X0\nG18 G0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,0,10", "CW -10,0,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 Z0\nG18 G0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,0,-10", "CW 10,0,0 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorOfOnePlaneAxisSwapsTheArcDirectionInG19) {
  EXPECT_EQ(motionOf("G51.1 Y0\nG19 G0 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R 0,-10,0", "CW 0,0,10 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 Z0\nG19 G0 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R 0,10,0", "CW 0,0,-10 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorOfTheNormalAxisKeepsTheArcDirection) {
  // the normal axis is mirrored (Y5 -> -5) but the arc keeps its sense in its plane
  EXPECT_EQ(motionOf("G51.1 Z0\nG17 G0 X10 Y0 Z5\nG3 X0 Y10 R10 F100\n"),
            (V{"R 10,0,-5", "CCW 0,10,-5 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 Y0\nG18 G0 X0 Y5 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,-5,10", "CCW 10,-5,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 X0\nG19 G0 X5 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R -5,10,0", "CCW -5,0,10 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorOfBothPlaneAxesKeepsTheArcDirection) {
  EXPECT_EQ(motionOf("G51.1 X0 Y0\nG17 G0 X10 Y0\nG3 X0 Y10 R10 F100\n"),
            (V{"R -10,0,0", "CCW 0,-10,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 X0 Z0\nG18 G0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 0,0,-10", "CCW -10,0,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G51.1 Y0 Z0\nG19 G0 Y10 Z0\nG3 Y0 Z10 R10 F100\n"),
            (V{"R 0,-10,0", "CCW 0,0,-10 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorAboutALineAwayFromTheOrigin) {
  // G18, mirror line X = 20: x' = 40 - x; the centre (z,x) = (0,0) goes to (0,40)
  EXPECT_EQ(motionOf("G51.1 X20\nG18 G0 X0 Z10\nG3 X10 Z0 R10 F100\n"),
            (V{"R 40,0,10", "CW 30,0,0 C0,40 r10 θ90"}));
}

TEST(NctSpec_3_15, MirrorReversesTheG68AngleInItsPlane) {
  // Mirror(Rot(P)): (10,0) turned by 30° is (8.6603, 5); mirroring the second plane axis
  // gives (8.6603, -5), a turn of -30°
  EXPECT_EQ(motionOf("G51.1 Y0\nG17 G68 X0 Y0 R30\nG1 X10 F100\n"), V{"L 8.6603,-5,0 F100"});
  EXPECT_EQ(motionOf("G51.1 X0\nG18 G68 X0 Z0 R30\nG1 Z10 F100\n"), V{"L -5,0,8.6603 F100"});
  EXPECT_EQ(motionOf("G51.1 Z0\nG19 G68 Y0 Z0 R30\nG1 Y10 F100\n"), V{"L 0,8.6603,-5 F100"});
}

// --- §3.5 arcs and helices: I/J/K of the plane, the helix along the normal axis ---------------

TEST(NctSpec_3_5, CentreWordsAndHelixAxisInEachPlane) {
  // G17: I, J; the helix rises along Z
  EXPECT_EQ(motionOf("G17 G0 X10 Y0 Z0\nG3 X0 Y10 Z5 I-10 J0 F100\n"),
            (V{"R 10,0,0", "CCW 0,10,5 C0,0 r10 θ90"}));
  // G18: K on Z, I on X; the helix rises along Y
  EXPECT_EQ(motionOf("G18 G0 X0 Y0 Z10\nG3 X10 Y5 Z0 K-10 I0 F100\n"),
            (V{"R 0,0,10", "CCW 10,5,0 C0,0 r10 θ90"}));
  // G19: J on Y, K on Z; the helix rises along X
  EXPECT_EQ(motionOf("G19 G0 X0 Y10 Z0\nG3 X5 Y0 Z10 J-10 K0 F100\n"),
            (V{"R 0,10,0", "CCW 5,0,10 C0,0 r10 θ90"}));
}

TEST(NctSpec_3_5, ClockwiseByRInEachPlane) {
  // G2 R10 from the first axis at 10 to the second axis at -10: a clockwise quarter about 0
  EXPECT_EQ(motionOf("G17 G0 X10 Y0\nG2 X0 Y-10 R10 F100\n"),
            (V{"R 10,0,0", "CW 0,-10,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G18 G0 X0 Z10\nG2 X-10 Z0 R10 F100\n"),
            (V{"R 0,0,10", "CW -10,0,0 C0,0 r10 θ90"}));
  EXPECT_EQ(motionOf("G19 G0 Y10 Z0\nG2 Y0 Z-10 R10 F100\n"),
            (V{"R 0,10,0", "CW 0,0,-10 C0,0 r10 θ90"}));
  // R < 0: the arc of more than 180° about the other centre (10,-10) in (first, second)
  EXPECT_EQ(motionOf("G18 G0 X0 Z10\nG2 X-10 Z0 R-10 F100\n"),
            (V{"R 0,0,10", "CW -10,0,0 C10,-10 r10 θ270"}));
}

TEST(NctSpec_3_5, FullTurnsWithLInEachPlane) {
  // no in-plane end word and a centre: full circles; L2 = two turns, the normal axis descends
  EXPECT_EQ(motionOf("G17 G0 X10 Y0 Z0\nG2 I-10 Z-20 L2 F100\n"),
            (V{"R 10,0,0", "CW 10,0,-20 C0,0 r10 θ720"}));
  EXPECT_EQ(motionOf("G18 G0 X0 Y0 Z10\nG2 K-10 Y-20 L2 F100\n"),
            (V{"R 0,0,10", "CW 0,-20,10 C0,0 r10 θ720"}));
  EXPECT_EQ(motionOf("G19 G0 X0 Y10 Z0\nG2 J-10 X-20 L2 F100\n"),
            (V{"R 0,10,0", "CW -20,10,0 C0,0 r10 θ720"}));
}

TEST(NctSpec_3_5, CentreWordOfTheNormalAxisIsAlarm2015InEachPlane) {
  EXPECT_EQ(runNct("G17 G2 X10 K5 F100\n").errors, V{"1:12 2015"});
  EXPECT_EQ(runNct("G18 G2 Z10 J5 F100\n").errors, V{"1:12 2015"});
  EXPECT_EQ(runNct("G19 G2 Y10 I5 F100\n").errors, V{"1:12 2015"});
}

// --- §3.9 polar input: the first plane axis is the radius, the second the angle --------------

TEST(NctSpec_3_9, PolarRadiusAndAngleInEachPlane) {
  // r100 at 30°: (86.6025, 50) in (first, second); the axis off the plane stays Cartesian
  EXPECT_EQ(motionOf("G17 G90 G16 G1 X100 Y30 Z5 F100\n"), V{"L 86.6025,50,5 F100"});
  EXPECT_EQ(motionOf("G18 G90 G16 G1 Z100 X30 Y5 F100\n"), V{"L 50,5,86.6025 F100"});
  EXPECT_EQ(motionOf("G19 G90 G16 G1 Y100 Z30 X5 F100\n"), V{"L 5,86.6025,50 F100"});
}

TEST(NctSpec_3_9, PolarIncrementalAngleAndRadiusInG18) {
  // N2: 30° more than the current 30°: r100 at 60° = (z,x) (50, 86.6025);
  // N3: an incremental radius travels 10 from the start point in the direction 90° (toward +X)
  EXPECT_EQ(motionOf("N1 G18 G90 G16 G1 Z100 X30 F100\nN2 XI30\nN3 ZI10 X90\n"),
            (V{"L 50,0,86.6025 F100", "L 86.6025,0,50 F100", "L 96.6025,0,50 F100"}));
}

TEST(NctSpec_3_9, PolarIncrementalAngleAndRadiusInG19) {
  EXPECT_EQ(motionOf("N1 G19 G90 G16 G1 Y100 Z30 F100\nN2 ZI30\nN3 YI10 Z90\n"),
            (V{"L 0,86.6025,50 F100", "L 0,50,86.6025 F100", "L 0,50,96.6025 F100"}));
}

TEST(NctSpec_3_9, OmittedRadiusKeepsThePolarRadiusInG18) {
  // after r100 at 0°, `X90` alone keeps radius 100 and turns to 90°: (z,x) = (0, 100)
  EXPECT_EQ(motionOf("G18 G90 G16 G1 Z100 X0 F100\nX90\n"),
            (V{"L 0,0,100 F100", "L 100,0,0 F100"}));
}

// --- cycles.md §2.2, §2.7: drilling positions in the plane, drills along its normal ----------

TEST(CyclesSpec_2_7, G17MirrorOfZMirrorsTheLevels) {
  // the levels are mirrored with the drilling axis: R2 -> -2, Z-5 -> 5, ini 20 -> -20
  const auto h = run("N1 G51.1 Z0\nN2 G17 G90 G0 X0 Y0 Z20\nN3 G81 X5 Y6 Z-5 R2 F100\n");
  EXPECT_EQ(h.out.at("N3"), "G0 X5 Y6 | G0 Z-2 | G1 Z5 F100 | G0 Z-20");
}

TEST(CyclesSpec_2_7, G18MirrorOfYMirrorsTheLevels) {
  const auto h = run("N1 G51.1 Y0\nN2 G18 G90 G0 X0 Y20 Z0\nN3 G81 Z10 X5 Y-5 R2 F100\n");
  EXPECT_EQ(h.out.at("N3"), "G0 X5 Z10 | G0 Y-2 | G1 Y5 F100 | G0 Y-20");
}

TEST(CyclesSpec_2_7, G18RotationTurnsTheHoleFromZTowardX) {
  // hole (z,x) = (10,0) turned by 90° about the origin: (0,10); Y drills unrotated
  const auto h = run("N1 G18 G90 G0 X0 Y20 Z0\nN2 G68 X0 Z0 R90\nN3 G81 Z10 X0 Y-5 R2 F100\n");
  EXPECT_EQ(h.out.at("N3"), "G0 X10 | G0 Y2 | G1 Y-5 F100 | G0 Y20");
}

TEST(CyclesSpec_2_7, G19RotationTurnsTheHoleFromYTowardZ) {
  const auto h = run("N1 G19 G90 G0 X20 Y0 Z0\nN2 G68 Y0 Z0 R90\nN3 G81 Y10 Z0 X-5 R2 F100\n");
  EXPECT_EQ(h.out.at("N3"), "G0 Z10 | G0 X2 | G1 X-5 F100 | G0 X20");
}

TEST(CyclesSpec_2_7, G19ScalingScalesTheHoleAndTheLevels) {
  // P2 about the origin: hole (y,z) (5,6) -> (10,12); R1 -> 2, X-4 -> -8, ini 30 -> 60
  const auto h = run("N1 G51 X0 Y0 Z0 P2\nN2 G19 G90 G0 X30 Y0 Z0\nN3 G81 Y5 Z6 X-4 R1 F60\n");
  EXPECT_EQ(h.out.at("N2"), "G0 X60");
  EXPECT_EQ(h.out.at("N3"), "G0 Y10 Z12 | G0 X2 | G1 X-8 F60 | G0 X60");
}

// --- cycles.md §4.2: a turning contour in each plane (P1 = lathe Z, P2 = lathe X) ------------

// TV-17 (cycles.md §4.8) with its letters mapped to the plane: the roughing table of §4.8 with
// the same coordinates on the plane's axes (P2 a diameter axis).
struct TurningPlane {
  const char* plane;
  char p1, p2;          // lathe Z and lathe X letters
  char u, w;            // lathe U and lathe W letters (§4.2 table)
  unsigned diameterBit; // P2 as a machine axis bit
};

std::string tv17(const TurningPlane& t) {
  auto s = [&](const char* text) {
    std::string out;
    for (const char* c = text; *c; ++c)
      out += *c == 'x' ? t.p2 : *c == 'z' ? t.p1 : *c == 'u' ? t.u : *c == 'w' ? t.w : *c;
    return out;
  };
  return s("N10 G10.9 x1\nN15 ") + t.plane +
         s(" G90 G95\nN20 G0 x60 z2 S800 M3\nN30 G71.7 u3 R1\n"
           "N40 G71.7 P50 Q90 u0.4 w0.1 F0.3\nN50 G0 x30\nN60 G1 z-20 F0.15\n"
           "N70 x50 z-30\nN80 z-40\nN90 x60\nN100 G70.7 P50 Q90\nN110 G0 x100 z50\n");
}

/// "x54 z-39.9" -> the plane's letters, printed in X Y Z order as the harness does.
std::string moves(const TurningPlane& t, const std::string& text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t bar = text.find(" | ", i);
    const std::string step = text.substr(i, bar == std::string::npos ? bar : bar - i);
    std::map<char, std::string> axes;
    std::string head, tail;
    std::istringstream in(step);
    for (std::string word; in >> word;) {
      if (word[0] == 'x' || word[0] == 'z')
        axes[word[0] == 'x' ? t.p2 : t.p1] = word.substr(1);
      else
        (axes.empty() ? head : tail) += " " + word;
    }
    std::string line = head.substr(1);
    for (const auto& [letter, value] : axes)
      line += " " + std::string(1, letter) + value;
    out += (out.empty() ? "" : " | ") + line + tail;
    if (bar == std::string::npos) break;
    i = bar + 3;
  }
  return out;
}

void expectTv17(const TurningPlane& t) {
  CycleHarness h;
  h.diameter = 1u << t.diameterBit;
  ASSERT_TRUE(h.run(tv17(t))) << t.plane << ": " << h.error();
  EXPECT_EQ(h.out.at("N40"), moves(t, "G0 x54 | G1 z-39.9 F0.3 | G0 x56 z-38.9 | G0 z2 | "
                                      "G0 x48 | G1 z-28.7 F0.3 | G0 x50 z-27.7 | G0 z2 | "
                                      "G0 x42 | G1 z-25.7 F0.3 | G0 x44 z-24.7 | G0 z2 | "
                                      "G0 x36 | G1 z-22.7 F0.3 | G0 x38 z-21.7 | G0 z2 | "
                                      "G0 x30.4 z2.1 | G1 z-19.9 F0.3 | G1 x50.4 z-29.9 F0.3 | "
                                      "G1 z-39.9 F0.3 | G1 x60.4 F0.3 | G0 x60 z2"))
      << t.plane;
  EXPECT_EQ(h.out.at("N70"), moves(t, "G1 x50 z-30 F0.15")) << t.plane;
  EXPECT_EQ(h.out.at("N100"), moves(t, "G0 z2")) << t.plane;
  EXPECT_EQ(h.out.at("N110"), moves(t, "G0 x100 z50")) << t.plane;
}

TEST(CyclesSpec_4_2, Tv17RoughingInG18) {
  expectTv17({"G18", 'Z', 'X', 'U', 'W', 0});
}

TEST(CyclesSpec_4_2, Tv17RoughingInG19) {
  expectTv17({"G19", 'Y', 'Z', 'W', 'V', 2});
}

TEST(CyclesSpec_4_2, Tv17RoughingInG17) {
  expectTv17({"G17", 'X', 'Y', 'V', 'U', 1});
}

TEST(CyclesSpec_4_4, G77TurningCycleInEachPlane) {
  // §4.4 from A = (x 50, z 2) radius: rapid to x 40, feed to z -20, feed out to x 50, rapid back
  const TurningPlane planes[] = {{"G18", 'Z', 'X', 'U', 'W', 0},
                                 {"G19", 'Y', 'Z', 'W', 'V', 2},
                                 {"G17", 'X', 'Y', 'V', 'U', 1}};
  for (const TurningPlane& t : planes) {
    const std::string program = std::string("N1 ") + t.plane + " G90 G0 " + t.p2 + "50 " + t.p1 +
                                "2\nN2 G77.7 " + t.p2 + "40 " + t.p1 + "-20 F100\nN3 G80\n";
    CycleHarness h;
    ASSERT_TRUE(h.run(program)) << t.plane << ": " << h.error();
    EXPECT_EQ(h.out.at("N2"), moves(t, "G0 x40 | G1 z-20 F100 | G1 x50 F100 | G0 z2")) << t.plane;
  }
}

} // namespace
} // namespace gcx::test
