#include "motion/describe.h"

#include <fmt/format.h>

#include <cmath>

#include "motion/geometry.h"

namespace gcx::motion {

namespace {

/// No "-0.0000" for a value that rounds to zero.
double z(double d) {
  return std::abs(d) < 5e-5 ? 0.0 : d;
}

std::string fmtVec(const Vec3& v) {
  return fmt::format("({:.4f}, {:.4f}, {:.4f})", z(v.x()), z(v.y()), z(v.z()));
}

/// " A 0.0000 -> 90.0000" for each extra axis off zero at either end of a move.
std::string fmtExtra(const Event& e) {
  std::string s;
  for (int i = 0; i < 6; ++i)
    if (e.extraStart[i] != 0 || e.extraEnd[i] != 0)
      s += fmt::format(" {} {:.4f} -> {:.4f}", kExtraAxisNames[i], z(e.extraStart[i]),
                       z(e.extraEnd[i]));
  return s;
}

} // namespace

const char* kindLabel(Kind k) {
  switch (k) {
  case Kind::Rapid:
    return "Rapid";
  case Kind::Feed:
    return "Feed";
  case Kind::Arc:
    return "Arc";
  case Kind::Dwell:
    return "Dwell";
  case Kind::Spindle:
    return "Spindle";
  case Kind::SpindleOrient:
    return "SpindleOrient";
  case Kind::OverrideLock:
    return "OverrideLock";
  case Kind::RadiusComp:
    return "RadiusComp";
  case Kind::ToolChange:
    return "ToolChange";
  case Kind::Coolant:
    return "Coolant";
  case Kind::Stop:
    return "Stop";
  case Kind::End:
    return "End";
  case Kind::Message:
    return "Message";
  case Kind::PlaneChange:
    return "PlaneChange";
  case Kind::UnitsChange:
    return "UnitsChange";
  case Kind::FeedModeChange:
    return "FeedModeChange";
  }
  return "?";
}

std::string describeEvent(const Event& e) {
  const std::string feed = fmt::format(" F{}{}", e.feed, e.perRevolution ? "/rev" : "");
  switch (e.kind) {
  case Kind::Rapid:
    return fmt::format("Rapid {} -> {}{}", fmtVec(e.start), fmtVec(e.end), fmtExtra(e));
  case Kind::Feed:
    return fmt::format("Feed {} -> {}{}{}", fmtVec(e.start), fmtVec(e.end), fmtExtra(e), feed);
  case Kind::Arc: {
    std::string s = fmt::format("Arc {} {} {} -> {}{} centre {}", planeCode(e.plane),
                                e.clockwise ? "CW" : "CCW", fmtVec(e.start), fmtVec(e.end),
                                fmtExtra(e), fmtVec(e.center));
    if (e.turns != 0) s += fmt::format(" +{} turns", e.turns);
    if (std::abs(e.startRadius - e.endRadius) > 5e-5) // spiral, not 4-decimal rounding
      s += fmt::format(" r {:.4f} -> {:.4f}", e.startRadius, e.endRadius);
    else
      s += fmt::format(" r {:.4f}", e.startRadius);
    return s + feed;
  }
  case Kind::Dwell:
    return fmt::format("Dwell {}{}", e.value, e.perRevolution ? " rev" : " s");
  case Kind::Spindle:
    return fmt::format("Spindle S{} {}", e.value,
                       e.direction > 0   ? "CW"
                       : e.direction < 0 ? "CCW"
                                         : "stop");
  case Kind::SpindleOrient:
    return fmt::format("SpindleOrient {}", e.value);
  case Kind::OverrideLock:
    return e.value != 0 ? "OverrideLock on" : "OverrideLock off";
  case Kind::RadiusComp:
    return e.value == 0
               ? "RadiusComp off"
               : fmt::format("RadiusComp {} r{}", e.value > 0 ? "left" : "right", e.startRadius);
  case Kind::ToolChange:
    return fmt::format("ToolChange T{}", e.value);
  case Kind::Coolant:
    return fmt::format("Coolant M{}", e.value);
  case Kind::Stop:
    return e.optional ? "Stop (optional)" : "Stop";
  case Kind::End:
    return "End";
  case Kind::Message:
    return fmt::format("Message \"{}\"", e.text);
  case Kind::PlaneChange:
    return fmt::format("PlaneChange {}{}{}", planeCode(e.plane), e.text.empty() ? "" : " ", e.text);
  case Kind::UnitsChange:
    return fmt::format("UnitsChange G{}", e.value);
  case Kind::FeedModeChange:
    return fmt::format("FeedModeChange G{}", e.value);
  }
  return "?";
}

} // namespace gcx::motion
