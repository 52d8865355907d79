// Builds turning-cycle requests as the interpreter will (turning.h): words from the text of a
// block, a contour from the text of blocks ns..nf (G18, X a diameter), and the result as the
// spec's vector text or as "line:col code" of the first error.
#pragma once
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cycles/turning.h"
#include "diag/diagnostic.h"
#include "dialects/nct/profile.h"

namespace gcx::test {

inline SourceRange at(unsigned line, unsigned col = 1, unsigned length = 1) {
  SourceRange r;
  r.begin.line = line, r.begin.col = col, r.length = length;
  return r;
}

/// "G71.7 P50 Q90 U0.4 W0.1 F0.3" on source line `line`: the cycle from the G word, every other
/// word with its column. `diameter`: bit 0 = X is a diameter axis.
inline cycles::TurningWords words(const std::string& block, unsigned line = 1,
                                  unsigned diameter = 1, motion::Plane plane = motion::Plane::ZX) {
  cycles::TurningWords w;
  w.plane = plane, w.diameter = diameter, w.range = at(line, 1, block.size());
  for (std::size_t i = 0; i < block.size();) {
    if (!std::isalpha(static_cast<unsigned char>(block[i]))) {
      ++i;
      continue;
    }
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(block[i])));
    char* end = nullptr;
    const double v = std::strtod(block.c_str() + i + 1, &end);
    const std::size_t len = static_cast<std::size_t>(end - block.c_str()) - i;
    if (c == 'G') {
      const GCodeSpec* g = nct::profile().gcode(v); // the NCT binding of the code
      if (g && g->action == GAction::TurningCycle)
        w.cycle = static_cast<cycles::TurningCycle>(g->arg); // G0-G3 are the caller's
    } else
      w.set(c, v, at(line, static_cast<unsigned>(i + 1), static_cast<unsigned>(len)));
    i += len;
  }
  return w;
}

/// Blocks ns..nf in G18 (absolute, X diameter, arcs by R > 0: the short arc), from A (radius);
/// block i is on source line firstLine + i. Modal G code carries over, as in a program.
inline std::vector<cycles::ContourSegment>
contour(const cycles::Vec3& a, const std::vector<std::string>& blocks, unsigned firstLine = 50) {
  std::vector<cycles::ContourSegment> out;
  cycles::Vec3 p = a;
  int mode = -1;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const cycles::TurningWords w = words("G70.7 " + blocks[i], 1, 1);
    cycles::ContourSegment s;
    const std::string& b = blocks[i];
    const std::size_t g = b.find('G');
    s.modeProgrammed = g != std::string::npos;
    if (s.modeProgrammed) mode = std::atoi(b.c_str() + g + 1);
    s.kind = mode == 0   ? cycles::OpKind::Rapid
             : mode == 2 ? cycles::OpKind::ArcCW
             : mode == 3 ? cycles::OpKind::ArcCCW
                         : cycles::OpKind::Feed;
    s.from = p;
    if (w['X'])
      s.to[0] = w['X']->value / 2;
    else
      s.to[0] = p[0];
    s.to[1] = p[1];
    s.to[2] = w['Z'] ? w['Z']->value : p[2];
    if (mode >= 2) { // centre from R in the (Z, X) plane: left of the chord for G3
      const double r = w['R']->value;
      const cycles::Vec2 u(s.from[2], s.from[0]), v(s.to[2], s.to[0]);
      const cycles::Vec2 d = v - u, n(-d[1] / d.norm(), d[0] / d.norm());
      const double h = std::sqrt(std::max(0.0, r * r - d.squaredNorm() / 4));
      const cycles::Vec2 c = (u + v) / 2 + (mode == 3 ? h : -h) * n;
      s.center = cycles::Vec3(c[1], p[1], c[0]);
    }
    s.range = at(static_cast<unsigned>(firstLine + i));
    out.push_back(s);
    p = s.to;
  }
  return out;
}

/// Runs the first block (if any) then the run block; the ops as text, or "line:col code".
inline std::string expand(const cycles::TurningRequest& req, const std::string& first,
                          const std::string& run, unsigned diameter = 1) {
  diag::Engine diags;
  cycles::TurningModal modal;
  auto fail = [&] {
    const diag::Diagnostic& d = diags.all().front();
    return std::to_string(d.range.begin.line) + ":" + std::to_string(d.range.begin.col) + " " +
           d.code;
  };
  if (!first.empty()) {
    const auto kind = cycles::updateModal(modal, words(first, 30, diameter, req.plane), diags);
    if (kind == cycles::TurningBlock::Error) return fail();
    if (kind != cycles::TurningBlock::Stored) return "first block runs";
  }
  const cycles::TurningWords w = words(run, 40, diameter, req.plane);
  if (cycles::updateModal(modal, w, diags) != cycles::TurningBlock::Run)
    return diags.hasErrors() ? fail() : "run block stores";
  const auto ops = cycles::expandTurning(req, modal, w, diags);
  if (!ops) return fail();
  return cycles::opsText(req.start, *ops, "XYZ", diameter);
}

/// A request at A = (X diameter, Z) in G18.
inline cycles::TurningRequest request(double xDiameter, double z) {
  cycles::TurningRequest req;
  req.start = cycles::Vec3(xDiameter / 2, 0, z);
  req.end = req.start;
  return req;
}

/// A contour cycle (G71.7-G73.7) at A = (X diameter, Z) in G18 with roughing feed f.
inline std::string contourCycle(double xDiameter, double z, double f,
                                const std::vector<std::string>& blocks, const std::string& first,
                                const std::string& run, CycleChoices choices = {}) {
  auto req = request(xDiameter, z);
  req.feed = f;
  req.choices = choices;
  req.contour = contour(req.start, blocks);
  return expand(req, first, run);
}

/// A cycle with an end point (G74.7-G79.7) from A = (X diameter, Z) in G18 to
/// (xEnd radius, zEnd), feed or lead f.
inline std::string cycleTo(double xDiameter, double z, double xEnd, double zEnd, double f,
                           const std::string& first, const std::string& run) {
  auto req = request(xDiameter, z);
  req.end = cycles::Vec3(xEnd, 0, zEnd);
  req.feed = f;
  return expand(req, first, run);
}

} // namespace gcx::test
