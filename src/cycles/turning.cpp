// The turning-cycle dispatcher, the simple cycles G77.7/G78.7/G79.7 (cycles.md §4.4-§4.6), the
// G70.7 return (§4.11) and the word helpers the other turning cycles share.
#include "cycles/turning.h"

#include <fmt/format.h>

#include "cycles/turning_cycles.h"
#include "diag/codes.h"

namespace gcx::cycles {

namespace {

// §4.4 G77.7 / §4.5 G78.7: down P2 to the taper start, along to the end, out, back.
std::vector<CycleOp> turningCycle(const TurningRequest& req, bool thread) {
  TurningPath path(req.start, req.plane);
  const Vec2 a = path.start(), e = path.lathe(req.end);
  path.rapid({a[0], e[1] + req.taper}); // 1: RAPID to P2 = x_e + R
  if (thread)
    path.thread(e, req.feed); // 2: G33, pull-out chamfer 0
  else
    path.feed(e, req.feed); // 2: FEED to (x_e, z_e)
  if (thread)
    path.rapid({e[0], a[1]}); // 3: RAPID out to x_A
  else
    path.feed({e[0], a[1]}, req.feed); // 3: FEED out to x_A
  path.rapid(a);                       // 4: RAPID back to z_A
  return std::move(path.ops());
}

// §4.6 G79.7: along P1 to the taper start, across to the end, back along P1, out.
std::vector<CycleOp> facingCycle(const TurningRequest& req) {
  TurningPath path(req.start, req.plane);
  const Vec2 a = path.start(), e = path.lathe(req.end);
  path.rapid({e[0] + req.taper, a[1]}); // 1: RAPID to P1 = z_e + R
  path.feed(e, req.feed);               // 2: FEED to (x_e, z_e)
  path.feed({a[0], e[1]}, req.feed);    // 3: FEED to P1 = z_A
  path.rapid(a);                        // 4: RAPID to P2 = x_A
  return std::move(path.ops());
}

} // namespace

std::optional<double> radiusWord(const TurningWords& w, char c) {
  if (const auto& v = w[c]) return v->value;
  return std::nullopt;
}

Vec2 allowance(const TurningWords& w) {
  const LatheAxes ax = latheAxes(w.plane);
  auto value = [&](char c, int axis) {
    const auto& v = w[c];
    if (!v) return 0.0;
    return (w.diameter >> axis) & 1u ? v->value / 2 : v->value;
  };
  return {value(ax.w, ax.p1), value(ax.u, ax.p2)};
}

bool checkFeed(double f, const TurningWords& w, bool lead, diag::Engine& diags) {
  if (f > 0) return true;
  if (lead)
    diags.error(diag::code::ThreadSpecification, w.at('F'),
                fmt::format("{}: thread lead F must be > 0 (000:1668-1673)", w.label));
  else
    diags.error(diag::code::MissingData, w.at('F'), fmt::format("{}: no feed F", w.label));
  return false;
}

void paramError(const TurningWords& w, char c, const std::string& why, diag::Engine& diags) {
  diags.error(diag::code::CycleParam, w.at(c), fmt::format("{}: {} (cycles.md §7)", w.label, why));
}

std::optional<std::vector<CycleOp>> expandTurning(const TurningRequest& req,
                                                  const TurningModal& modal,
                                                  const TurningWords& words, diag::Engine& diags) {
  switch (words.cycle) {
  case TurningCycle::Finishing: { // §4.11: the blocks ran; RAPID back to the start point
    TurningPath path(req.end, req.plane);
    path.rapid(path.lathe(req.start));
    return std::move(path.ops());
  }
  case TurningCycle::RoughTurning:
  case TurningCycle::RoughFacing:
    return expandStockRemoval(req, modal, words, diags);
  case TurningCycle::PatternRepeat:
    return expandPatternRepeat(req, modal, words, diags);
  case TurningCycle::FaceGrooving:
  case TurningCycle::Grooving:
    return expandGrooving(req, modal, words, diags);
  case TurningCycle::MultipleThread:
    return expandThreading(req, modal, words, diags);
  case TurningCycle::TurningPass:
  case TurningCycle::ThreadPass: {
    const bool thread = words.cycle == TurningCycle::ThreadPass;
    if (!checkFeed(req.feed, words, thread, diags)) return std::nullopt;
    return turningCycle(req, thread);
  }
  case TurningCycle::FacingPass:
    if (!checkFeed(req.feed, words, false, diags)) return std::nullopt;
    return facingCycle(req);
  }
  return std::nullopt;
}

} // namespace gcx::cycles
