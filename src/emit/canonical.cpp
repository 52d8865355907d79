#include "emit/canonical.h"

#include <fmt/format.h>

#include "motion/decimal.h"
#include "motion/geometry.h"
#include "motion/interpolator.h"

namespace gcx::emit {

using motion::Kind;

namespace {
std::string num(double v) {
  return motion::formatDecimal(v, 6);
}

std::string xyz(const motion::Vec3& p) {
  return fmt::format("X{} Y{} Z{}", num(p.x()), num(p.y()), num(p.z()));
}

const char* planeCode(motion::Plane p) {
  switch (p) {
  case motion::Plane::XY:
    return "G17";
  case motion::Plane::ZX:
    return "G18";
  case motion::Plane::YZ:
    return "G19";
  }
  return "G17";
}
} // namespace

CanonicalEmitter::CanonicalEmitter(std::ostream& out, CanonicalOptions opt)
    : out_(out), opt_(std::move(opt)) {}

void CanonicalEmitter::line(std::string text, const motion::Event& e) {
  if (!headerDone_) {
    out_ << "(gcx canonical motion: machine frame, mm, absolute; offsets and tool lengths are "
            "in the coordinates)\n"
            "G21 G90 G94 G17 G40 G49 G80 G54\n";
    headerDone_ = true;
  }
  const SourceLoc& at = e.from.at;
  if (opt_.provenance && at.valid() &&
      (at.line != lastSource_.line || at.file != lastSource_.file)) {
    std::string where = opt_.fileName ? opt_.fileName(at.file) : std::string("line");
    text += fmt::format(" ({}:{}", where, at.line);
    for (auto it = e.from.chain.rbegin(); it != e.from.chain.rend(); ++it)
      text += fmt::format(", in {}", it->what);
    text += ')';
    lastSource_ = at;
  }
  out_ << text << '\n';
}

void CanonicalEmitter::feedMode(const motion::Event& e) {
  if (e.perRevolution == perRevolution_) return;
  perRevolution_ = e.perRevolution;
  line(perRevolution_ ? "G95" : "G94", e);
}

void CanonicalEmitter::straight(const motion::Event& e, const char* code, const motion::Vec3& to,
                                bool withFeed) {
  std::string s = fmt::format("{} {}", code, xyz(to));
  if (withFeed) s += " F" + num(e.feed);
  line(std::move(s), e);
}

void CanonicalEmitter::event(const motion::Event& e) {
  switch (e.kind) {
  case Kind::Rapid:
    straight(e, "G0", e.end, false);
    return;
  case Kind::Feed:
    feedMode(e);
    straight(e, "G1", e.end, true);
    return;
  case Kind::Arc: {
    feedMode(e);
    const motion::ArcGeometry arc(e);
    if (arc.isSpiral() && std::fabs(arc.startRadius() - arc.endRadius()) > 1e-9) {
      std::vector<motion::Vec3> pts;
      motion::appendArcPoints(arc, opt_.chordTolerance, pts);
      for (const motion::Vec3& p : pts)
        straight(e, "G1", p, true);
      return;
    }
    if (e.plane != plane_) {
      plane_ = e.plane;
      line(planeCode(plane_), e);
    }
    const motion::Vec3 d = e.center - e.start;
    const motion::PlaneAxes ax = motion::axesOf(e.plane);
    static const char letters[] = {'I', 'J', 'K'};
    std::string s = fmt::format("{} {}", e.clockwise ? "G2" : "G3", xyz(e.end));
    for (int a : {0, 1, 2})
      if (a == ax.first || a == ax.second) s += fmt::format(" {}{}", letters[a], num(d[a]));
    if (e.turns > 0) s += fmt::format(" P{}", e.turns + 1);
    s += " F" + num(e.feed);
    line(std::move(s), e);
    return;
  }
  case Kind::Dwell: {
    double seconds = e.value;
    if (e.perRevolution) {
      if (spindleSpeed_ <= 0) {
        line(fmt::format("(dwell of {} revolutions with the spindle stopped)", num(e.value)), e);
        return;
      }
      seconds = e.value * 60.0 / spindleSpeed_;
    }
    line("G4 P" + num(seconds), e);
    return;
  }
  case Kind::Spindle:
    spindleSpeed_ = e.value;
    line(fmt::format("S{} {}", num(e.value),
                     e.direction > 0   ? "M3"
                     : e.direction < 0 ? "M4"
                                       : "M5"),
         e);
    return;
  case Kind::SpindleOrient:
    line("M19", e);
    return;
  case Kind::ToolChange:
    line(fmt::format("T{} M6", num(e.value)), e);
    return;
  case Kind::Coolant:
    line(fmt::format("M{}", num(e.value)), e);
    return;
  case Kind::Stop:
    line(e.optional ? "M1" : "M0", e);
    return;
  case Kind::End:
    line(e.value == 30 ? "M30" : "M2", e);
    return;
  case Kind::Message:
    line("(MSG," + e.text + ")", e);
    return;
  }
}

void CanonicalEmitter::finish() {
  out_.flush();
}

} // namespace gcx::emit
