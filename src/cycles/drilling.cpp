// One hole of an NCT drilling cycle: checks (cycles.md §7), levels (§2.3), the op table of §3.1
// and the peck arithmetic of §3.2. Op numbers are the manual's (000:9410-9421).
#include "cycles/drilling.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "motion/geometry.h"

namespace gcx::cycles {

namespace {

constexpr double kZeroLength = 0.0005; // §1.2 rule 2: shorter moves are omitted

/// The resolved quantities of one hole (§2.3, §3 notation).
struct Hole {
  double ini = 0, r = 0, z = 0;
  double s = -1;              // drilling direction sign(z - r)
  double feed = 0;            // F
  double dwell = 0;           // P
  Vec3 shift = Vec3::Zero();  // orientation shift (i, j) in the plane (G76, G87-B)
  std::optional<double> peck; // Q in program units (Q / scale)
  double scale = 1;           // |scale factor| on the drilling axis (§2.7)
};

/// Appends ops, tracking the position; moves of zero length are dropped.
class Ops {
public:
  Ops(const Vec3& start, int drillAxis) : at_(start), axis_(drillAxis) {}

  void step(int n) { step_ = n; }
  Vec3 level(double v) const {
    Vec3 p = at_;
    p[axis_] = v;
    return p;
  }
  const Vec3& at() const { return at_; }
  void rapid(const Vec3& to) { move(OpKind::Rapid, to, 0); }
  void rapidLevel(double v) { rapid(level(v)); }
  void feedLevel(double v, double f) { move(OpKind::Feed, level(v), f); }
  void tap(double v, double f, double speed, int dir, double ovr = 100) {
    if (move(OpKind::RigidTap, level(v), f)) {
      ops_.back().value = speed;
      ops_.back().direction = dir;
      ops_.back().override = ovr;
    }
  }
  void op(OpKind k, double value = 0) {
    DrillOp o;
    o.kind = k, o.step = step_, o.to = at_, o.value = value;
    ops_.push_back(o);
  }
  void dwell(double p) {
    if (p > 0) op(OpKind::Dwell, p); // §3.1: only when P > 0 [D]
  }
  std::vector<DrillOp>& list() { return ops_; }

private:
  bool move(OpKind k, const Vec3& to, double f) {
    const bool zero = (to - at_).norm() < kZeroLength;
    at_ = to;
    if (zero) return false;
    DrillOp o;
    o.kind = k, o.step = step_, o.to = to, o.feed = f;
    ops_.push_back(o);
    return true;
  }

  std::vector<DrillOp> ops_;
  Vec3 at_;
  int axis_;
  int step_ = 1;
};

bool rigidTap(DrillCycle c) {
  return c == DrillCycle::RigidTapRight || c == DrillCycle::RigidTapLeft;
}
bool pecking(DrillCycle c) {
  return c == DrillCycle::HighSpeedPeck || c == DrillCycle::PeckDrill;
}

// §3.2: n = max(1, ceil(D/Q - 1e-9)), L_k = r + s*min(k*Q, D), never accumulated (§1.2 rule 3).
int peckCount(const Hole& h, double q) {
  const double d = std::abs(h.z - h.r);
  return std::max(1, static_cast<int>(std::ceil(d / q - 1e-9)));
}
double peckLevel(const Hole& h, double q, int k) {
  return h.r + h.s * std::min(k * q, std::abs(h.z - h.r));
}

// Ops 7-10 when the return is a rapid: G99 -> op 7 to R then op 8; G98 -> op 9 to the
// initial level then op 10 (000:9455-9462). `after` is the op 8 / op 10 activity.
template <class After> void rapidReturn(Ops& o, const Hole& h, bool g99, After after) {
  o.step(g99 ? 7 : 9);
  o.rapidLevel(g99 ? h.r : h.ini);
  o.step(g99 ? 8 : 10);
  after();
}

void highSpeedPecks(Ops& o, const Hole& h, double d) { // G73 (000:9692-9701)
  const int n = peckCount(h, *h.peck);
  for (int k = 1; k <= n; ++k) {
    const double lk = peckLevel(h, *h.peck, k);
    o.feedLevel(lk, h.feed);
    if (k < n) o.rapidLevel(lk - h.s * d); // no retract after the last peck (§9 Q-2)
  }
}

void deepPecks(Ops& o, const Hole& h, double c) { // G83 (000:9873-9883)
  const int n = peckCount(h, *h.peck);
  for (int k = 1; k <= n; ++k) {
    if (k >= 2) o.rapidLevel(peckLevel(h, *h.peck, k - 1) - h.s * c); // not clamped
    o.feedLevel(peckLevel(h, *h.peck, k), h.feed);
    if (k < n) o.rapidLevel(h.r);
  }
}

// G84.2 / G84.3 (000:9986-10100, §3.9): op 4, the tap into the hole (pecks with Q), dwell,
// the reverse tap to R, then G98 rapid to the initial level.
void rigidTapHole(Ops& o, const Hole& h, const DrillRequest& req, const DrillConfig& cfg) {
  const int fwd =
      req.cycle == DrillCycle::RigidTapRight ? +1 : -1; // CW for G84.2 (000:10000-10003)
  const double speed = req.spindleSpeed;
  // the retract override applies only with EOE=1: I, else the tapExtraction setting
  // (000:10012-10020, 10072-10080)
  const double extract =
      cfg.extractionEnabled
          ? (req.vars.overridePercent ? req.vars.overridePercent->value : cfg.tapExtraction)
          : 100;
  o.step(4);
  if (cfg.tapOrient)
    o.op(OpKind::SpindleOrient); // TSC=1 (000:9997-9998)
  else
    o.op(OpKind::CloseLoop, cfg.closeLoopMCode); // TSC=0 (000:9992-9995)
  o.step(5);
  if (h.peck) {
    const int n = peckCount(h, *h.peck);
    const double ret = (req.vars.e ? req.vars.e->value : cfg.tapReturn) / h.scale;
    const double clear = (req.vars.e ? req.vars.e->value : cfg.tapClearance) / h.scale;
    const double back = cfg.returnEnabled ? cfg.tapReturnOverride : 100; // ROE (000:10089-10097)
    for (int k = 1; k <= n; ++k) {
      const double lk = peckLevel(h, *h.peck, k);
      if (cfg.tapNormalPeck && k >= 2)
        o.tap(peckLevel(h, *h.peck, k - 1) - h.s * clear, h.feed, speed, fwd);
      o.tap(lk, h.feed, speed, fwd);
      if (k == n) break;
      if (cfg.tapNormalPeck) // PTC=1: as G83, back to R (000:10061-10063)
        o.tap(h.r, h.feed, speed, -fwd, back);
      else // PTC=0: as G83.1, back by E / tapReturn (000:10060, 10065-10067)
        o.tap(lk - h.s * ret, h.feed, speed, -fwd, extract);
    }
  } else {
    o.tap(h.z, h.feed, speed, fwd);
  }
  o.step(6);
  o.dwell(h.dwell);
  o.step(7);
  o.tap(h.r, h.feed, speed, -fwd, extract); // always, reverse direction (000:10006-10010)
  if (req.ret == DrillReturn::Initial) {
    o.step(9);
    o.rapidLevel(h.ini);
  }
}

// G87 variant B, back boring (000:10202-10251): R lies below the bottom, G99 is ignored.
void backBoring(Ops& o, const Hole& h) {
  o.step(2);
  o.op(OpKind::SpindleOrient);
  o.rapid(o.at() + h.shift);
  o.step(3);
  o.rapidLevel(h.r);
  o.step(4);
  o.rapid(o.at() - h.shift);
  o.op(OpKind::SpindleCW);
  o.step(5);
  o.feedLevel(h.z, h.feed);
  o.step(6);
  o.op(OpKind::SpindleOrient);
  o.rapid(o.at() + h.shift);
  o.step(9);
  o.rapidLevel(h.ini);
  o.step(10);
  o.rapid(o.at() - h.shift);
  o.op(OpKind::SpindleCW);
}

// Ops 2-10 of every cycle but G84.2/G84.3 and G87-B (the table of §3.1).
void standardHole(Ops& o, const Hole& h, const DrillRequest& req, const DrillConfig& cfg) {
  const bool g99 = req.ret == DrillReturn::RLevel;
  o.step(3);
  o.rapidLevel(h.r);
  o.step(5);
  auto none = [] {};
  auto spindleCW = [&] { o.op(OpKind::SpindleCW); };
  switch (req.cycle) {
  case DrillCycle::HighSpeedPeck: {
    const double d = req.vars.e ? req.vars.e->value : cfg.returnG73; // E, else the setting
    highSpeedPecks(o, h, d / h.scale);
    return rapidReturn(o, h, g99, none);
  }
  case DrillCycle::PeckDrill: {
    const double c = req.vars.e ? req.vars.e->value : cfg.clearanceG83; // E, else the setting
    deepPecks(o, h, c / h.scale);
    return rapidReturn(o, h, g99, none);
  }
  case DrillCycle::Drill:
  case DrillCycle::DrillDwell:
    o.feedLevel(h.z, h.feed);
    o.step(6);
    if (req.cycle == DrillCycle::DrillDwell) o.dwell(h.dwell);
    return rapidReturn(o, h, g99, none);
  case DrillCycle::LeftTapFloating:
  case DrillCycle::RightTapFloating: { // floating-holder tapping (000:9729-9743, 9910-9924)
    const bool left = req.cycle == DrillCycle::LeftTapFloating;
    o.op(OpKind::OverrideLock);
    o.feedLevel(h.z, h.feed);
    o.step(6);
    o.dwell(h.dwell);
    o.op(left ? OpKind::SpindleCW : OpKind::SpindleCCW);
    o.step(7);
    o.feedLevel(h.r, h.feed); // always at F, also under G98
    o.step(8);
    o.op(left ? OpKind::SpindleCCW : OpKind::SpindleCW);
    o.op(OpKind::OverrideRestore);
    break;
  }
  case DrillCycle::BoreFeedOut:
  case DrillCycle::BoreDwellFeedOut: { // feed retract at F*I/100 (000:10124-10133, 10308-10318)
    const double percent =
        req.vars.overridePercent ? req.vars.overridePercent->value : cfg.extractionG85G89;
    o.feedLevel(h.z, h.feed);
    o.step(6);
    if (req.cycle == DrillCycle::BoreDwellFeedOut) o.dwell(h.dwell);
    o.step(7);
    o.feedLevel(h.r, h.feed * percent / 100);
    break;
  }
  case DrillCycle::FineBoring: // fine boring (000:9763-9788)
    o.feedLevel(h.z, h.feed);
    o.step(6);
    o.dwell(h.dwell);
    o.op(OpKind::SpindleOrient);
    o.rapid(o.at() + h.shift);
    return rapidReturn(o, h, g99, [&] {
      o.rapid(o.at() - h.shift);
      o.op(OpKind::SpindleCW);
    });
  case DrillCycle::BoreSpindleStop: // spindle stop, rapid retract (000:10150-10160)
  case DrillCycle::BackBore:        // variant A, ORI=0 (000:10180-10200)
  case DrillCycle::BoreDwellManual: // dwell, manual intervention (000:10265-10289)
    o.feedLevel(h.z, h.feed);
    o.step(6);
    if (req.cycle == DrillCycle::BoreDwellManual) o.dwell(h.dwell);
    o.op(OpKind::SpindleStop);
    if (req.cycle != DrillCycle::BoreSpindleStop) o.op(OpKind::ProgramStop);
    return rapidReturn(o, h, g99, spindleCW);
  case DrillCycle::RigidTapRight:
  case DrillCycle::RigidTapLeft:
    return; // rigidTapHole
  }
  if (!g99) { // op 9 of the cycles whose op 7 always returns to R
    o.step(9);
    o.rapidLevel(h.ini);
  }
}

const SourceRange& wordRange(const std::optional<DrillWord>& w, const SourceRange& fallback) {
  return w && w->range.begin.valid() ? w->range : fallback;
}

// The spindle direction the cycle needs before it starts (§3.1), 0 if none.
int neededDirection(DrillCycle c) {
  switch (c) {
  case DrillCycle::LeftTapFloating:
    return -1;                       // 000:9713-9714
  case DrillCycle::FineBoring:       // 000:9760
  case DrillCycle::RightTapFloating: // 000:9895-9896
  case DrillCycle::BoreSpindleStop:  // 000:10147
  case DrillCycle::BackBore:         // 000:10177, 10214
  case DrillCycle::BoreDwellManual:  // 000:10262
    return +1;
  default:
    return 0;
  }
}

// §7 checks; fills h. False after reporting an error.
bool resolve(const DrillRequest& req, const SourceRange& where, const DrillConfig& cfg,
             diag::Engine& diags, Hole& h) {
  const std::string_view name = req.label;
  const DrillVariables& v = req.vars;
  if (req.cylindrical) {
    diags.error(diag::code::CycleCylindrical, where,
                fmt::format("{}: drilling cycles are not allowed during G7.1 cylindrical "
                            "interpolation (000:2005-2013)",
                            name));
    return false;
  }
  if (req.cycle == DrillCycle::FineBoring && !cfg.orient) {
    diags.error(diag::code::CycleNoOrientation, where,
                fmt::format("G76, G87: the spindle cannot be oriented ({}=0) (000:9746-9749)",
                            cfg.orientLabel));
    return false;
  }
  if (rigidTap(req.cycle) && !cfg.indexable) {
    diags.error(
        diag::code::CycleNotIndexable, where,
        fmt::format("{}: spindle cannot be indexed ({}=0) (000:9927-9930)", name, cfg.indexLabel));
    return false;
  }
  if (!v.z || !v.r) {
    diags.error(diag::code::CycleNoData, where,
                fmt::format("no bottom point or R point for {} (000:9503-9505, 9624)", name));
    return false;
  }
  for (const auto* w : {&v.q, &v.e})
    if (*w && (*w)->value < 0) {
      diags.error(diag::code::CycleQNegative, wordRange(*w, where),
                  fmt::format("{} must be positive (000:9584, 9590)", w == &v.q ? 'Q' : 'E'));
      return false;
    }
  if (pecking(req.cycle) && (!v.q || v.q->value == 0)) {
    diags.error(diag::code::CycleQMissing, wordRange(v.q, where),
                fmt::format("{} needs a peck depth Q > 0", name));
    return false;
  }
  if (req.feed <= 0) {
    diags.error(diag::code::MissingData, where,
                fmt::format("{} without a feed rate F (000:9602-9604)", name));
    return false;
  }
  const bool overrideI = req.cycle == DrillCycle::BoreFeedOut ||
                         req.cycle == DrillCycle::BoreDwellFeedOut ||
                         (rigidTap(req.cycle) && cfg.extractionEnabled);
  if (overrideI && v.overridePercent && v.overridePercent->value <= 0) {
    diags.error(diag::code::DataOutOfRange, wordRange(v.overridePercent, where),
                fmt::format("{}: the retract override I must be > 0 %", name));
    return false;
  }
  h.ini = req.initial;
  h.r = v.r->incremental ? req.initial + v.r->value : v.r->value; // 000:9574-9580
  h.z = v.z->incremental ? h.r + v.z->value : v.z->value;         // 000:9563-9567
  h.s = h.z > h.r ? +1 : -1;
  // The rapid to R must not pass the bottom; back boring is the one cycle whose R lies beyond
  // it (000:10246-10248). The manual gives no alarm: rs274 refuses the same ("R less than Z").
  const bool backBoring = req.cycle == DrillCycle::BackBore && cfg.orient;
  const bool rBeyondBottom = (h.z - h.ini) * (h.r - h.z) > 0;
  if (rBeyondBottom != backBoring) {
    diags.error(diag::code::CycleRBeyondBottom, wordRange(v.r, where),
                backBoring ? "G87 back boring needs its R point beyond the bottom, seen from the "
                             "initial level (000:10246-10248)"
                           : fmt::format("{}: the R point lies beyond the bottom; the rapid to R "
                                         "would pass through the hole bottom",
                                         name));
    return false;
  }
  h.feed = req.feed;
  h.dwell = v.p ? v.p->value : 0;
  h.scale = req.drillScale != 0 ? std::abs(req.drillScale) : 1;
  if (v.q && v.q->value > 0 && (pecking(req.cycle) || rigidTap(req.cycle)))
    h.peck = v.q->value / h.scale; // Q is not scaled (§2.7)
  const motion::PlaneAxes ax = motion::axesOf(req.plane);
  const Vec3 ijk(v.i ? v.i->value : 0, v.j ? v.j->value : 0, v.k ? v.k->value : 0);
  const Eigen::Vector2d shift = req.shiftMap * Eigen::Vector2d(ijk[ax.first], ijk[ax.second]);
  h.shift[ax.first] = shift[0];
  h.shift[ax.second] = shift[1];
  return true;
}

void warnings(const DrillRequest& req, const SourceRange& where, diag::Engine& diags) {
  const int need = neededDirection(req.cycle);
  if (need != 0 && req.spindleDirection && *req.spindleDirection != need)
    diags.warning(diag::code::CycleSpindleDirection, where,
                  fmt::format("{} expects the spindle turning {} before the cycle (§3.1)",
                              req.label, need > 0 ? "clockwise (M3)" : "counter-clockwise (M4)"));
  if (req.radiusCompensation)
    diags.warning(
        diag::code::CycleRadiusComp, where,
        fmt::format("{} with G41/G42 active: hole positions are not compensated", req.label));
}

} // namespace

std::optional<DrillResult> expandHole(const DrillRequest& req, const SourceRange& where,
                                      const DrillConfig& config, diag::Engine& diags) {
  Hole h;
  if (!resolve(req, where, config, diags, h)) return std::nullopt;
  warnings(req, where, diags);
  const int drillAxis = motion::axesOf(req.plane).normal;
  Ops o(req.position, drillAxis);
  // op 1: rapid positioning in the plane, whatever group 1 says (000:9517-9518)
  Vec3 hole = req.position;
  const motion::PlaneAxes ax = motion::axesOf(req.plane);
  hole[ax.first] = req.hole[ax.first];
  hole[ax.second] = req.hole[ax.second];
  o.rapid(hole);
  DrillResult res;
  res.auxAt = o.list().size();
  if (req.cycle == DrillCycle::BackBore && config.orient) {
    backBoring(o, h);
  } else if (rigidTap(req.cycle)) {
    o.step(3);
    o.rapidLevel(h.r);
    rigidTapHole(o, h, req, config);
  } else {
    standardHole(o, h, req, config);
  }
  res.end = o.at();
  res.r = h.r;
  res.z = h.z;
  res.ops = std::move(o.list());
  return res;
}

} // namespace gcx::cycles
