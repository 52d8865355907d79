// The internal contour cycles (WL4 G76, G77 P Q, G78 P Q; wl4.md §5.6): passes that follow a
// finished-part contour given by block numbers, in lathe coordinates (z = P1, x = P2, radius).
// Pure functions of the request; the interpreter (machine/contour_cycles.cpp) finds and traces
// the contour, applies the allowances (a shift, or an equidistant it computes with the
// compensation geometry) and runs the ops. The pass geometry is the spec's reference algorithm
// [D] (the manual's figures are lost, wl4.md §5.6):
//
//   Levels (G77 P Q along lathe X, G78 P Q along lathe Z): levels x_k = x_A + s·E·k toward the
//     contour's start P' (s = sign(x_P' - x_A)), P's own level and the contour's extreme, the
//     last clipped there. On each level, the stretches of the line outside the part: the one
//     from A gets the infeed (G0 or G1) from (x_(k-1), z_A) to (x_k, z_A), a G1 along the cut
//     axis until the contour is met, a G1 out along it back to x_(k-1) (or to where it turns
//     deeper), a G0 back to z_A. A closed zone (the contour turns back toward the levels, a
//     groove) is cut level by level [D]: G0 at A's level over its near wall, G0 down onto the
//     wall at x_(k-1), G1 along the wall to x_k, across, up the far wall, G0 up to A's level.
//     At the end G0 to A. The contour is monotonic along the cut axis (else CYC-NONMONOTONIC).
//   Passes (G76): one per contour given, each G0|G1 A -> P_i, along the contour, G0 to A.
//   Finishing (no E): G0|G1 A -> P', along the contour, G0 to x_A, G0 to z_A.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cycles/contour.h"
#include "diag/diagnostic.h"

namespace gcx::cycles {

enum class ContourCycle : unsigned char {
  Approach,     // passes along the contour shifted by a shrinking allowance (WL4 G76)
  Longitudinal, // levels along lathe X, cuts along Z (WL4 G77 P Q)
  Transverse,   // levels along lathe Z, cuts along X (WL4 G78 P Q)
};

struct ContourCycleRequest {
  ContourCycle cycle = ContourCycle::Longitudinal;
  std::string label = "the cycle"; // the code as written, for messages: "G77"
  motion::Plane plane = motion::Plane::ZX;
  Vec3 start = Vec3::Zero();     // A, program coordinates (radius)
  OpKind infeed = OpKind::Rapid; // G0 or G1 of the block
  double feed = 0;               // F, inside the cycle only
  std::optional<double> depth;   // E > 0 (radius, mm): roughing; none: one finishing pass
  SourceRange block, depthWord;  // where errors point
  /// The contour as programmed, block by block: the manual's monotonicity condition is its.
  Profile programmed;
  /// The contours to follow, each with a = A and a' = its start P', allowances applied: one for
  /// Longitudinal, Transverse and every finishing pass; G76 roughing: one per pass, in order.
  std::vector<Profile> contours;
};

/// G76 roughing: the number of passes, ceil(initial allowance / depth), at least 1.
int approachPasses(double initialAllowance, double depth);

/// The ops of the cycle, ending at A; nullopt when reported (CYC-PARAM, CYC-NONMONOTONIC,
/// CYC-CONTOUR-DEGENERATE, 2004 no feed).
std::optional<std::vector<CycleOp>> expandContourCycle(const ContourCycleRequest& req,
                                                       diag::Engine& diags);

} // namespace gcx::cycles
