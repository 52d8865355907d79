// Reading rs274 canonical output into machine-frame events. The samples are verbatim rs274
// output (LinuxCNC 2.9.0~pre1, Debian 12): 06_arcs_ij, 11_offsets_units and
// 16h_comment_semicolon from the LinuxCNC reference runs, and one run made for this test
// (tool/spindle/coolant/feed modes/units).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "oracle/canon.h"

namespace gcx::oracle {
namespace {

using motion::Event;
using motion::Kind;
using motion::Plane;
using motion::Vec3;

constexpr double kEps = 1e-9;

void expectVec(const Vec3& got, const Vec3& want, const char* what, std::size_t i) {
  EXPECT_NEAR(got.x(), want.x(), kEps) << what << " x of event " << i;
  EXPECT_NEAR(got.y(), want.y(), kEps) << what << " y of event " << i;
  EXPECT_NEAR(got.z(), want.z(), kEps) << what << " z of event " << i;
}

void expectMove(const std::vector<Event>& ev, std::size_t i, Kind k, std::uint32_t line,
                const Vec3& start, const Vec3& end, double feed = 0) {
  ASSERT_LT(i, ev.size());
  const Event& e = ev[i];
  EXPECT_EQ(e.kind, k) << "event " << i;
  EXPECT_EQ(e.from.at.line, line) << "event " << i;
  expectVec(e.start, start, "start", i);
  expectVec(e.end, end, "end", i);
  if (k == Kind::Feed) {
    EXPECT_NEAR(e.feed, feed, kEps) << "feed of event " << i;
  }
}

void expectArc(const std::vector<Event>& ev, std::size_t i, Plane plane, bool cw, int turns,
               const Vec3& start, const Vec3& end, const Vec3& centre, double r, double feed) {
  ASSERT_LT(i, ev.size());
  const Event& e = ev[i];
  EXPECT_EQ(e.kind, Kind::Arc) << "event " << i;
  EXPECT_EQ(e.plane, plane) << "event " << i;
  EXPECT_EQ(e.clockwise, cw) << "event " << i;
  EXPECT_EQ(e.turns, turns) << "event " << i;
  expectVec(e.start, start, "start", i);
  expectVec(e.end, end, "end", i);
  expectVec(e.center, centre, "centre", i);
  EXPECT_NEAR(e.startRadius, r, kEps) << "event " << i;
  EXPECT_NEAR(e.endRadius, r, kEps) << "event " << i;
  EXPECT_NEAR(e.feed, feed, kEps) << "event " << i;
}

// refs/linuxcnc/programs/06_arcs_ij.ngc -> outputs/06_arcs_ij.canon
const char* const kArcs = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... COMMENT("06: arcs with I/J/K centre offsets, all three planes, full circle, helix")
    8 N..... COMMENT("interpreter: feed mode set to units per minute")
    9 N..... SET_FEED_MODE(0, 0)
   10 N..... SET_FEED_RATE(0.0000)
   11 N..... SELECT_PLANE(CANON_PLANE_XY)
   12 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   13 N..... COMMENT("interpreter: cutter radius compensation off")
   14 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)
   15 N..... COMMENT("interpreter: motion mode set to none")
   16 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   17 N..... SET_FEED_RATE(300.0000)
   18 N..... STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   19 N..... COMMENT("quarter arc CCW centre 0,0")
   20 N..... ARC_FEED(0.0000, 10.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   21 N..... COMMENT("quarter arc CW back")
   22 N..... ARC_FEED(10.0000, 0.0000, 0.0000, 0.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   23 N..... COMMENT("full circle: end == start")
   24 N..... ARC_FEED(10.0000, 0.0000, 0.0000, 0.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   25 N..... COMMENT("helix: 2 turns with P2, Z drop 4")
   26 N..... ARC_FEED(10.0000, 0.0000, 0.0000, 0.0000, 2, -4.0000, 0.0000, 0.0000, 0.0000)
   27 N..... COMMENT("XZ plane G18")
   28 N..... SELECT_PLANE(CANON_PLANE_XZ)
   29 N..... STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   30 N..... ARC_FEED(0.0000, 10.0000, 0.0000, 5.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)
   31 N..... COMMENT("YZ plane G19")
   32 N..... SELECT_PLANE(CANON_PLANE_YZ)
   33 N..... ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, 1, 10.0000, 0.0000, 0.0000, 0.0000)
   34 N..... SELECT_PLANE(CANON_PLANE_XY)
   35 N..... COMMENT("absolute arc centre G90.1")
   36 N..... COMMENT("interpreter: IJK distance mode changed to absolute")
   37 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   38 N..... ARC_FEED(0.0000, 20.0000, 0.0000, 10.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
   39 N..... COMMENT("interpreter: IJK distance mode changed to incremental")
   40 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   41 N..... SET_XY_ROTATION(0.0000)
   42 N..... SET_FEED_MODE(0, 0)
   43 N..... SET_FEED_RATE(0.0000)
   44 N..... STOP_SPINDLE_TURNING(0)
   45 N..... SET_SPINDLE_MODE(0 0.0000)
   46 N..... PROGRAM_END()
   47 N..... ON_RESET()
   48 N..... ON_RESET()
)";

TEST(Canon, ArcsInAllPlanes) {
  const std::vector<Event> ev = parseCanonText(kArcs);
  ASSERT_EQ(ev.size(), 12u);
  const Vec3 o(0, 0, 0);
  expectMove(ev, 0, Kind::Rapid, 0, o, o);
  expectMove(ev, 1, Kind::Feed, 0, o, Vec3(10, 0, 0), 300);
  expectArc(ev, 2, Plane::XY, false, 0, Vec3(10, 0, 0), Vec3(0, 10, 0), o, 10, 300);
  expectArc(ev, 3, Plane::XY, true, 0, Vec3(0, 10, 0), Vec3(10, 0, 0), o, 10, 300);
  expectArc(ev, 4, Plane::XY, true, 0, Vec3(10, 0, 0), Vec3(10, 0, 0), o, 10, 300);   // full
  expectArc(ev, 5, Plane::XY, false, 1, Vec3(10, 0, 0), Vec3(10, 0, -4), o, 10, 300); // P2
  expectMove(ev, 6, Kind::Feed, 0, Vec3(10, 0, -4), o, 300);
  // G18: ARC_FEED(Z, X, Zc, Xc, ...): G2 X10 Z0 I5 K0 from the origin, CW seen from +Y
  expectArc(ev, 7, Plane::ZX, true, 0, o, Vec3(10, 0, 0), Vec3(5, 0, 0), 5, 300);
  // G19: ARC_FEED(Y, Z, Yc, Zc, rot, X): G3 Y10 Z0 J5 K0 from (10,0,0)
  expectArc(ev, 8, Plane::YZ, false, 0, Vec3(10, 0, 0), Vec3(10, 10, 0), Vec3(10, 5, 0), 5, 300);
  expectMove(ev, 9, Kind::Rapid, 0, Vec3(10, 10, 0), o);
  expectArc(ev, 10, Plane::XY, false, 0, o, Vec3(0, 20, 0), Vec3(0, 10, 0), 10, 300);
  EXPECT_EQ(ev[11].kind, Kind::End);
}

// refs/linuxcnc/programs/11_offsets_units.ngc -> outputs/11_offsets_units.canon:
// G10 L2 P1 X100 Y50; G54; G0 X0 Y0 Z5; G10 L2 P2 X200 Y0 Z0 R30; G55; G0 X10 Y0;
// G92 X0 Y0; G0 X1 Y1; G92.1; G54; G20; G0 X1 Y1; G21; G0 X25.4 Y25.4; G52 X5 Y5; G0 X0 Y0
const char* const kOffsets = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... COMMENT("11: work offsets, G92, rotation, units; are canonical coords program or machine coordinates?")
    8 N..... SELECT_PLANE(CANON_PLANE_XY)
    9 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   10 N..... SET_G5X_OFFSET(1, 100.0000, 50.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   11 N..... SET_XY_ROTATION(0.0000)
   12 N..... COMMENT("interpreter: continuing to use same coordinate system")
   13 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   14 N..... COMMENT("interpreter: setting coordinate system origin")
   15 N..... SET_G5X_OFFSET(2, 200.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   16 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   17 N..... SET_XY_ROTATION(30.0000)
   18 N..... STRAIGHT_TRAVERSE(10.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   19 N..... SET_G92_OFFSET(10.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   20 N..... STRAIGHT_TRAVERSE(1.0000, 1.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   21 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   22 N..... SET_G5X_OFFSET(1, 100.0000, 50.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   23 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   24 N..... SET_XY_ROTATION(0.0000)
   25 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)
   26 N..... STRAIGHT_TRAVERSE(1.0000, 1.0000, 0.1969, 0.0000, 0.0000, 0.0000)
   27 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
   28 N..... STRAIGHT_TRAVERSE(25.4000, 25.4000, 5.0000, 0.0000, 0.0000, 0.0000)
   29 N..... SET_G92_OFFSET(5.0000, 5.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   30 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
   31 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   32 N..... SET_G5X_OFFSET(1, 100.0000, 50.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   33 N..... SET_XY_ROTATION(0.0000)
   34 N..... SET_FEED_MODE(0, 0)
   35 N..... SET_FEED_RATE(0.0000)
   36 N..... STOP_SPINDLE_TURNING(0)
   37 N..... SET_SPINDLE_MODE(0 0.0000)
   38 N..... PROGRAM_END()
   39 N..... ON_RESET()
   40 N..... ON_RESET()
)";

TEST(Canon, OffsetsRotationG92UnitsToMachineFrame) {
  const std::vector<Event> ev = parseCanonText(kOffsets);
  ASSERT_EQ(ev.size(), 7u);
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Vec3 a(100, 50, 5);                              // G54 (100,50) + (0,0,5)
  const Vec3 b(200 + 10 * c, 10 * s, 5);                 // G55 R30: Rot(10,0) + (200,0)
  const Vec3 d(200 + 11 * c - 1 * s, 11 * s + 1 * c, 5); // G92 (10,0): Rot(1+10, 1)
  const Vec3 e(125.4, 75.4, 0.1969 * 25.4);              // inches: (1, 1, 0.1969) in
  const Vec3 f(125.4, 75.4, 5);
  const Vec3 g(105, 55, 5); // G52 (5,5) = G92 offset
  expectMove(ev, 0, Kind::Rapid, 0, Vec3::Zero(), a);
  expectMove(ev, 1, Kind::Rapid, 0, a, b);
  expectMove(ev, 2, Kind::Rapid, 0, b, d);
  expectMove(ev, 3, Kind::Rapid, 0, d, e);
  expectMove(ev, 4, Kind::Rapid, 0, e, f);
  expectMove(ev, 5, Kind::Rapid, 0, f, g);
  EXPECT_EQ(ev[6].kind, Kind::End);
}

// refs/linuxcnc/programs/16h_comment_semicolon.ngc: `/G0 X99` (block delete off),
// `N5 G0 X1`, (msg,hello), (debug,value is #5220), M1, M2
const char* const kMessages = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N..... COMMENT("16h: semicolon comments, block delete /, optional stop M1, line numbers N, msg and debug comments")
    8 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    9 N..... STRAIGHT_TRAVERSE(99.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   10 N5     STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   11 N..... MESSAGE("hello")
   12 N..... MESSAGE("value is 1.000000")
   13 N..... OPTIONAL_PROGRAM_STOP()
   14 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   15 N..... SET_XY_ROTATION(0.0000)
   16 N..... SET_FEED_MODE(0, 0)
   17 N..... SET_FEED_RATE(0.0000)
   18 N..... STOP_SPINDLE_TURNING(0)
   19 N..... SET_SPINDLE_MODE(0 0.0000)
   20 N..... PROGRAM_END()
   21 N..... ON_RESET()
   22 N..... ON_RESET()
)";

TEST(Canon, MessagesStopsAndLineNumbers) {
  const std::vector<Event> ev = parseCanonText(kMessages);
  ASSERT_EQ(ev.size(), 6u);
  expectMove(ev, 0, Kind::Rapid, 0, Vec3::Zero(), Vec3(99, 0, 0));
  expectMove(ev, 1, Kind::Rapid, 5, Vec3(99, 0, 0), Vec3(1, 0, 0));
  EXPECT_EQ(ev[2].kind, Kind::Message);
  EXPECT_EQ(ev[2].text, "hello");
  EXPECT_EQ(ev[3].text, "value is 1.000000");
  EXPECT_EQ(ev[4].kind, Kind::Stop);
  EXPECT_TRUE(ev[4].optional);
  EXPECT_EQ(ev[5].kind, Kind::End);
}

// Run for this test: N1 G21 G90 F100 / N2 T7 M6 (T7 is the first table entry, pocket 3) /
// N3 M8 / N4 M7 / N5 M9 / N6 G95 F0.1 S500 M3 / N7 G1 X1 / N8 G93 G1 X2 F2 /
// N9 G94 G1 X3 F100 / N10 M4 S200 / N11 M5 / N12 G4 P1.5 / N13 M0 / N14 G20 /
// N15 G1 X1 F10 / N16 G43 H7 (Z4.0 in the table) / N17 G0 Z1 / N18 M2
const char* const kMachine = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N1     SET_FEED_RATE(100.0000)
    8 N1     USE_LENGTH_UNITS(CANON_UNITS_MM)
    9 N2     SELECT_TOOL(7)
   10 N2     START_CHANGE()
   11 N2     STOP_SPINDLE_TURNING(0)
   12 N2     CHANGE_TOOL(1)
   13 N3     FLOOD_ON()
   14 N4     MIST_ON()
   15 N5     MIST_OFF()
   16 N5     FLOOD_OFF()
   17 N6     COMMENT("interpreter: feed mode set to units per revolution")
   18 N6     SET_FEED_MODE(0, 1)
   19 N6     SET_FEED_RATE(0.0000)
   20 N6     SET_FEED_RATE(0.1000)
   21 N6     SET_SPINDLE_SPEED(0, 500.0000)
   22 N6     START_SPINDLE_CLOCKWISE(0)
   23 N7     STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   24 N8     COMMENT("interpreter: feed mode set to inverse time")
   25 N8     SET_FEED_MODE(0, 0)
   26 N8     SET_FEED_RATE(2.0000)
   27 N8     STRAIGHT_FEED(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   28 N9     COMMENT("interpreter: feed mode set to units per minute")
   29 N9     SET_FEED_MODE(0, 0)
   30 N9     SET_FEED_RATE(0.0000)
   31 N9     SET_FEED_RATE(100.0000)
   32 N9     STRAIGHT_FEED(3.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   33 N10    SET_SPINDLE_SPEED(0, 200.0000)
   34 N10    START_SPINDLE_COUNTERCLOCKWISE(0)
   35 N11    STOP_SPINDLE_TURNING(0)
   36 N12    DWELL(1.5000)
   37 N13    PROGRAM_STOP()
   38 N14    USE_LENGTH_UNITS(CANON_UNITS_INCHES)
   39 N15    SET_FEED_RATE(10.0000)
   40 N15    STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   41 N16    USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 4.0000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)
   42 N17    STRAIGHT_TRAVERSE(1.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000)
   43 N18    SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   44 N18    SET_XY_ROTATION(0.0000)
   45 N18    SET_FEED_MODE(0, 0)
   46 N18    SET_FEED_RATE(0.0000)
   47 N18    STOP_SPINDLE_TURNING(0)
   48 N18    SET_SPINDLE_MODE(0 0.0000)
   49 N18    PROGRAM_END()
   50 N..... ON_RESET()
   51 N..... ON_RESET()
)";

TEST(Canon, ToolSpindleCoolantFeedModesAndInches) {
  CanonReader reader;
  for (const char* p = kMachine; *p;) {
    const char* nl = std::strchr(p, '\n');
    reader.line(std::string_view(p, nl ? static_cast<std::size_t>(nl - p) : std::strlen(p)));
    p = nl ? nl + 1 : p + std::strlen(p);
  }
  ASSERT_EQ(reader.unsupported().size(), 1u); // the G93 move
  EXPECT_NE(reader.unsupported()[0].find("line 8: "), std::string::npos);
  EXPECT_NE(reader.unsupported()[0].find("inverse-time"), std::string::npos);
  const std::vector<Event> ev = reader.take();
  ASSERT_EQ(ev.size(), 15u);
  EXPECT_EQ(ev[0].kind, Kind::ToolChange);
  EXPECT_EQ(ev[0].value, 7); // from SELECT_TOOL, not CHANGE_TOOL's table index
  EXPECT_EQ(ev[0].from.at.line, 2u);
  EXPECT_EQ(ev[1].kind, Kind::Coolant);
  EXPECT_EQ(ev[1].value, 8);
  EXPECT_EQ(ev[2].value, 7);
  EXPECT_EQ(ev[3].kind, Kind::Coolant); // MIST_OFF + FLOOD_OFF = one M9
  EXPECT_EQ(ev[3].value, 9);
  EXPECT_EQ(ev[3].from.at.line, 5u);
  EXPECT_EQ(ev[4].kind, Kind::Spindle); // S500 M3: one event
  EXPECT_EQ(ev[4].value, 500);
  EXPECT_EQ(ev[4].direction, 1);
  expectMove(ev, 5, Kind::Feed, 7, Vec3::Zero(), Vec3(1, 0, 0), 0.1);
  EXPECT_TRUE(ev[5].perRevolution);
  expectMove(ev, 6, Kind::Feed, 8, Vec3(1, 0, 0), Vec3(2, 0, 0), 2); // G93: not modelled
  EXPECT_FALSE(ev[6].perRevolution);
  expectMove(ev, 7, Kind::Feed, 9, Vec3(2, 0, 0), Vec3(3, 0, 0), 100);
  EXPECT_EQ(ev[8].kind, Kind::Spindle);
  EXPECT_EQ(ev[8].value, 200);
  EXPECT_EQ(ev[8].direction, -1);
  EXPECT_EQ(ev[9].kind, Kind::Spindle);
  EXPECT_EQ(ev[9].direction, 0);
  EXPECT_EQ(ev[10].kind, Kind::Dwell);
  EXPECT_EQ(ev[10].value, 1.5);
  EXPECT_EQ(ev[11].kind, Kind::Stop);
  EXPECT_FALSE(ev[11].optional);
  expectMove(ev, 12, Kind::Feed, 15, Vec3(3, 0, 0), Vec3(25.4, 0, 0), 254); // F10 in/min
  // TLO 4 in = 101.6 mm is added to Z: program Z1 in -> machine 25.4 + 101.6
  expectMove(ev, 13, Kind::Rapid, 17, Vec3(25.4, 0, 0), Vec3(25.4, 0, 127));
  EXPECT_EQ(ev[14].kind, Kind::End);
}

TEST(Canon, SplitsLinesAndIgnoresOtherText) {
  CanonCall c;
  ASSERT_TRUE(
      splitCanonLine("   16 N123456STRAIGHT_TRAVERSE(0.0000, -0.0000, 1.5000, 0, 0, 0)", c));
  EXPECT_EQ(c.line, 123456u);
  EXPECT_EQ(c.name, "STRAIGHT_TRAVERSE");
  ASSERT_EQ(c.args.size(), 6u);
  EXPECT_EQ(c.args[1], "-0.0000");
  ASSERT_TRUE(splitCanonLine("   14 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 101.6000, 0.0000 "
                             "0.0000 0.0000, 0.0000 0.0000 0.0000)",
                             c));
  EXPECT_EQ(c.line, 0u);
  ASSERT_EQ(c.args.size(), 9u);
  EXPECT_EQ(c.args[2], "101.6000");
  ASSERT_TRUE(splitCanonLine("   11 N3     MESSAGE(\"a, b (c)\")", c));
  ASSERT_EQ(c.args.size(), 1u);
  EXPECT_EQ(c.args[0], "a, b (c)");
  EXPECT_FALSE(splitCanonLine(" x=0.000000 done", c)); // (print,...) output
  EXPECT_FALSE(splitCanonLine("", c));
  EXPECT_FALSE(splitCanonLine("    3 N..... BROKEN", c));

  const std::string program = "G21\nG0 X1\n  G1 X2\nG1 X3 Y4\n";
  CanonOptions opt;
  opt.programText = program;
  CanonReader r(opt);
  r.line(" body j=1.000000");
  r.line("    9 N4     STRAIGHT_FEED(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)");
  ASSERT_EQ(r.events().size(), 1u);
  EXPECT_EQ(r.events()[0].from.at.line, 4u);
  EXPECT_EQ(r.events()[0].from.at.col, 1u); // with programText: col 1 and the line's offset
  EXPECT_EQ(r.events()[0].from.at.offset, 18u);
  EXPECT_TRUE(r.unsupported().empty());
}

TEST(Canon, HelixAndRotatedArcCentres) {
  // G55 = (200, 0, 0) R90, G92 = (0, 0, 0): arc in XY about program (10, 0), helix Z 0 -> -3.
  const char* text =
      R"(    1 N..... SET_G5X_OFFSET(2, 200.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    2 N..... SET_XY_ROTATION(90.0000)
    3 N2     STRAIGHT_FEED(20.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N3     ARC_FEED(0.0000, 0.0000, 10.0000, 0.0000, -2, -3.0000, 0.0000, 0.0000, 0.0000)
)";
  CanonOptions opt;
  opt.file = 3;
  const std::vector<Event> ev = parseCanonText(text, opt);
  ASSERT_EQ(ev.size(), 2u);
  // program (20, 0) rotated 90 deg -> (0, 20), + (200, 0)
  expectMove(ev, 0, Kind::Feed, 2, Vec3::Zero(), Vec3(200, 20, 0));
  expectArc(ev, 1, Plane::XY, true, 1, Vec3(200, 20, 0), Vec3(200, 0, -3), Vec3(200, 10, 0), 10, 0);
  EXPECT_EQ(ev[1].from.at.file, 3u);
}

// Verbatim rs274 output for (each line numbered N1..N14):
//   G21 G90 G17 / G0 X0 Y0 Z0 A10 / G1 X10 B5 C-3 F100 / G2 X-10 Y0 I-10 J0 A180 F200 /
//   G92 A0 / G1 A20 / G10 L2 P1 A5 / G1 A30 / G20 / G1 X1 B30 / G21 / G92.1 / G0 A0 / M2
const char* const kRotary = R"(    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N..... SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    3 N..... SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
    4 N..... SET_XY_ROTATION(0.0000)
    5 N..... SET_FEED_REFERENCE(CANON_XYZ)
    6 N..... ON_RESET()
    7 N1     SELECT_PLANE(CANON_PLANE_XY)
    8 N1     USE_LENGTH_UNITS(CANON_UNITS_MM)
    9 N2     STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 10.0000, 0.0000, 0.0000)
   10 N3     SET_FEED_RATE(100.0000)
   11 N3     STRAIGHT_FEED(10.0000, 0.0000, 0.0000, 10.0000, 5.0000, -3.0000)
   12 N4     SET_FEED_RATE(200.0000)
   13 N4     ARC_FEED(-10.0000, 0.0000, 0.0000, 0.0000, -1, 0.0000, 180.0000, 5.0000, -3.0000)
   14 N5     SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 180.0000, 0.0000, 0.0000)
   15 N6     STRAIGHT_FEED(-10.0000, 0.0000, 0.0000, 20.0000, 5.0000, -3.0000)
   16 N7     SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 5.0000, 0.0000, 0.0000)
   17 N7     SET_XY_ROTATION(0.0000)
   18 N8     STRAIGHT_FEED(-10.0000, 0.0000, 0.0000, 30.0000, 5.0000, -3.0000)
   19 N9     USE_LENGTH_UNITS(CANON_UNITS_INCHES)
   20 N10    STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 30.0000, 30.0000, -3.0000)
   21 N11    USE_LENGTH_UNITS(CANON_UNITS_MM)
   22 N12    SET_G92_OFFSET(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)
   23 N13    STRAIGHT_TRAVERSE(25.4000, 0.0000, 0.0000, 0.0000, 30.0000, -3.0000)
   24 N14    SET_G5X_OFFSET(1, 0.0000, 0.0000, 0.0000, 5.0000, 0.0000, 0.0000)
   25 N14    SET_XY_ROTATION(0.0000)
   26 N14    SET_FEED_MODE(0, 0)
   27 N14    SET_FEED_RATE(0.0000)
   28 N14    STOP_SPINDLE_TURNING(0)
   29 N14    SET_SPINDLE_MODE(0 0.0000)
   30 N14    PROGRAM_END()
   31 N..... ON_RESET()
   32 N..... ON_RESET()
)";

TEST(Canon, RotaryAxesInDegreesWithTheirOffsets) {
  const std::vector<Event> ev = parseCanonText(kRotary);
  ASSERT_EQ(ev.size(), 8u);
  using E = motion::Extra;
  auto abc = [](double a, double b, double c) { return E((E() << a, b, c, 0, 0, 0).finished()); };
  const std::vector<std::pair<E, E>> want = {
      {abc(0, 0, 0), abc(10, 0, 0)},       // N2
      {abc(10, 0, 0), abc(10, 5, -3)},     // N3
      {abc(10, 5, -3), abc(180, 5, -3)},   // N4: the arc turns A too
      {abc(180, 5, -3), abc(200, 5, -3)},  // N6: A20 + G92 180
      {abc(200, 5, -3), abc(215, 5, -3)},  // N8: A30 + G92 180 + G54 5
      {abc(215, 5, -3), abc(215, 30, -3)}, // N10: degrees under G20 too
      {abc(215, 30, -3), abc(5, 30, -3)},  // N13: A0 + G54 5 after G92.1
  };
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(ev[i].extraStart, want[i].first)
        << "event " << i << ": " << ev[i].extraStart.transpose();
    EXPECT_EQ(ev[i].extraEnd, want[i].second)
        << "event " << i << ": " << ev[i].extraEnd.transpose();
  }
  expectArc(ev, 2, Plane::XY, true, 0, Vec3(10, 0, 0), Vec3(-10, 0, 0), Vec3(0, 0, 0), 10, 200);
  expectMove(ev, 5, Kind::Feed, 10, Vec3(-10, 0, 0), Vec3(25.4, 0, 0), 200);
  EXPECT_EQ(ev[7].kind, Kind::End);
  EXPECT_EQ(ev[7].extraStart, abc(5, 30, -3)); // non-motion events carry the position

  // Without a b c arguments the rotary axes stay where they are.
  CanonReader r;
  r.line("    1 N1     STRAIGHT_FEED(0.0000, 0.0000, 0.0000, 45.0000, 0.0000, 0.0000)");
  r.line("    2 N2     STRAIGHT_FEED(1.0000, 0.0000, 0.0000)");
  ASSERT_EQ(r.events().size(), 2u);
  EXPECT_EQ(r.events()[1].extraStart, abc(45, 0, 0));
  EXPECT_EQ(r.events()[1].extraEnd, abc(45, 0, 0));
  EXPECT_TRUE(r.unsupported().empty());
}

} // namespace
} // namespace gcx::oracle
