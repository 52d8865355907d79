#include "motion/stats.h"

#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>

#include "motion/event_builders.h"

namespace gcx::motion {
namespace {

constexpr double pi = std::numbers::pi;
using namespace test;

Event spindle(double rpm, int direction) {
  Event e = valueEvent(Kind::Spindle, rpm);
  e.direction = direction;
  return e;
}

std::vector<Event> program() {
  Event perRev = feed({40, 50, -5}, {50, 50, -5}, 0.1);
  perRev.perRevolution = true;
  Event stalled = feed({50, 50, -5}, {50, 60, -5}, 0.1);
  stalled.perRevolution = true;
  return {
      spindle(1000, 1),
      valueEvent(Kind::ToolChange, 1),
      rapid({0, 0, 0}, {30, 40, 0}),                                          // 50 mm, 0.6 s
      feed({30, 40, 0}, {30, 40, -5}, 100),                                   // 5 mm, 3 s
      arc(Plane::XY, {30, 40, -5}, {40, 50, -5}, {40, 40, -5}, true, 0, 200), // 5π mm, 1.5π s
      perRev,                           // 10 mm at 0.1 mm/rev · 1000 rpm: 6 s
      valueEvent(Kind::Dwell, 2),       // 2 s
      valueEvent(Kind::Dwell, 5, true), // 5 rev at 1000 rpm: 0.3 s
      valueEvent(Kind::ToolChange, 2),
      spindle(1000, 0),
      stalled, // per revolution with the spindle stopped: 10 mm, no time
  };
}

TEST(Stats, LengthsTimesAndCounts) {
  StatsCollector c;
  for (const Event& e : program())
    c.event(e);
  const Stats& s = c.stats();
  EXPECT_EQ(s.rapidMoves, 1u);
  EXPECT_EQ(s.feedMoves, 3u);
  EXPECT_EQ(s.arcMoves, 1u);
  EXPECT_NEAR(s.rapidLength, 50, 1e-12);
  EXPECT_NEAR(s.feedLength, 25 + 5 * pi, 1e-12);
  EXPECT_NEAR(s.arcLength, 5 * pi, 1e-12);
  EXPECT_NEAR(s.totalLength(), 75 + 5 * pi, 1e-12);
  EXPECT_NEAR(s.rapidSeconds, 0.6, 1e-12);
  EXPECT_NEAR(s.feedSeconds, 9 + 1.5 * pi, 1e-12);
  EXPECT_NEAR(s.dwellSeconds, 2.3, 1e-12);
  EXPECT_NEAR(s.totalSeconds(), 11.9 + 1.5 * pi, 1e-12);
  EXPECT_EQ(s.dwells, 2u);
  EXPECT_EQ(s.toolChanges, 2u);
  EXPECT_EQ(s.untimed, 1u);
  EXPECT_EQ(s.bounds.min(), Vec3(0, 0, -5));
  EXPECT_EQ(s.bounds.max(), Vec3(50, 60, 0));
}

TEST(Stats, RapidRateIsConfigurable) {
  StatsCollector c(StatsOptions{10000});
  c.event(rapid({0, 0, 0}, {30, 40, 0}));
  EXPECT_NEAR(c.stats().rapidSeconds, 0.3, 1e-12);
}

TEST(Stats, BoundsOfACircleIncludeItsBulge) {
  StatsCollector c;
  c.event(arc(Plane::XY, {15, 5, -1}, {15, 5, -1}, {5, 5, -1}, false));
  const Box3& b = c.stats().bounds;
  EXPECT_NEAR(b.min().x(), -5, 1e-12);
  EXPECT_NEAR(b.min().y(), -5, 1e-12);
  EXPECT_NEAR(b.max().x(), 15, 1e-12);
  EXPECT_NEAR(b.max().y(), 15, 1e-12);
  EXPECT_EQ(b.min().z(), -1);
  EXPECT_EQ(b.max().z(), -1);
}

TEST(Stats, JsonAndReport) {
  StatsCollector c;
  for (const Event& e : program())
    c.event(e);
  const nlohmann::json j = toJson(c.stats());
  EXPECT_EQ(j["moves"]["feed"], 3);
  EXPECT_EQ(j["moves"]["rotary"], 0);
  EXPECT_EQ(j["length_mm"]["rapid"], 50.0);
  EXPECT_EQ(j["length_mm"]["arc"], 15.707963);
  EXPECT_EQ(j["time_s"]["dwell"], 2.3);
  EXPECT_EQ(j["tool_changes"], 2);
  EXPECT_EQ(j["untimed"], 1);
  EXPECT_EQ(j["bounds"]["max"], nlohmann::json::array({50.0, 60.0, 0.0}));

  const std::string r = formatReport(c.stats());
  EXPECT_NE(
      r.find("length        rapid 50.000 mm, feed 40.708 mm (arcs 15.708 mm), total 90.708 mm"),
      std::string::npos)
      << r;
  EXPECT_NE(r.find("tool changes  2\n"), std::string::npos) << r;
  EXPECT_NE(r.find("untimed       1 "), std::string::npos) << r;
  EXPECT_NE(r.find("bounds        X 0.000 .. 50.000, Y 0.000 .. 60.000, Z -5.000 .. 0.000"),
            std::string::npos)
      << r;

  EXPECT_TRUE(toJson(Stats{})["bounds"].is_null());
}

TEST(Stats, RotaryOnlyMovesTakeAngleOverFeed) {
  StatsCollector c;
  Event perRev = withExtra(feed({10, 0, 0}, {10, 0, 0}, 2), extra(90, 0, 0), extra(90, 30, 40));
  perRev.perRevolution = true;
  Event plane = valueEvent(Kind::PlaneChange, 0);
  plane.plane = Plane::ZX;
  for (const Event& e : {
           spindle(600, 1),
           withExtra(rapid({0, 0, 0}, {0, 0, 0}), Extra::Zero(), extra(-45, 0, 0)), // no time
           withExtra(feed({0, 0, 0}, {0, 0, 0}, 120), extra(-45, 0, 0),
                     extra(90, 0, 0)), // 135°: 67.5 s
           withExtra(feed({0, 0, 0}, {10, 0, 0}, 100), extra(90, 0, 0), extra(90, 0, 0)), // 6 s
           plane,
           valueEvent(Kind::UnitsChange, 20),
           valueEvent(Kind::FeedModeChange, 95),
           perRev, // |(0, 30, 40)| = 50° at 2°/rev · 600 rpm: 2.5 s
           // X and A together: the time follows the X Y Z length (6 s); not rotary only
           withExtra(feed({10, 0, 0}, {20, 0, 0}, 100), extra(90, 30, 40), extra(0, 30, 40)),
           // U V W moved too: not rotary only, |(10°, 5 mm)| / F = 6.708204 s
           withExtra(feed({20, 0, 0}, {20, 0, 0}, 100), extra(0, 30, 40),
                     extra(10, 30, 40, 0, 0, 5)),
       })
    c.event(e);
  const Stats& s = c.stats();
  EXPECT_EQ(s.rapidMoves, 1u);
  EXPECT_EQ(s.feedMoves, 5u);
  EXPECT_EQ(s.rotaryMoves, 3u);
  EXPECT_EQ(s.rapidLength, 0);
  EXPECT_NEAR(s.feedLength, 20, 1e-12);
  EXPECT_EQ(s.rapidSeconds, 0);
  EXPECT_NEAR(s.feedSeconds, 67.5 + 6 + 2.5 + 6 + std::sqrt(125.0) * 0.6, 1e-12);
  EXPECT_EQ(s.untimed, 0u);
  EXPECT_EQ(toJson(s)["moves"]["rotary"], 3);
  const std::string r = formatReport(s);
  EXPECT_NE(r.find("moves         rapid 1, feed 5, arc 0 (3 rotary only)\n"), std::string::npos)
      << r;
  EXPECT_EQ(formatReport(Stats{}).find("rotary"), std::string::npos);

  StatsCollector f0;
  f0.event(withExtra(feed({0, 0, 0}, {0, 0, 0}, 0), Extra::Zero(), extra(0, 0, 90)));
  EXPECT_EQ(f0.stats().untimed, 1u);
}

} // namespace
} // namespace gcx::motion
