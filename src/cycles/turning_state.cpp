// The first blocks of the two-block turning formats (cycles.md §4.8-§4.13) and their checks
// (§7 CYC-PARAM).
#include "cycles/turning_state.h"

#include <cmath>
#include <fmt/format.h>

#include "diag/codes.h"
#include "motion/geometry.h"

namespace gcx::cycles {

namespace {

bool isInteger(double v) {
  return std::abs(v - std::round(v)) < 1e-9;
}

bool fail(diag::Engine& diags, const TurningWords& w, char c, const std::string& why) {
  diags.error(diag::code::CycleParam, w.at(c),
              fmt::format("{}: {} ({})", w.label, why, "cycles.md §7"));
  return false;
}

// §4.8/§4.9: `G7x.7 <depth letter>Δd R e`; G71 takes lathe U', G72 lathe W' (§4.2).
bool storeRough(TurningModal& m, const TurningWords& w, diag::Engine& diags) {
  const LatheAxes ax = latheAxes(w.plane);
  const char depth = w.cycle == TurningCycle::RoughTurning ? ax.u : ax.w;
  if (const auto& d = w[depth]) {
    if (d->value <= 0) return fail(diags, w, depth, "the depth of cut must be > 0");
    m.roughDepth = d->value; // always radius (000:2506-2509)
  }
  if (const auto& e = w['R']) {
    if (e->value < 0) return fail(diags, w, 'R', "the retract e must be >= 0");
    m.roughRetract = e->value;
  }
  return true;
}

// §4.10: `G73.7 <U'>Δi <W'>Δk R d`.
bool storeRepeat(TurningModal& m, const TurningWords& w, diag::Engine& diags) {
  const LatheAxes ax = latheAxes(w.plane);
  if (const auto& i = w[ax.u]) m.reliefP2 = i->value;
  if (const auto& k = w[ax.w]) m.reliefP1 = k->value;
  if (const auto& d = w['R']) {
    if (d->value < 1 || !isInteger(d->value) || d->value > 9999)
      return fail(diags, w, 'R', "the number of passes d must be an integer >= 1");
    m.repeatCount = static_cast<int>(std::lround(d->value));
  }
  return true;
}

// §4.12: `G74.7 R e` / `G75.7 R e`.
bool storeGroove(TurningModal& m, const TurningWords& w, diag::Engine& diags) {
  if (const auto& e = w['R']) {
    if (e->value < 0) return fail(diags, w, 'R', "the retract e must be >= 0");
    m.grooveRetract = e->value;
  }
  return true;
}

// §4.13: `G76.7 P(m)(r)(a) Q Δdmin R d`; P is a 6-digit code, not a length.
bool storeThread(TurningModal& m, const TurningWords& w, diag::Engine& diags) {
  if (const auto& p = w['P']) {
    if (p->value < 0 || !isInteger(p->value) || p->value > 999999)
      return fail(diags, w, 'P', "P must be the 6-digit code mmrraa");
    const long code = std::lround(p->value);
    const int mm = static_cast<int>(code / 10000), rr = static_cast<int>(code / 100 % 100);
    const int aa = static_cast<int>(code % 100);
    if (mm < 1) return fail(diags, w, 'P', "the finishing repetitions m must be 01..99");
    if (aa != 0 && aa != 29 && aa != 30 && aa != 55 && aa != 60 && aa != 80)
      return fail(diags, w, 'P',
                  fmt::format("tool angle {} is not one of 0, 29, 30, 55, 60, 80", aa));
    m.threadFinishPasses = mm, m.threadChamfer = rr, m.threadAngle = aa;
  }
  if (const auto& q = w['Q']) {
    if (q->value < 0) return fail(diags, w, 'Q', "the minimum cut must be >= 0");
    m.threadMinCut = q->value;
  }
  if (const auto& r = w['R']) {
    if (r->value < 0) return fail(diags, w, 'R', "the finishing allowance must be >= 0");
    m.threadAllowance = r->value;
  }
  return true;
}

bool hasAxisWord(const TurningWords& w) {
  const LatheAxes ax = latheAxes(w.plane);
  return w[ax.z] || w[ax.x] || w[ax.w] || w[ax.u];
}

} // namespace

LatheAxes latheAxes(motion::Plane plane) {
  const motion::PlaneAxes a = motion::axesOf(plane);
  constexpr char abs[] = "XYZ", inc[] = "UVW";
  return {a.first, a.second, a.normal, abs[a.first], abs[a.second], inc[a.first], inc[a.second]};
}

TurningBlock updateModal(TurningModal& m, const TurningWords& w, diag::Engine& diags) {
  bool ok = true;
  switch (w.cycle) {
  case TurningCycle::RoughTurning:
  case TurningCycle::RoughFacing:
  case TurningCycle::PatternRepeat:
    if (w['P'] && w['Q']) return TurningBlock::Run;
    if (w['P'] || w['Q']) {
      diags.error(diag::code::CyclePQNotFound, w.range,
                  fmt::format("{} needs both P (ns) and Q (nf) (cycles.md §4.7)", w.label));
      return TurningBlock::Error;
    }
    ok =
        w.cycle == TurningCycle::PatternRepeat ? storeRepeat(m, w, diags) : storeRough(m, w, diags);
    break;
  case TurningCycle::FaceGrooving:
  case TurningCycle::Grooving:
    if (hasAxisWord(w)) return TurningBlock::Run;
    ok = storeGroove(m, w, diags);
    break;
  case TurningCycle::MultipleThread:
    if (hasAxisWord(w)) return TurningBlock::Run;
    ok = storeThread(m, w, diags);
    break;
  default:
    return TurningBlock::Run; // G70.7 and the modal G77.7-G79.7 have one block
  }
  return ok ? TurningBlock::Stored : TurningBlock::Error;
}

} // namespace gcx::cycles
