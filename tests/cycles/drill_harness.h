// A minimal stand-in for the interpreter's side of the drilling contract (passes/cycles/
// drilling.h), to run the program text of cycles.md §8 vectors: it keeps the modal state the
// cycles read (plane, G90/G91, G98/G99, group 1, F, S, spindle), resolves hole positions with
// G90/G91 and the I operator, and prints every block the way the vectors do ("N2: G0 X10 |
// ..."). Polar and `,A` positions are the interpreter's and not handled here.
#pragma once
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <string>

#include "emit/number.h"
#include "motion/geometry.h"
#include "passes/cycles/drilling.h"
#include "support/test_support.h"

namespace gcx::test {

class DrillHarness {
public:
  cycles::DrillConfig config;
  bool wIsAxis = false; // N0103: W is an axis parallel to Z (cycles.md §2.2)

  /// Runs the program; false when a block reported an error (error() names it).
  bool run(const std::string& program) {
    parsed_ = parseNct(program);
    int index = 0;
    for (const ir::Block& b : parsed_.blocks) {
      ++index;
      if (b.words.empty()) continue;
      label_ = b.sequence ? fmt::format("N{}", *b.sequence) : fmt::format("#{}", index);
      text_.clear();
      if (!block(b)) {
        for (const diag::Diagnostic& d : diags.all())
          if (d.severity == diag::Severity::Error && error_.empty())
            error_ =
                fmt::format("{} {} {}:{}", label_, d.code, d.range.begin.line, d.range.begin.col);
        return false;
      }
      if (!text_.empty()) out[label_] = text_;
    }
    return true;
  }
  /// "N2 2053 2:1": the block, the code and the location of the first error.
  const std::string& error() const { return error_; }

  diag::Engine diags{100};
  std::map<std::string, std::string> out; // block label -> its ops
  cycles::DrillModal modal;

private:
  using Vec3 = cycles::Vec3;

  void append(const std::string& s) {
    if (s.empty()) return;
    if (!text_.empty()) text_ += " | ";
    text_ += s;
  }
  std::string axisNames() const { return drillAxis_ == 5 ? "XYW" : "XYZ"; }

  // The current position with the drilling axis' value in the Z slot when W drills.
  Vec3 position() const {
    Vec3 p = pos_;
    if (drillAxis_ == 5) p[2] = w_;
    return p;
  }
  void setPosition(const Vec3& p) {
    pos_ = p;
    if (drillAxis_ == 5)
      pos_[2] = z_, w_ = p[2];
    else
      z_ = p[2];
  }

  static std::optional<cycles::DrillWord> word(const ir::Word* w, bool incremental) {
    if (!w) return std::nullopt;
    return cycles::DrillWord{w->number, incremental || w->incremental, w->range};
  }

  bool block(const ir::Block& b) {
    std::optional<cycles::DrillCycle> code;
    bool dwell = false;
    const ir::Word* axis[3] = {b.find('X'), b.find('Y'), b.find('Z')};
    const ir::Word* wWord = wIsAxis ? b.find('W') : nullptr;
    for (const ir::Word& w : b.words) {
      if (!w.is('G')) continue;
      const int g = static_cast<int>(std::lround(w.number * 10));
      if (g == 0 || g == 10) rapid_ = g == 0, cancelCycle();
      if (g == 800) cancelCycle();
      if (g == 40) dwell = true;
      if (g == 71) cylindrical_ = true;
      if (g == 170 || g == 180 || g == 190)
        plane_ = g == 170 ? motion::Plane::XY : g == 180 ? motion::Plane::ZX : motion::Plane::YZ;
      if (g == 900 || g == 910) incremental_ = g == 910;
      if (g == 980 || g == 990)
        ret_ = g == 990 ? cycles::DrillReturn::RLevel : cycles::DrillReturn::Initial;
      if (auto c = cycles::drillCycleFromCode10(g)) code = c;
    }
    if (const ir::Word* f = b.find('F')) feed_ = f->number;
    if (const ir::Word* s = b.find('S')) speed_ = s->number;
    std::string aux;
    for (const ir::Word& w : b.words)
      if (w.is('M')) {
        aux += (aux.empty() ? "M" : " | M") + emit::formatNumber(w.number);
        if (w.number == 3 || w.number == 4 || w.number == 5)
          spindle_ = w.number == 3 ? 1 : w.number == 4 ? -1 : 0;
      }
    if (dwell) { // not a drilling block: its P is the dwell's, the cycle's P stays (000:10334)
      append("G4 P" + emit::formatNumber(b.find('P')->number));
      append(aux);
      cycles::DrillWords w;
      w.vars.p = word(b.find('P'), false);
      w.axis = drillAxis_;
      return cycles::updateModal(modal, w, diags).has_value();
    }
    if (modal.cycle || code) return cycleBlock(b, code, axis, wWord, aux);
    Vec3 to = pos_;
    bool moved = false;
    for (int a = 0; a < 3; ++a)
      if (axis[a]) {
        to[a] = incremental_ || axis[a]->incremental ? to[a] + axis[a]->number : axis[a]->number;
        moved = true;
      }
    if (wWord) w_ = wWord->number;
    if (moved) {
      cycles::DrillOp op;
      op.kind = rapid_ ? cycles::OpKind::Rapid : cycles::OpKind::Feed;
      op.to = to, op.feed = feed_;
      append(cycles::opsText(pos_, {op}));
      pos_ = to, z_ = to[2];
    }
    append(aux);
    return true;
  }

  bool cycleBlock(const ir::Block& b, std::optional<cycles::DrillCycle> code,
                  const ir::Word* const axis[3], const ir::Word* wWord, const std::string& aux) {
    const motion::PlaneAxes ax = motion::axesOf(plane_);
    const int newAxis = wWord ? 5 : ax.normal;
    cycles::DrillWords w;
    w.code = code;
    w.axis = newAxis;
    w.axisPosition = newAxis == 5 ? w_ : pos_[ax.normal];
    const ir::Word* drillWord = wWord ? wWord : axis[ax.normal];
    w.holeWord = axis[ax.first] || axis[ax.second] || drillWord;
    w.vars.z = word(drillWord, incremental_);
    w.vars.r = word(b.find('R'), incremental_);
    w.vars.q = word(b.find('Q'), false);
    w.vars.e = word(b.find('E'), false);
    w.vars.p = word(b.find('P'), false);
    w.vars.i = word(b.find('I'), false);
    w.vars.j = word(b.find('J'), false);
    w.vars.k = word(b.find('K'), false);
    w.l = word(b.find('L'), false);
    w.range = b.range;
    const std::optional<long> holes = cycles::updateModal(modal, w, diags);
    if (!holes) return false;
    drillAxis_ = newAxis;
    if (*holes == 0) append(aux);
    for (long i = 1; i <= *holes; ++i) {
      cycles::DrillRequest req;
      req.cycle = *modal.cycle;
      req.ret = ret_;
      req.plane = plane_;
      req.position = position();
      req.hole = req.position;
      for (int a : {ax.first, ax.second})
        if (axis[a])
          req.hole[a] = incremental_ || axis[a]->incremental ? req.position[a] + axis[a]->number
                                                             : axis[a]->number;
      req.initial = *modal.initial;
      req.vars = modal.vars;
      req.feed = feed_;
      req.spindleSpeed = speed_;
      req.spindleDirection = spindle_;
      req.cylindrical = cylindrical_;
      const auto res = cycles::expandHole(req, b.range, config, diags);
      if (!res) return false;
      const std::vector<cycles::DrillOp> before(res->ops.begin(), res->ops.begin() + res->auxAt);
      const std::vector<cycles::DrillOp> after(res->ops.begin() + res->auxAt, res->ops.end());
      append(cycles::opsText(req.position, before, axisNames()));
      if (i == 1) append(aux); // end of op 1, first repetition only (000:10360-10362)
      append(cycles::opsText(before.empty() ? req.position : before.back().to, after, axisNames()));
      for (const cycles::DrillOp& op : res->ops)
        if (op.kind == cycles::OpKind::SpindleCW || op.kind == cycles::OpKind::SpindleCCW ||
            op.kind == cycles::OpKind::SpindleStop)
          spindle_ = op.kind == cycles::OpKind::SpindleCW    ? 1
                     : op.kind == cycles::OpKind::SpindleCCW ? -1
                                                             : 0;
      setPosition(res->end);
    }
    return true;
  }

  void cancelCycle() {
    cycles::cancel(modal);
    ret_ = cycles::DrillReturn::Initial; // G98 again (000:9456-9459)
    drillAxis_ = 2;
  }

  Parsed parsed_;
  std::string label_, text_, error_;
  Vec3 pos_ = Vec3::Zero(); // X Y Z
  double z_ = 0, w_ = 0;    // Z and W when W is an axis
  int drillAxis_ = 2;       // 2 = Z, 5 = W
  motion::Plane plane_ = motion::Plane::XY;
  bool incremental_ = false, rapid_ = true, cylindrical_ = false;
  cycles::DrillReturn ret_ = cycles::DrillReturn::Initial;
  double feed_ = 0, speed_ = 0;
  int spindle_ = 0;
};

} // namespace gcx::test
