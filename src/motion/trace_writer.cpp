#include "motion/trace_writer.h"

#include <fmt/format.h>
#include <iterator>
#include <nlohmann/json.hpp>

#include "motion/decimal.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"

namespace gcx::motion {

const char* kindName(Kind k) {
  switch (k) {
  case Kind::Rapid:
    return "rapid";
  case Kind::Feed:
    return "feed";
  case Kind::Arc:
    return "arc";
  case Kind::Dwell:
    return "dwell";
  case Kind::Spindle:
    return "spindle";
  case Kind::SpindleOrient:
    return "spindle_orient";
  case Kind::OverrideLock:
    return "override_lock";
  case Kind::RadiusComp:
    return "radius_comp";
  case Kind::ToolChange:
    return "tool_change";
  case Kind::Coolant:
    return "coolant";
  case Kind::Stop:
    return "stop";
  case Kind::End:
    return "end";
  case Kind::Message:
    return "message";
  case Kind::PlaneChange:
    return "plane";
  case Kind::UnitsChange:
    return "units";
  case Kind::FeedModeChange:
    return "feed_mode";
  }
  return "unknown";
}

namespace {
const char* planeName(Plane p) {
  switch (p) {
  case Plane::XY:
    return "XY";
  case Plane::ZX:
    return "ZX";
  case Plane::YZ:
    return "YZ";
  }
  return "XY";
}

void appendString(std::string& s, const std::string& text) {
  // nlohmann escapes for JSON; invalid UTF-8 (old controllers' code pages) becomes U+FFFD.
  s += nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void appendVec(std::string& s, const Vec3& v) {
  s += '[';
  appendDecimal(s, v.x());
  s += ',';
  appendDecimal(s, v.y());
  s += ',';
  appendDecimal(s, v.z());
  s += ']';
}

void key(std::string& s, const char* k) {
  s += ",\"";
  s += k;
  s += "\":";
}

void appendExtra(std::string& s, const Extra& v, unsigned axes) {
  s += '{';
  bool first = true;
  for (int i = 0; i < 6; ++i) {
    if (!(axes & (1u << i))) continue;
    s += first ? "\"" : ",\"";
    s += kExtraAxisNames[i];
    s += "\":";
    appendDecimal(s, v[i]);
    first = false;
  }
  s += '}';
}
} // namespace

TraceWriter::TraceWriter(std::ostream& out, FileNames names, TraceOptions opt)
    : out_(out), names_(std::move(names)), opt_(opt) {}

void TraceWriter::appendLoc(std::string& s, const SourceLoc& loc) {
  // File names are escaped once: a trace has millions of lines but a handful of files.
  std::string& name = fileText_[loc.file];
  if (name.empty()) {
    appendString(name, names_ ? names_(loc.file) : fmt::format("#{}", loc.file));
    name.pop_back(); // keep the opening quote, drop the closing one
  }
  s += name;
  fmt::format_to(std::back_inserter(s), ":{}:{}\"", loc.line, loc.col);
}

std::string TraceWriter::line(const Event& e) {
  std::string s = "{\"kind\":\"";
  s += kindName(e.kind);
  s += '"';
  if (isMotion(e)) {
    key(s, "start");
    appendVec(s, e.start);
    key(s, "end");
    appendVec(s, e.end);
    // Only the axes that are off zero at either end, so 3-axis traces stay as they were.
    unsigned axes = 0;
    for (int i = 0; i < 6; ++i)
      if (e.extraStart[i] != 0 || e.extraEnd[i] != 0) axes |= 1u << i;
    if (axes != 0) {
      key(s, "extra_start");
      appendExtra(s, e.extraStart, axes);
      key(s, "extra_end");
      appendExtra(s, e.extraEnd, axes);
    }
  }
  switch (e.kind) {
  case Kind::Arc:
    if (opt_.sample) {
      points_.assign(1, e.start);
      appendArcPoints(ArcGeometry(e), opt_.tolerance, points_);
      key(s, "points");
      s += '[';
      for (std::size_t i = 0; i < points_.size(); ++i) {
        if (i) s += ',';
        appendVec(s, points_[i]);
      }
      s += ']';
    } else {
      key(s, "center");
      appendVec(s, e.center);
      key(s, "plane");
      s += '"';
      s += planeName(e.plane);
      s += '"';
      key(s, "dir");
      s += e.clockwise ? "\"cw\"" : "\"ccw\"";
      key(s, "turns");
      s += std::to_string(e.turns);
    }
    [[fallthrough]];
  case Kind::Feed:
    key(s, "feed");
    appendDecimal(s, e.feed);
    if (e.perRevolution) s += ",\"per_rev\":true";
    if (e.lead > 0) {
      key(s, "lead");
      appendDecimal(s, e.lead);
    }
    break;
  case Kind::Dwell:
    key(s, e.perRevolution ? "revolutions" : "seconds");
    appendDecimal(s, e.value);
    break;
  case Kind::Spindle:
    key(s, "speed");
    appendDecimal(s, e.value);
    key(s, "dir");
    s += e.direction > 0 ? "\"cw\"" : e.direction < 0 ? "\"ccw\"" : "\"stop\"";
    break;
  case Kind::SpindleOrient:
  case Kind::OverrideLock:
    key(s, "value");
    appendDecimal(s, e.value);
    break;
  case Kind::RadiusComp:
    key(s, "value");
    appendDecimal(s, e.value);
    key(s, "radius");
    appendDecimal(s, e.startRadius);
    break;
  case Kind::ToolChange:
    key(s, "tool");
    appendDecimal(s, e.value);
    break;
  case Kind::Coolant:
    key(s, "code");
    appendDecimal(s, e.value);
    break;
  case Kind::Stop:
    s += e.optional ? ",\"optional\":true" : ",\"optional\":false";
    break;
  case Kind::Message:
    key(s, "text");
    appendString(s, e.text);
    break;
  case Kind::PlaneChange:
    key(s, "plane");
    s += '"';
    s += planeName(e.plane);
    s += '"';
    if (!e.text.empty()) {
      key(s, "axes");
      appendString(s, e.text);
    }
    break;
  case Kind::UnitsChange:
  case Kind::FeedModeChange:
    key(s, "code");
    appendDecimal(s, e.value);
    break;
  case Kind::Rapid:
  case Kind::End:
    break;
  }
  if (e.from.at.valid()) {
    key(s, "at");
    appendLoc(s, e.from.at);
  }
  if (!e.from.chain.empty()) {
    key(s, "chain");
    s += '[';
    for (std::size_t i = 0; i < e.from.chain.size(); ++i) {
      const Frame& f = e.from.chain[i];
      s += i ? ",{\"what\":" : "{\"what\":";
      appendString(s, f.what);
      if (f.call.valid()) {
        key(s, "at");
        appendLoc(s, f.call);
      }
      s += '}';
    }
    s += ']';
  }
  s += '}';
  return s;
}

void TraceWriter::event(const Event& e) {
  std::string s = line(e);
  s += '\n';
  out_.write(s.data(), static_cast<std::streamsize>(s.size()));
}

} // namespace gcx::motion
