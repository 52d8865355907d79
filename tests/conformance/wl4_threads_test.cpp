// Thread motion G32 / G33 (wl4.md §3.6), the %1 threading cycle G31 (§5.5, TV18), the arc of
// TV3 (§3.4: a radius difference within the tolerance stays a circle) and a lathe's diameter
// X (§0.2, TV19). Thread moves are written "TH x,y,z K<lead along Z>": the canonical output's
// G33 K.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sstream>

#include "emit/canonical.h"
#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

std::vector<std::string> withThreads(const MacroRun& r) {
  std::vector<std::string> out;
  for (const motion::Event& e : r.events) {
    if (e.kind == motion::Kind::PlaneChange || e.kind == motion::Kind::UnitsChange ||
        e.kind == motion::Kind::FeedModeChange)
      continue;
    if (e.kind == motion::Kind::Feed && e.lead > 0)
      out.push_back("TH " + n4(e.end.x()) + "," + n4(e.end.y()) + "," + n4(e.end.z()) + " K" +
                    n4(e.lead));
    else
      out.push_back(describe(e));
  }
  return out;
}

machine::Setup lathe() {
  machine::Setup s;
  s.parameters["lathe"] = 1; // machine.kind = lathe: X and U are diameters (§0.2)
  return s;
}

TEST(Wl4Vectors_8, TV3_AnArcByIJAndTheSameArcByRAreOneCircle) {
  MacroRun r = runWl4("%TV3\nG90G54G17G1X-50Y86.603F100\nG2X0Y100I50J-86.603\n"
                      "G1X-50Y86.603\nG2X0Y100R100\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  std::vector<const motion::Event*> arcs;
  for (const motion::Event& e : r.events)
    if (e.kind == motion::Kind::Arc) arcs.push_back(&e);
  ASSERT_EQ(arcs.size(), 2u) << r.rendered;
  for (const motion::Event* a : arcs) {
    EXPECT_TRUE(a->clockwise);
    EXPECT_EQ(n4(a->end.x()) + "," + n4(a->end.y()), "0,100");
    // the centre from I J, and from R within 0.001 of it
    EXPECT_NEAR(a->center.x(), 0, 1e-3);
    EXPECT_NEAR(a->center.y(), 0, 1e-3);
    // |CS| = 100.0002, |CE| = 100: within 0.002 mm the arc is the circle, not a spiral
    EXPECT_EQ(a->startRadius, a->endRadius);
  }
  std::ostringstream out;
  emit::CanonicalEmitter canonical(out);
  canonical.event(*arcs[0]);
  canonical.finish();
  EXPECT_NE(out.str().find("G2 X0 Y100 Z0 I50 J-86.603 F100\n"), std::string::npos) << out.str();
}

TEST(Wl4Vectors_8, TV19_TheChamferOnALatheWithXAsADiameter) {
  machine::Setup s = lathe();
  s.parameters["b_chamfer"] = 1;
  MacroRun r = runWl4("%TV19\nG18 G90 G95 G0 X40 Z70\nG1 X100 F0.2 B10\nZ10\nM2\n%\n", s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // the spec's X80 Z70, X100 Z60, X100 Z10 as radii (the motion stream and LinuxCNC's G8)
  EXPECT_EQ(r.motion(),
            (V{"R 20,0,70", "L 40,0,70 F0.2", "L 50,0,60 F0.2", "L 50,0,10 F0.2", "END"}));
}

TEST(Wl4Motion_0_2, OnALatheXAndUAreDiametersAndIARadius) {
  MacroRun r = runWl4("%P\nG18 G90 G0 X100 Z86.603\nG2 X0 Z100 I-50 K-86.603 F0.2\n"
                      "G0 U20\nM2\n%\n",
                      lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // I-50 is a radius: the centre (0,0), |CS| = 100.0004 and |CE| = 100 within the tolerance
  EXPECT_EQ(r.motion(),
            (V{"R 50,0,86.603", "CW 0,0,100 C0,0 r100.0004->100 θ29.9999", "R 10,0,100", "END"}));
  for (const motion::Event& e : r.events)
    if (e.kind == motion::Kind::Arc) {
      EXPECT_EQ(e.startRadius, e.endRadius); // the circle
    }
}

TEST(Wl4Threads_3_6, G32IsASynchronisedLineWithFTheLead) {
  MacroRun r =
      runWl4("%P\nG18 G90 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5\nX24 Z-22\nG0 X40\nM2\n%\n", lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // the second block travels 1 on X (radius) and 2 on Z: F leads Z, the longer one
  EXPECT_EQ(withThreads(r), (V{"EV S500 M3", "R 10,0,5", "TH 10,0,-20 K1.5", "TH 12,0,-22 K1.5",
                               "R 20,0,-22", "END"}));
}

TEST(Wl4Threads_3_6, FLeadsTheLongerAxisAndAfterTheSequenceANewFActs) {
  MacroRun r = runWl4("%P\nG18 G90 G0 X0 Z0 S500 M3\nG32 X8 Z-2 F2\nZ-10 F3 G9\nG1 X20 Z-11\n"
                      "G32 Z-20 G9\nG0 X30\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // X travels 8, Z 2: F2 is the lead along X, so Z advances 0.5 per revolution; the F3 of the
  // sequence's second block waits for its end, then feeds G1 and leads the next sequence
  EXPECT_EQ(withThreads(r), (V{"EV S500 M3", "TH 8,0,-2 K0.5", "TH 8,0,-10 K2", "L 20,0,-11 F3",
                               "TH 20,0,-20 K3", "R 30,0,-20", "END"}));
}

TEST(Wl4Threads_3_6, G33ThreadsOutReversesTheSpindleAndThreadsBack) {
  MacroRun r = runWl4("%P\nG17 G90 G0 X10 Y10 Z5 S300 M3\nG33 Z-20 F1.25\nG0 Z30\nM2\n%\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withThreads(r), (V{"EV S300 M3", "R 10,10,5", "TH 10,10,-20 K1.25", "EV S300 M4",
                               "TH 10,10,5 K1.25", "EV S300 M3", "R 10,10,30", "END"}));
}

TEST(Wl4Threads_3_6, WhatTheCanonicalThreadCannotSayIsALocatedError) {
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5 P90\nM2\n%\n")),
            (V{"3:15 GCX066"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20 F1.5 I0.01\nM2\n%\n")),
            (V{"3:15 GCX066"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 X30 F1.5\nM2\n%\n")),
            (V{"3:1 GCX066"}));
  EXPECT_EQ(errorsAt(runWl4("%P\nG18 G0 X20 Z5 S500 M3\nG32 Z-20\nM2\n%\n")), (V{"3:1 2004"}));
}

// TV18's thread from A = X30 Z5 on the lathe, with the flank infeed angle #4
MacroRun tv18(int infeed) {
  return runWl4(fmt::format("%TV18\nG18 G90\nG0 X30 Z5\n"
                            "G31 X24 Z-20 F1.5 P0 I0 #1=1 #2=0.25 #3=0 #4={} #5=1.5\nM2\n%\n",
                            infeed),
                lathe());
}

TEST(Wl4OpenCycles_8, TV18_G31ThreadsInNinePasses) {
  MacroRun r = tv18(0);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V expected{"R 15,0,5"};
  // the spec's diameters: X words from variables round to 0.001 (§6.1), 22.0625 to 22.063
  for (double x : {24.0, 23.5, 23.0, 22.5, 22.25, 22.125, 22.063, 22.0, 22.0}) {
    expected.push_back("R " + n4(x / 2) + ",0,5");
    expected.push_back("TH " + n4(x / 2) + ",0,-18.5 K1.5");
    expected.push_back("TH " + n4((x + 3) / 2) + ",0,-20 K1.5"); // the 45° run-out
    expected.push_back("R 15,0,-20");
    expected.push_back("R 15,0,5");
  }
  expected.push_back("END");
  EXPECT_EQ(withThreads(r), expected);
}

TEST(Wl4OpenCycles_5_5, G31WithAFlankInfeedShiftsEachPassStart) {
  MacroRun r = tv18(30);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  std::vector<std::string> starts; // the Z of each pass's approach (§5.5: 3.268 ... 2.691)
  const std::vector<std::string> all = withThreads(r);
  for (std::size_t i = 1; i + 1 < all.size(); ++i)
    if (all[i].starts_with("TH") && all[i - 1].starts_with("R ") && !all[i - 1].ends_with(",5") &&
        !all[i - 1].ends_with(",-20"))
      starts.push_back(all[i - 1].substr(all[i - 1].rfind(',') + 1));
  // Z words from variables round to 0.001 (§6.1): the spec's values exactly
  EXPECT_EQ(starts,
            (V{"3.268", "3.124", "2.979", "2.835", "2.763", "2.727", "2.709", "2.691", "2.691"}));
}

TEST(Wl4OpenCycles_5_5, G31WithATaperWidensAnExternalThreadTowardItsEnd) {
  // worked by hand through §5.4 (its restored signs: #18 = -1 outside, #14 = #20 - #22*#18):
  // #3 = 1 on the diameter over the 25 mm from A's Z to the end, no run-out; #1 = 0 leaves the
  // zero-cut pass and the spring pass, each from X24 at Z5 to X25 at Z-20
  MacroRun r = runWl4("%P\nG18 G90\nG0 X30 Z5\n"
                      "G31 X24 Z-20 F1.5 P0 I0 #1=0 #2=0.25 #3=1 #4=0 #5=0\nM2\n%\n",
                      lathe());
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withThreads(r),
            (V{"R 15,0,5", "R 12,0,5", "TH 12.5,0,-20 K1.5", "R 15,0,-20", "R 15,0,5", "R 12,0,5",
               "TH 12.5,0,-20 K1.5", "R 15,0,-20", "R 15,0,5", "END"}));
}

} // namespace
} // namespace gcx::test
