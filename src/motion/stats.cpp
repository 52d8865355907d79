#include "motion/stats.h"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace gcx::motion {

namespace {
/// A line that moves no X Y Z: F applies to the extra axes (nct.md §3.4), so it takes their
/// travel (degrees, and mm of U V W) over F. 0 for other moves.
double extraOnlyTravel(const Event& e, double length) {
  return length == 0 ? (e.extraEnd - e.extraStart).norm() : 0;
}
/// Whether a line turns rotary axes and moves nothing else.
bool rotaryOnly(const Event& e, double length) {
  const Extra d = e.extraEnd - e.extraStart;
  return length == 0 && (d.head<3>().array() != 0).any() && (d.tail<3>().array() == 0).all();
}
} // namespace

StatsCollector::StatsCollector(StatsOptions opt) : opt_(opt) {}

void StatsCollector::addFeedTime(const Event& e, double length) {
  const double mmPerMin = e.perRevolution ? e.feed * spindleRpm_ : e.feed;
  if (mmPerMin > 0)
    stats_.feedSeconds += length / mmPerMin * 60;
  else if (length > 0)
    ++stats_.untimed;
}

void StatsCollector::event(const Event& e) {
  switch (e.kind) {
  case Kind::Rapid: {
    const double len = pathLength(e);
    stats_.bounds.extend(e.start).extend(e.end);
    ++stats_.rapidMoves;
    if (rotaryOnly(e, len)) ++stats_.rotaryMoves;
    stats_.rapidLength += len;
    if (opt_.rapidRate > 0) stats_.rapidSeconds += len / opt_.rapidRate * 60;
    break;
  }
  case Kind::Feed: {
    const double len = pathLength(e);
    stats_.bounds.extend(e.start).extend(e.end);
    ++stats_.feedMoves;
    stats_.feedLength += len;
    if (rotaryOnly(e, len)) ++stats_.rotaryMoves;
    addFeedTime(e, len > 0 ? len : extraOnlyTravel(e, len));
    break;
  }
  case Kind::Arc: {
    const ArcGeometry g(e);
    const double len = g.length();
    stats_.bounds.extend(g.bounds());
    ++stats_.arcMoves;
    stats_.feedLength += len;
    stats_.arcLength += len;
    addFeedTime(e, len);
    break;
  }
  case Kind::Dwell:
    ++stats_.dwells;
    if (!e.perRevolution)
      stats_.dwellSeconds += e.value;
    else if (spindleRpm_ > 0)
      stats_.dwellSeconds += e.value / spindleRpm_ * 60;
    else
      ++stats_.untimed;
    break;
  case Kind::Spindle:
    spindleRpm_ = e.direction == 0 ? 0 : std::abs(e.value);
    break;
  case Kind::ToolChange:
    ++stats_.toolChanges;
    break;
  case Kind::SpindleOrient:
  case Kind::OverrideLock:
  case Kind::RadiusComp:
  case Kind::Coolant:
  case Kind::Stop:
  case Kind::End:
  case Kind::Message:
  case Kind::PlaneChange:
  case Kind::UnitsChange:
  case Kind::FeedModeChange:
    break;
  }
}

namespace {
std::string clock(double seconds) {
  const auto s = static_cast<long long>(std::llround(seconds));
  return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
}
double round6(double v) {
  return std::round(v * 1e6) / 1e6 + 0.0;
} // + 0.0 drops -0
} // namespace

std::string formatReport(const Stats& s) {
  std::string out;
  out +=
      fmt::format("moves         rapid {}, feed {}, arc {}", s.rapidMoves, s.feedMoves, s.arcMoves);
  if (s.rotaryMoves > 0) out += fmt::format(" ({} rotary only)", s.rotaryMoves);
  out += '\n';
  out += fmt::format(
      "length        rapid {:.3f} mm, feed {:.3f} mm (arcs {:.3f} mm), total {:.3f} mm\n",
      s.rapidLength, s.feedLength, s.arcLength, s.totalLength());
  out += fmt::format("time          rapid {:.3f} s, feed {:.3f} s, dwell {:.3f} s, total {:.3f} s "
                     "({})\n",
                     s.rapidSeconds, s.feedSeconds, s.dwellSeconds, s.totalSeconds(),
                     clock(s.totalSeconds()));
  out += fmt::format("tool changes  {}\n", s.toolChanges);
  if (s.untimed > 0)
    out += fmt::format("untimed       {} (F0, or per-revolution with the spindle stopped)\n",
                       s.untimed);
  if (s.bounds.isEmpty()) {
    out += "bounds        (no motion)\n";
  } else {
    const Vec3 lo = s.bounds.min(), hi = s.bounds.max();
    out += fmt::format("bounds        X {:.3f} .. {:.3f}, Y {:.3f} .. {:.3f}, Z {:.3f} .. {:.3f}\n",
                       lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z());
  }
  return out;
}

nlohmann::json toJson(const Stats& s) {
  using nlohmann::json;
  auto vec = [](const Vec3& v) {
    return json::array({round6(v.x()), round6(v.y()), round6(v.z())});
  };
  json j;
  j["moves"] = {{"rapid", s.rapidMoves},
                {"feed", s.feedMoves},
                {"arc", s.arcMoves},
                {"rotary", s.rotaryMoves}};
  j["length_mm"] = {{"rapid", round6(s.rapidLength)},
                    {"feed", round6(s.feedLength)},
                    {"arc", round6(s.arcLength)},
                    {"total", round6(s.totalLength())}};
  j["time_s"] = {{"rapid", round6(s.rapidSeconds)},
                 {"feed", round6(s.feedSeconds)},
                 {"dwell", round6(s.dwellSeconds)},
                 {"total", round6(s.totalSeconds())}};
  j["dwells"] = s.dwells;
  j["tool_changes"] = s.toolChanges;
  j["untimed"] = s.untimed;
  j["bounds"] = s.bounds.isEmpty()
                    ? json(nullptr)
                    : json{{"min", vec(s.bounds.min())}, {"max", vec(s.bounds.max())}};
  return j;
}

} // namespace gcx::motion
