// Running rs274 for real (skipped when it is not installed): exact machine-frame motion of a
// few small programs, the frame bookkeeping check, errors, timeouts, parallel runs.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

#include "motion/describe.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "oracle/setup.h"

namespace gcx::oracle {
namespace {

using motion::Event;
using motion::Kind;
using motion::Plane;
using motion::Vec3;

constexpr double kEps = 1e-9;

#define SKIP_WITHOUT_RS274()                                                                       \
  if (!rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed"

void expectVec(const Vec3& got, const Vec3& want, double eps, const std::string& what) {
  EXPECT_NEAR(got.x(), want.x(), eps) << what << " x";
  EXPECT_NEAR(got.y(), want.y(), eps) << what << " y";
  EXPECT_NEAR(got.z(), want.z(), eps) << what << " z";
}

struct Want {
  Kind kind = Kind::End;
  std::uint32_t line = 0;
  std::array<double, 3> end{}; // not Vec3: `{}` must mean zero in the tables below
  std::array<double, 3> centre{};
  bool cw = false;
  Plane plane = Plane::XY;
  double feed = 0; // Feed/Arc; Dwell: seconds
};

void expectEvents(const std::vector<Event>& ev, const std::vector<Want>& want, double eps = kEps) {
  ASSERT_EQ(ev.size(), want.size());
  Vec3 pos = Vec3::Zero();
  for (std::size_t i = 0; i < ev.size(); ++i) {
    const std::string at = "event " + std::to_string(i) + " (" + motion::describeEvent(ev[i]) + ")";
    EXPECT_EQ(ev[i].kind, want[i].kind) << at;
    EXPECT_EQ(ev[i].from.at.line, want[i].line) << at;
    switch (want[i].kind) {
    case Kind::Rapid:
    case Kind::Feed:
    case Kind::Arc: {
      expectVec(ev[i].start, pos, eps, at + " start");
      const Vec3 end(want[i].end[0], want[i].end[1], want[i].end[2]);
      expectVec(ev[i].end, end, eps, at + " end");
      pos = end;
      if (want[i].kind != Kind::Rapid) {
        EXPECT_NEAR(ev[i].feed, want[i].feed, eps) << at;
      }
      if (want[i].kind == Kind::Arc) {
        expectVec(ev[i].center, Vec3(want[i].centre[0], want[i].centre[1], want[i].centre[2]), eps,
                  at + " centre");
        EXPECT_EQ(ev[i].clockwise, want[i].cw) << at;
        EXPECT_EQ(ev[i].plane, want[i].plane) << at;
      }
      break;
    }
    case Kind::Dwell:
      EXPECT_NEAR(ev[i].value, want[i].feed, eps) << at;
      break;
    default:
      break;
    }
  }
}

std::vector<Event> run(const Rs274& rs, const std::string& program) {
  const Rs274Result r = rs.run(program);
  EXPECT_TRUE(r.ok()) << r.summary();
  CanonReader reader;
  reader.lines(r.canonLines);
  EXPECT_TRUE(reader.unsupported().empty()) << reader.unsupported().front();
  return reader.take();
}

TEST(Rs274Text, NumberLines) {
  EXPECT_EQ(numberLines("G0 X1\n\n  G1 X2\n"), "N1 G0 X1\nN2 \nN3 G1 X2\n");
  EXPECT_EQ(numberLines("%\nN10 G0 X1\n/ N20 G1 X2\n/G1 X3\nn 30 M2\n%"),
            "%\nN2 G0 X1\n/N3 G1 X2\n/N4 G1 X3\nN5 M2\n%\n");
  EXPECT_EQ(numberLines("o100 sub\r\n"), "N1 o100 sub\r\n");
  EXPECT_EQ(numberLines(""), "");
}

TEST(Rs274Text, ToolTableAndParameterFileAreInInches) {
  const std::string tbl = toolTableText({{1, 101.6, 10}, {12, 50.8, 6.35}});
  EXPECT_EQ(tbl.substr(0, tbl.find(' ', tbl.find(" Z") + 1)), "T1 P1 D0.3937007874 Z4.0000000000");
  EXPECT_NE(tbl.find("T12 P12 D0.2500000000 Z2.0000000000"), std::string::npos) << tbl;

  OracleWorkOffset g55;
  g55.index = 2;
  g55.offsetMm = Vec3(254, -25.4, 0);
  g55.rotationDeg = 30;
  EXPECT_EQ(parameterFileText({g55}),
            "5220\t1.000000000000\n"
            "5241\t10.000000000000\n5242\t-1.000000000000\n5243\t0.000000000000\n"
            "5250\t30.000000000000\n");
}

TEST(Rs274Text, SetupJson) {
  OracleSetup s;
  std::string err;
  ASSERT_TRUE(parseSetupJson(
      R"({"work_offsets": {"G55": [1, 2, 3], "G59": [0, 0, -5.5]},
          "tools": {"1": {"length": 101.6, "radius": 5}, "12": {"length": 20}}})",
      s, err))
      << err;
  ASSERT_EQ(s.workOffsets.size(), 2u);
  EXPECT_EQ(s.workOffsets[0].index, 2);
  EXPECT_EQ(s.workOffsets[0].offsetMm, Vec3(1, 2, 3));
  EXPECT_EQ(s.workOffsets[1].index, 6);
  ASSERT_EQ(s.tools.size(), 2u);
  EXPECT_EQ(s.tools[0].number, 1);
  EXPECT_EQ(s.tools[0].lengthMm, 101.6);
  EXPECT_EQ(s.tools[0].diameterMm, 10);
  EXPECT_EQ(s.tools[1].number, 12);
  EXPECT_FALSE(parseSetupJson(R"({"work_offsets": {"G60": [1, 2, 3]}})", s, err));
  EXPECT_NE(err.find("G60"), std::string::npos);
  EXPECT_FALSE(parseSetupJson(R"({"work_offsets": {"G54": [1, 2]}})", s, err));
  EXPECT_FALSE(parseSetupJson(R"({"tools": {"x": {}}})", s, err));
  EXPECT_FALSE(parseSetupJson("{", s, err));
}

// The dialect sections of a shared setup are gcx's (docs/setup.md); the rapid rate is kept for
// the times equiv reports.
TEST(Rs274Text, SetupJsonSkipsDialectSectionsAndKeepsTheRapidRate) {
  OracleSetup s;
  std::string err;
  ASSERT_TRUE(parseSetupJson(
      R"({"nct": {"parameters": {"N1339": 1}}, "wl4": {"variables": {"#31": 2}},
          "rapid_rate": 5000})",
      s, err))
      << err;
  EXPECT_EQ(s.rapidRate, 5000);
  EXPECT_FALSE(parseSetupJson(R"({"nct": {"feed": 1}})", s, err));
  EXPECT_EQ(err, "setup JSON: unknown key 'nct'");
  EXPECT_FALSE(parseSetupJson(R"({"rapid_rate": 0})", s, err));
  EXPECT_EQ(err, "setup JSON: rapid_rate must be a number above 0");
}

TEST(Rs274Run, LinesArcsHelixDwellWithSourceLines) {
  SKIP_WITHOUT_RS274();
  const std::string program = "(oracle run 1: lines, arcs in three planes, helix, dwell)\n"
                              "G21 G90 G17 G94\n"
                              "G0 X10 Y0 Z5\n"
                              "G1 Z0 F200\n"
                              "G3 X0 Y10 I-10 J0\n"
                              "G2 X10 Y0 Z-2 R10\n"
                              "G4 P0.5\n"
                              "G18 G2 X30 Z-2 I10 K0 F300\n"
                              "G19 G3 Y0 Z8 J0 K5\n"
                              "G17 G0 Z20\n"
                              "M30\n";
  const std::vector<Event> ev = run(Rs274(), program);
  expectEvents(ev, {
                       {Kind::Rapid, 3, {10, 0, 5}},
                       {Kind::Feed, 4, {10, 0, 0}, {}, false, Plane::XY, 200},
                       {Kind::Arc, 5, {0, 10, 0}, {0, 0, 0}, false, Plane::XY, 200},
                       {Kind::Arc, 6, {10, 0, -2}, {0, 0, 0}, true, Plane::XY, 200},
                       {Kind::Dwell, 7, {}, {}, false, Plane::XY, 0.5},
                       {Kind::Arc, 8, {30, 0, -2}, {20, 0, -2}, true, Plane::ZX, 300},
                       {Kind::Arc, 9, {30, 0, 8}, {30, 0, 3}, false, Plane::YZ, 300},
                       {Kind::Rapid, 10, {30, 0, 20}},
                       {Kind::End, 11},
                   });
  EXPECT_NEAR(ev[3].startRadius, 10, kEps);
  EXPECT_NEAR(ev[3].endRadius, 10, kEps);
}

// The machine frame: work offsets (parameter file), tool length (tool table), G92 and the
// G10 L2 R rotation. rs274 prints program coordinates; when the frame changes, the
// interpreter re-expresses the unchanged physical position in the new frame, so the axes a
// move does not program show its idea of "machine -> program", which must be the inverse of
// ours (m = Rot(R)(p + g92) + g5x + tool).
TEST(Rs274Run, FramesMatchInterpreterBookkeeping) {
  SKIP_WITHOUT_RS274();
  Rs274Options opt;
  opt.tools = {{1, 101.6, 10}};
  OracleWorkOffset g54, g55;
  g54.index = 1;
  g54.offsetMm = Vec3(100, 50, -10);
  g55.index = 2;
  g55.offsetMm = Vec3(200, 0, 0);
  g55.rotationDeg = 30;
  opt.workOffsets = {g54, g55};
  const std::string program = "G21 G90 G17 G94\n" // 1
                              "G0 X1 Y2 Z3\n"     // 2
                              "G43 H1\n"          // 3
                              "G0 Z5\n"           // 4
                              "G92 X0 Y0\n"       // 5
                              "G55\n"             // 6
                              "G1 X10 F100\n"     // 7: Y and Z not programmed
                              "M2\n";             // 8
  const Rs274Result r = Rs274(opt).run(program);
  ASSERT_TRUE(r.ok()) << r.summary();

  CanonReader reader;
  bool checked = false;
  double printedY = 0;
  for (const std::string& line : r.canonLines) {
    CanonCall c;
    if (splitCanonLine(line, c) && c.name == "STRAIGHT_FEED" && c.line == 7) {
      // rs274's program coordinates of the current physical point vs. ours
      const Vec3 ours = reader.toProgramMm(reader.position());
      EXPECT_NEAR(std::stod(c.args[1]), ours.y(), 5e-5) << line;
      EXPECT_NEAR(std::stod(c.args[2]), ours.z(), 5e-5) << line;
      EXPECT_NEAR(ours.z(), -5, 1e-9); // 96.6 - 101.6 (tool) - 0 (G55 z)
      printedY = std::stod(c.args[1]);
      checked = true;
    }
    reader.line(line);
  }
  ASSERT_TRUE(checked);

  const std::vector<Event>& ev = reader.events();
  ASSERT_EQ(ev.size(), 4u);
  expectVec(ev[0].end, Vec3(101, 52, -7), kEps, "G54 rapid");
  expectVec(ev[1].end, Vec3(101, 52, 96.6), kEps, "G43 rapid"); // 5 - 10 + 101.6
  // G1 X10 in G55 (rotated 30 deg) with the G92 offset (1, 2, 0), Y as rs274 printed it:
  // m = Rot(30) * (p + g92) + g5x + tool
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const double x = 10 + 1, y = printedY + 2;
  expectVec(ev[2].end, Vec3(x * c - y * s + 200, x * s + y * c, -5 + 101.6), kEps, "G55 feed");
  EXPECT_NEAR(ev[2].start.z(), ev[2].end.z(), kEps); // physical Z unchanged by G55
  EXPECT_EQ(ev[3].kind, Kind::End);
}

TEST(Rs274Run, InchProgramWithWorkOffsetAndTool) {
  SKIP_WITHOUT_RS274();
  Rs274Options opt;
  OracleSetup setup;
  std::string err;
  ASSERT_TRUE(parseSetupJson(
      R"({"work_offsets": {"G55": [50.8, 25.4, 0]}, "tools": {"2": {"length": 50.8, "radius": 3}}})",
      setup, err))
      << err;
  applySetup(setup, opt);
  const std::string program = "G20 G90 G17 G94\n"   // 1
                              "G55 G0 X1 Y1 Z0.5\n" // 2
                              "G43 H2\n"            // 3
                              "G1 Z0 F10\n"         // 4
                              "G2 X2 Y2 I0 J1\n"    // 5
                              "G21 G0 Z25.4\n"      // 6
                              "M2\n";               // 7
  expectEvents(run(Rs274(opt), program),
               {
                   {Kind::Rapid, 2, {76.2, 50.8, 12.7}},
                   {Kind::Feed, 4, {76.2, 50.8, 50.8}, {}, false, Plane::XY, 254},
                   {Kind::Arc, 5, {101.6, 76.2, 50.8}, {76.2, 76.2, 50.8}, true, Plane::XY, 254},
                   {Kind::Rapid, 6, {101.6, 76.2, 76.2}},
                   {Kind::End, 7},
               });
}

TEST(Rs274Run, ErrorKeepsThePrefixAndTheMessage) {
  SKIP_WITHOUT_RS274();
  const Rs274Result r = Rs274().run("G21 G90\nG0 X10\nG1 X20 F100\nG2 X20.1 Y0 I5 J0\nM2\n");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(r.timedOut);
  EXPECT_NE(r.stderrText.find("Radius to end of arc differs from radius to start"),
            std::string::npos)
      << r.stderrText;
  EXPECT_NE(r.stderrText.find("N4 G2 X20.1"), std::string::npos) << r.stderrText;
  EXPECT_NE(r.summary().find("exit code 1: Radius to end of arc"), std::string::npos)
      << r.summary();
  const std::vector<Event> ev = parseCanon(r.canonLines);
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[1].from.at.line, 3u);
}

TEST(Rs274Run, TimeoutKillsTheRun) {
  SKIP_WITHOUT_RS274();
  Rs274Options opt;
  opt.timeoutSeconds = 0.5;
  const auto t0 = std::chrono::steady_clock::now();
  const Rs274Result r = Rs274(opt).run("#1 = 0\no100 while [#1 LT 1]\n#2 = 1\no100 endwhile\nM2\n");
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.timedOut) << r.summary();
  EXPECT_FALSE(r.ok());
  EXPECT_LT(secs, 5.0);
}

TEST(Rs274Run, MissingExecutableIsAnError) {
  Rs274Options opt;
  opt.executable = "/nonexistent/rs274";
  const Rs274Result r = Rs274(opt).run("M2\n");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.summary().find("could not run rs274"), std::string::npos);
}

TEST(Rs274Run, ParallelRunsAreIndependent) {
  SKIP_WITHOUT_RS274();
  // Different tool lengths in each thread: a shared HOME/.tool.mmap or var file would mix them.
  std::vector<double> z(4, 0);
  std::vector<std::string> errors(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &z, &errors] {
      Rs274Options opt;
      opt.tools = {{1, 25.4 * (t + 1), 6}};
      const Rs274Result r = Rs274(opt).run("G21 G90\nG43 H1\nG0 Z1\nM2\n");
      if (!r.ok()) errors[t] = r.summary();
      const std::vector<Event> ev = parseCanon(r.canonLines);
      if (!ev.empty()) z[t] = ev[0].end.z();
    });
  for (std::thread& th : threads)
    th.join();
  for (int t = 0; t < 4; ++t) {
    EXPECT_TRUE(errors[t].empty()) << errors[t];
    EXPECT_NEAR(z[t], 1 + 25.4 * (t + 1), kEps) << "thread " << t;
  }
}

// The oracle chain end to end: the same path split differently compares equal; a changed
// arc is reported with both source lines.
TEST(Rs274Run, CompareTwoRealRuns) {
  SKIP_WITHOUT_RS274();
  const Rs274 rs;
  const std::vector<Event> a = run(rs, "G21 G90 G17\nG0 X0 Y0 Z1\nG1 X30 Y15 F300\n"
                                       "G3 X10 Y35 R20\nG0 Z5\nM2\n");
  const std::vector<Event> b = run(rs, "G21 G90 G17\nG0 X0 Y0 Z1\nG1 X10 Y5 F300\n"
                                       "G1 X20 Y10\nX30 Y15\nG3 X10 Y35 R20\nG0 Z5\nM2\n");
  const std::string textC = "G21 G90 G17\nG0 X0 Y0 Z1\nG1 X30 Y15 F300\n"
                            "G3 X10 Y35 R-20\nG0 Z5\nM2\n";
  SourceManager sources;
  CanonOptions copt;
  copt.file = sources.addBuffer("c.ngc", textC);
  copt.programText = textC;
  const Rs274Result rc = rs.run(textC);
  ASSERT_TRUE(rc.ok()) << rc.summary();
  CanonReader reader(copt);
  reader.lines(rc.canonLines);
  const std::vector<Event> c = reader.take();
  CompareOptions opt;
  opt.rightSources = &sources;
  opt.leftName = "a";
  opt.rightName = "b";
  const CompareResult ab = compareEvents(a, b, opt);
  EXPECT_TRUE(ab.equivalent) << ab.report;
  const CompareResult ac = compareEvents(a, c, opt);
  ASSERT_FALSE(ac.equivalent);
  EXPECT_NE(ac.report.find("arc centres differ"), std::string::npos) << ac.report;
  EXPECT_NE(ac.report.find("line 4"), std::string::npos) << ac.report;
  EXPECT_NE(ac.report.find("c.ngc:4:1 \"G3 X10 Y35 R-20\""), std::string::npos) << ac.report;
}

} // namespace
} // namespace gcx::oracle
