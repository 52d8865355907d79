// Expansion of the NCT turning cycles G70.7-G79.7 (cycles.md §4) into cycle ops: pure
// functions of the request, the stored first-block values and the block's words. The
// interpreter, per block with a turning-cycle code (or a modal G77.7-G79.7 repeat):
//
//   kind = updateModal(modal, words, diags)             // turning_state.h
//   Error -> stop; Stored -> nothing moves;
//   Run   -> req.start = current position (A); plane; then by cycle:
//     G71.7-G73.7: req.contour = blocks ns..nf executed on a scratch copy (contour.h),
//                  req.feed = F of the P/Q block, else the modal F; continue after nf;
//     G74.7-G79.7: req.end = the block's X(U) Z(W) resolved like a move's target (omitted
//                  axes: A), radius; req.taper = R (G76.7: of the block; G77.7-G79.7: modal
//                  while the cycle is active); req.feed = F (G76.7/G78.7: the lead);
//     G70.7:       re-execute ns..nf, then req.end = the position reached;
//   ops = expandTurning(req, modal, words, diags)       // nullopt: reported, stop
//
// Every cycle ends at A (G70.7: at its start point, §4.11). Positions are program coordinates
// in mm, diameter axes as radius, before the programmable transformations. CycleOp::step is the
// pass number (the final pass of G71.7/G72.7 is the last). In the P/Q block of G71.7-G73.7 and
// the first blocks of G74.7-G76.7 the U/V/W letters are cycle values, not axis moves.
#pragma once
#include <optional>
#include <vector>

#include "cycles/contour.h"
#include "cycles/ops.h"
#include "cycles/turning_state.h"
#include "diag/diagnostic.h"
#include "dialect/profile.h"

namespace gcx::cycles {

struct TurningRequest {
  motion::Plane plane = motion::Plane::ZX;
  Vec3 start = Vec3::Zero(); // A: where the tool is when the cycle runs
  Vec3 end = Vec3::Zero();   // G74.7-G79.7: the resolved end point; G70.7: the position reached
  double taper = 0;          // G76.7-G79.7: R, radius, signed (start minus end)
  double feed = 0;           // F; G76.7 and G78.7: the lead
  std::vector<ContourSegment> contour; // G71.7-G73.7: blocks ns..nf
  CycleChoices choices;                // the dialect's answers to cycles.md §9
};

/// The ops of one run of the cycle `words.cycle`. Errors (§7): CYC-PARAM at the offending word,
/// 2004 no feed, 2021 lead <= 0, and the contour errors of contour.h.
std::optional<std::vector<CycleOp>> expandTurning(const TurningRequest& req,
                                                  const TurningModal& modal,
                                                  const TurningWords& words, diag::Engine& diags);

} // namespace gcx::cycles
