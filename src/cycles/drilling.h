// Expansion of one NCT drilling-cycle hole into primitive operations (cycles.md §2.9, §3): a
// pure function of its inputs. The interpreter, per block executed in cycle mode:
//
//   holes = updateModal(modal, words, diags)           // drilling_state.h; nullopt: stop
//   for i in 1..holes:                                  // L repetitions (§2.6)
//     req.hole = hole position of repetition i          // increments applied once per i
//     req.position = current program position; req.initial = *modal.initial; ...
//     res = expandHole(req, blockRange, config, diags)  // nullopt: stop (reported)
//     execute res.ops; on i == 1 run the block's M S T at index res.auxAt (000:10360-10362)
//     position = res.end
//
// DrillOp::step is the manual's operation number: a G43/G44/G49 or new H of the block takes
// effect from the first op of step >= 3 (000:10376-10378); single block stops after ops 1, 3 and
// 10 (000:10365-10367). What the ops leave modal is the caller's to restore when it emits them
// (§1.2 rule 4): group 1, F after a G85/G89 retract feed, G91, the group-15 code.
//
// All positions are program coordinates in mm (the caller converts inch and resolves G90/G91,
// the I operator, U/V/W increments, polar and `,A` for the hole position). Programmable
// transformations are applied by the caller to the operations afterwards; drillScale and
// shiftMap keep the unscaled quantities their programmed size (§2.7).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cycles/drilling_state.h"
#include "cycles/ops.h"
#include "diag/diagnostic.h"
#include "motion/event.h"

namespace gcx::cycles {

struct DrillRequest {
  DrillCycle cycle = DrillCycle::Drill;
  std::string_view label; // the code as written ("G81"), for messages (DrillModal::label)
  DrillReturn ret = DrillReturn::Initial;
  /// G17/G18/G19: positioning plane and drilling axis Z/Y/X (§2.2). When a parallel axis
  /// drills (W in G17, 000:9496-9501), pass its value in the slot of Z and map the ops back.
  motion::Plane plane = motion::Plane::XY;
  Vec3 position = Vec3::Zero(); // where the tool is: start of op 1
  Vec3 hole = Vec3::Zero();     // the hole; its drilling-axis component is ignored
  double initial = 0;           // the initial level ini (DrillModal::initial)
  DrillVariables vars;          // Z R Q E P I J K (DrillModal::vars)
  double feed = 0;              // modal F as programmed (per minute or per revolution)
  double spindleSpeed = 0;      // modal S (rpm), written on RIGID_TAP ops
  /// +1 M3, -1 M4, 0 M5; nullopt when unknown. G74 needs M4, G76 G84 G86 G87 G88 need M3:
  /// CYC-SPINDLE-DIR warning otherwise (§3.1).
  std::optional<int> spindleDirection;
  bool cylindrical = false;        // G7.1 is on: drilling cycles are not allowed (000:2005-2013)
  bool radiusCompensation = false; // G41/G42 on: warning CYC-RADCOMP, holes uncompensated
  /// §2.7: |scale factor| of the active scaling on the drilling axis; Q and E keep their
  /// programmed physical size, so program-space pecks are Q/drillScale and E/drillScale.
  double drillScale = 1;
  /// §2.7: inverse of the in-plane linear part (rotation, mirror, scaling) of the active
  /// transformation, in the plane's (first, second) axes; applied to the I J K shift.
  Eigen::Matrix2d shiftMap = Eigen::Matrix2d::Identity();
};

using DrillOp = CycleOp;

struct DrillResult {
  std::vector<DrillOp> ops;
  Vec3 end = Vec3::Zero(); // the position after the hole (the return level, or r under G99)
  double r = 0, z = 0;     // the resolved R level and bottom of this hole
  /// Index into ops where the M S T functions of the block run on the first repetition: the
  /// end of op 1, i.e. before the first op of a later step (000:10360-10362).
  std::size_t auxAt = 0;
};

/// Expands one hole (§2.9, the op table §3.1, peck arithmetic §3.2). Moves of zero length
/// (< 0.0005 mm) are omitted (§1.2). Errors are reported at `where` (the block) or at the
/// word of a modal value and give nullopt: 2053 no Z/R, 2137 G76 with ORI=0, 2138 G84.2/.3
/// with INX=0, CYC-Q-MISSING (G73/G83 without Q > 0), CYC-Q-NEGATIVE, CYC-CYLINDRICAL,
/// 2004 feed F = 0, 2002 retract override I <= 0.
std::optional<DrillResult> expandHole(const DrillRequest& req, const SourceRange& where,
                                      const DrillConfig& config, diag::Engine& diags);

} // namespace gcx::cycles
