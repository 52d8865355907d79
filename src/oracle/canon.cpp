#include "oracle/canon.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace gcx::oracle {

using motion::Event;
using motion::Kind;
using motion::Plane;
using motion::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isNameChar(char c) {
  return (c >= 'A' && c <= 'Z') || isDigit(c) || c == '_';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && isSpace(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back()))
    s.remove_suffix(1);
  return s;
}

bool toDouble(std::string_view s, double& v) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

/// The in-plane axis indices (first, second) and the normal axis of a plane.
void planeAxes(Plane p, int& a, int& b, int& n) {
  switch (p) {
  case Plane::XY:
    a = 0;
    b = 1;
    n = 2;
    return;
  case Plane::ZX:
    a = 2;
    b = 0;
    n = 1;
    return;
  case Plane::YZ:
    a = 1;
    b = 2;
    n = 0;
    return;
  }
}

} // namespace

bool splitCanonLine(std::string_view line, CanonCall& out) {
  std::size_t p = 0;
  while (p < line.size() && isSpace(line[p]))
    ++p;
  const std::size_t counter = p;
  while (p < line.size() && isDigit(line[p]))
    ++p;
  if (p == counter) return false; // no output counter: `(print,...)` text or garbage
  while (p < line.size() && isSpace(line[p]))
    ++p;
  if (p >= line.size() || line[p] != 'N') return false;
  ++p;
  std::uint32_t n = 0;
  if (line.substr(p, 5) == ".....") {
    p += 5;
  } else {
    const std::size_t d = p;
    std::uint64_t v = 0;
    while (p < line.size() && isDigit(line[p])) {
      v = v * 10 + static_cast<std::uint64_t>(line[p] - '0');
      if (v > 0xffffffffULL) v = 0xffffffffULL;
      ++p;
    }
    if (p == d) return false;
    n = static_cast<std::uint32_t>(v);
  }
  while (p < line.size() && isSpace(line[p]))
    ++p; // `N123456STRAIGHT_...` has no space
  const std::size_t name = p;
  while (p < line.size() && isNameChar(line[p]))
    ++p;
  if (p == name || p >= line.size() || line[p] != '(') return false;
  const std::size_t close = line.rfind(')');
  if (close == std::string_view::npos || close < p) return false;

  out.line = n;
  out.name = std::string(line.substr(name, p - name));
  out.args.clear();
  std::string_view args = line.substr(p + 1, close - p - 1);
  if (args.find('"') != std::string_view::npos) { // MESSAGE("..."), COMMENT("..."): one text
    args = trim(args);
    if (args.size() >= 2 && args.front() == '"' && args.back() == '"')
      args = args.substr(1, args.size() - 2);
    out.args.emplace_back(args);
    return true;
  }
  // Numbers are separated by ", " and, in USE_TOOL_LENGTH_OFFSET / SET_SPINDLE_MODE, by spaces.
  std::size_t q = 0;
  while (q < args.size()) {
    while (q < args.size() && (isSpace(args[q]) || args[q] == ','))
      ++q;
    const std::size_t s = q;
    while (q < args.size() && !isSpace(args[q]) && args[q] != ',')
      ++q;
    if (q > s) out.args.emplace_back(args.substr(s, q - s));
  }
  return true;
}

CanonReader::CanonReader(CanonOptions options)
    : options_(std::move(options)), pos_(options_.initialPosition) {
  if (!options_.programText.empty()) {
    lineStarts_.push_back(0);
    for (std::size_t i = 0; i < options_.programText.size(); ++i)
      if (options_.programText[i] == '\n') lineStarts_.push_back(i + 1);
  }
  options_.programText = {};
}

Vec3 CanonReader::toMachine(const Vec3& programPoint) const {
  Vec3 p = programPoint * unit_ + g92_;
  const double t = rotationDeg_ * kPi / 180.0;
  if (t != 0) {
    const double c = std::cos(t), s = std::sin(t);
    p = Vec3(p.x() * c - p.y() * s, p.x() * s + p.y() * c, p.z());
  }
  return p + g5x_ + tool_;
}

Vec3 CanonReader::toProgramMm(const Vec3& machine) const {
  Vec3 p = machine - g5x_ - tool_;
  const double t = -rotationDeg_ * kPi / 180.0;
  if (t != 0) {
    const double c = std::cos(t), s = std::sin(t);
    p = Vec3(p.x() * c - p.y() * s, p.x() * s + p.y() * c, p.z());
  }
  return p - g92_;
}

Event CanonReader::make(Kind k, std::uint32_t line) const {
  Event e;
  e.kind = k;
  e.from.at.file = options_.file;
  e.from.at.line = line;
  if (line != 0 && line <= lineStarts_.size()) {
    e.from.at.col = 1;
    e.from.at.offset = lineStarts_[line - 1];
  }
  e.start = pos_;
  e.end = pos_;
  e.extraStart = e.extraEnd = extra_;
  return e;
}

void CanonReader::rotaryTarget(const std::vector<double>& v, std::size_t first, Event& e) {
  if (v.size() < first + 3) return; // a b c not printed: they stay where they are
  e.extraEnd.head<3>() =
      Vec3(v[first], v[first + 1], v[first + 2]) + g92Rotary_ + g5xRotary_ + toolRotary_;
  extra_ = e.extraEnd;
}

void CanonReader::push(Event e) {
  events_.push_back(std::move(e));
}

void CanonReader::note(std::uint32_t line, std::string_view text, std::string_view why) {
  unsupported_.push_back(fmt::format("line {}: {}: {}", line, trim(text), why));
}

bool CanonReader::numbers(const CanonCall& c, std::size_t n, std::vector<double>& v,
                          std::string_view text) {
  v.clear();
  if (c.args.size() < n) {
    note(c.line, text, fmt::format("expected {} arguments", n));
    return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    double d = 0;
    if (!toDouble(c.args[i], d)) {
      note(c.line, text, fmt::format("argument {} is not a number", i + 1));
      return false;
    }
    v.push_back(d);
  }
  return true;
}

void CanonReader::spindle(std::uint32_t line) {
  if (spindleSpeed_ == emittedSpeed_ && spindleDir_ == emittedDir_) return;
  emittedSpeed_ = spindleSpeed_;
  emittedDir_ = spindleDir_;
  // `S1000 M3` prints SET_SPINDLE_SPEED and START_SPINDLE_CLOCKWISE: one event per block.
  if (line != 0 && !events_.empty() && events_.back().kind == Kind::Spindle &&
      events_.back().from.at.line == line) {
    events_.back().value = spindleSpeed_;
    events_.back().direction = spindleDir_;
    return;
  }
  Event e = make(Kind::Spindle, line);
  e.value = spindleSpeed_;
  e.direction = spindleDir_;
  push(std::move(e));
}

void CanonReader::line(std::string_view text) {
  CanonCall c;
  if (splitCanonLine(text, c)) call(c, text);
}

void CanonReader::call(const CanonCall& c, std::string_view text) {
  const std::string& n = c.name;
  std::vector<double> v;
  auto arg0 = [&]() -> std::string_view {
    return c.args.empty() ? std::string_view() : std::string_view(c.args[0]);
  };

  if (n == "STRAIGHT_TRAVERSE" || n == "STRAIGHT_FEED") { // (x, y, z, a, b, c)
    if (!numbers(c, c.args.size() >= 6 ? 6 : 3, v, text)) return;
    Event e = make(n == "STRAIGHT_FEED" ? Kind::Feed : Kind::Rapid, c.line);
    e.end = toMachine(Vec3(v[0], v[1], v[2]));
    rotaryTarget(v, 3, e);
    if (e.kind == Kind::Feed) {
      e.feed = synced_ ? syncPitch_ : feed_;
      e.perRevolution = synced_ || perRev_;
      e.lead = synced_ ? syncPitch_ : 0;
      if (inverseTime_ && !synced_) note(c.line, text, "inverse-time feed (G93) not converted");
    }
    pos_ = e.end;
    push(std::move(e));
  } else if (n == "RIGID_TAP") { // (x, y, z[, scale]): G33.1 in to the point and back out
    if (!numbers(c, 3, v, text)) return;
    const Vec3 from = pos_;
    for (const Vec3& to : {toMachine(Vec3(v[0], v[1], v[2])), from}) {
      Event e = make(Kind::Feed, c.line);
      e.end = to;
      e.feed = e.lead = syncPitch_;
      e.perRevolution = true;
      pos_ = e.end;
      push(std::move(e));
    }
  } else if (n == "ARC_FEED") { // (e1, e2, c1, c2, rot, e3, a, b, c)
    if (!numbers(c, c.args.size() >= 9 ? 9 : 6, v, text)) return;
    const double e1 = v[0], e2 = v[1], c1 = v[2] * unit_, c2 = v[3] * unit_, e3 = v[5];
    const int rot = static_cast<int>(std::lround(v[4]));
    const Vec3 startProg = toProgramMm(pos_);
    Vec3 endProg = Vec3::Zero(), centreProgMm = Vec3::Zero();
    switch (plane_) {
    case Plane::XY:
      endProg = Vec3(e1, e2, e3);
      centreProgMm = Vec3(c1, c2, startProg.z());
      break;
    case Plane::YZ:
      endProg = Vec3(e3, e1, e2);
      centreProgMm = Vec3(startProg.x(), c1, c2);
      break;
    case Plane::ZX:
      endProg = Vec3(e2, e3, e1);
      centreProgMm = Vec3(c2, startProg.y(), c1);
      break;
    }
    Event e = make(Kind::Arc, c.line);
    e.plane = plane_;
    e.end = toMachine(endProg);
    rotaryTarget(v, 6, e);
    e.center = toMachine(centreProgMm / unit_);
    int a = 0, b = 0, nrm = 0;
    planeAxes(plane_, a, b, nrm);
    // The event's centre lies at the start's height along the normal. Exact unless an XY
    // rotation is combined with a G18/G19 arc, which tilts the arc plane (not expressible).
    if (rotationDeg_ != 0 && plane_ != Plane::XY)
      note(c.line, text, "XY rotation with a G18/G19 arc: the arc plane is tilted");
    e.center[nrm] = e.start[nrm];
    e.clockwise = rot < 0;
    e.turns = std::max(0, std::abs(rot) - 1);
    if (rot == 0) note(c.line, text, "rotation 0");
    e.startRadius = std::hypot(e.start[a] - e.center[a], e.start[b] - e.center[b]);
    e.endRadius = std::hypot(e.end[a] - e.center[a], e.end[b] - e.center[b]);
    e.feed = synced_ ? syncPitch_ : feed_;
    e.perRevolution = synced_ || perRev_;
    if (inverseTime_ && !synced_) note(c.line, text, "inverse-time feed (G93) not converted");
    pos_ = e.end;
    push(std::move(e));
  } else if (n == "DWELL") {
    if (!numbers(c, 1, v, text)) return;
    Event e = make(Kind::Dwell, c.line);
    e.value = v[0];
    push(std::move(e));
  } else if (n == "SET_FEED_RATE") {
    if (!numbers(c, 1, v, text)) return;
    feed_ = v[0] * unit_;
  } else if (n == "SET_FEED_MODE") {
    // 2.9 prints (spindle, mode); mode 1 = units per revolution (measured with G95)
    if (c.args.empty() || !toDouble(c.args.back(), v.emplace_back())) return;
    perRev_ = std::lround(v.back()) == 1;
  } else if (n == "START_SPEED_FEED_SYNC") {
    if (!numbers(c, 1, v, text)) return;
    synced_ = true;
    syncPitch_ = v[0] * unit_;
  } else if (n == "STOP_SPEED_FEED_SYNCH" || n == "STOP_SPEED_FEED_SYNC") {
    synced_ = false;
  } else if (n == "USE_LENGTH_UNITS") {
    const std::string_view u = arg0();
    if (u == "CANON_UNITS_INCHES")
      unit_ = 25.4;
    else if (u == "CANON_UNITS_MM")
      unit_ = 1.0;
    else if (u == "CANON_UNITS_CM")
      unit_ = 10.0;
    else
      note(c.line, text, "unknown length units");
  } else if (n == "SET_G5X_OFFSET") { // (index, x, y, z, a, b, c)
    if (!numbers(c, c.args.size() >= 7 ? 7 : 4, v, text)) return;
    g5x_ = Vec3(v[1], v[2], v[3]) * unit_;
    if (v.size() >= 7) g5xRotary_ = Vec3(v[4], v[5], v[6]);
  } else if (n == "SET_G92_OFFSET") { // (x, y, z, a, b, c)
    if (!numbers(c, c.args.size() >= 6 ? 6 : 3, v, text)) return;
    g92_ = Vec3(v[0], v[1], v[2]) * unit_;
    if (v.size() >= 6) g92Rotary_ = Vec3(v[3], v[4], v[5]);
  } else if (n == "SET_XY_ROTATION") {
    if (!numbers(c, 1, v, text)) return;
    rotationDeg_ = v[0];
  } else if (n == "USE_TOOL_LENGTH_OFFSET") { // (x y z, a b c, u v w)
    if (!numbers(c, c.args.size() >= 6 ? 6 : 3, v, text)) return;
    tool_ = Vec3(v[0], v[1], v[2]) * unit_;
    if (v.size() >= 6) toolRotary_ = Vec3(v[3], v[4], v[5]);
  } else if (n == "SELECT_PLANE") {
    const std::string_view p = arg0();
    if (p == "CANON_PLANE_XY")
      plane_ = Plane::XY;
    else if (p == "CANON_PLANE_YZ")
      plane_ = Plane::YZ;
    else if (p == "CANON_PLANE_XZ")
      plane_ = Plane::ZX;
    else
      note(c.line, text, "plane not supported (UV/UW/VW)");
  } else if (n == "SET_SPINDLE_SPEED") { // 2.9: (spindle, speed)
    if (c.args.empty() || !toDouble(c.args.back(), v.emplace_back())) return;
    spindleSpeed_ = v.back();
    spindle(c.line);
  } else if (n == "START_SPINDLE_CLOCKWISE") {
    spindleDir_ = 1;
    spindle(c.line);
  } else if (n == "START_SPINDLE_COUNTERCLOCKWISE") {
    spindleDir_ = -1;
    spindle(c.line);
  } else if (n == "STOP_SPINDLE_TURNING") {
    spindleDir_ = 0;
    spindle(c.line);
  } else if (n == "ORIENT_SPINDLE") { // (spindle, orientation, mode)
    Event e = make(Kind::SpindleOrient, c.line);
    if (c.args.size() >= 2) toDouble(c.args[1], e.value);
    push(std::move(e));
  } else if (n == "SELECT_TOOL") {
    if (!numbers(c, 1, v, text)) return;
    selectedTool_ = static_cast<int>(std::lround(v[0]));
  } else if (n == "CHANGE_TOOL") {
    // prints the tool-table index; the tool number is the last SELECT_TOOL
    if (!numbers(c, 1, v, text)) return;
    Event e = make(Kind::ToolChange, c.line);
    e.value = selectedTool_ >= 0 ? selectedTool_ : v[0];
    push(std::move(e));
  } else if (n == "FLOOD_ON" || n == "MIST_ON" || n == "FLOOD_OFF" || n == "MIST_OFF") {
    const double code = n == "FLOOD_ON" ? 8 : n == "MIST_ON" ? 7 : 9;
    // M9 prints MIST_OFF and FLOOD_OFF: one off event
    if (code == 9 && !events_.empty() && events_.back().kind == Kind::Coolant &&
        events_.back().value == 9)
      return;
    Event e = make(Kind::Coolant, c.line);
    e.value = code;
    push(std::move(e));
  } else if (n == "PROGRAM_STOP" || n == "OPTIONAL_PROGRAM_STOP") {
    Event e = make(Kind::Stop, c.line);
    e.optional = n == "OPTIONAL_PROGRAM_STOP";
    push(std::move(e));
  } else if (n == "PROGRAM_END") {
    push(make(Kind::End, c.line));
  } else if (n == "MESSAGE") {
    Event e = make(Kind::Message, c.line);
    e.text = std::string(arg0());
    push(std::move(e));
  } else if (n == "COMMENT") {
    // G93 prints SET_FEED_MODE(0, 0) like G94; only this note tells them apart
    const std::string_view t = arg0();
    if (t == "interpreter: feed mode set to inverse time")
      inverseTime_ = true;
    else if (t.starts_with("interpreter: feed mode set to units per"))
      inverseTime_ = false;
  } else if (n == "STRAIGHT_PROBE") {
    note(c.line, text, "probe move not modelled (position set to its target)");
    if (numbers(c, 3, v, text)) pos_ = toMachine(Vec3(v[0], v[1], v[2]));
  } else if (n == "NURBS_FEED" || n == "SPLINE_FEED") {
    note(c.line, text, "motion not modelled");
  }
  // Everything else (other comments, ON_RESET, SET_FEED_REFERENCE, SET_MOTION_CONTROL_MODE,
  // SET_NAIVECAM_TOLERANCE, overrides, SET_SPINDLE_MODE, START_CHANGE, ...) carries no motion.
}

std::vector<Event> parseCanon(const std::vector<std::string>& lines, const CanonOptions& options) {
  CanonReader r(options);
  r.lines(lines);
  return r.take();
}

std::vector<Event> parseCanonText(std::string_view text, const CanonOptions& options) {
  CanonReader r(options);
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    r.line(text.substr(pos, nl - pos));
    pos = nl + 1;
  }
  return r.take();
}

} // namespace gcx::oracle
