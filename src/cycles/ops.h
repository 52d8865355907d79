// The canonical operations every canned cycle expands into (cycles.md §1.1): drilling, turning
// and (later) the FMS-3000 and WL4 cycles all produce lists of CycleOp, and the interpreter
// executes such a list the same way whatever cycle made it. Positions are program coordinates
// in mm (diameter axes as radius), before the programmable transformations.
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace gcx::cycles {

using Vec3 = Eigen::Vector3d;

enum class OpKind : unsigned char {
  Rapid,           // G0 to `to`
  Feed,            // G1 to `to` at `feed`
  ArcCW,           // G2 to `to` about `center` in the active plane at `feed`
  ArcCCW,          // G3
  Thread,          // G33 to `to`: spindle-synchronised, `value` = lead (mm per revolution)
  Dwell,           // G4 P`value`: G04 units (s under G94, rev under G95)
  SpindleCW,       // M3
  SpindleCCW,      // M4
  SpindleStop,     // M5
  SpindleOrient,   // M19 (oriented stop)
  CloseLoop,       // M`value` (DrillConfig::closeLoopMCode): close the spindle position loop
  ProgramStop,     // M0: the operator may act by hand, then presses START
  OverrideLock,    // NOOVR-ON, G63: overrides at 100 %, feed hold ignored
  OverrideRestore, // NOOVR-OFF: the group-15 code that was active before (G64 by default)
  RigidTap,        // RTAP: to `to` at `feed`, spindle `value` rpm turning `direction`,
                   // `override` % retract override (100 when none applies)
};

struct CycleOp {
  OpKind kind = OpKind::Rapid;
  int step = 0;               // the manual's operation number of a drilling cycle; pass number
  Vec3 to = Vec3::Zero();     // moves: the end point; other ops: where they run
  Vec3 center = Vec3::Zero(); // ArcCW, ArcCCW
  double feed = 0;            // Feed, arcs, RigidTap
  double value = 0;           // Dwell: P; CloseLoop: M code; RigidTap: S; Thread: lead
  int direction = 0;          // RigidTap: +1 CW, -1 CCW
  double override = 100;      // RigidTap
};

/// Appends a straight move from `at` to `to` unless it is shorter than 0.0005 mm (the FMS-3000
/// resolution: zero-length moves are not emitted), and moves `at` there.
inline void appendMove(std::vector<CycleOp>& ops, Vec3& at, OpKind kind, const Vec3& to,
                       double feed = 0) {
  if ((to - at).norm() < 0.0005) return;
  CycleOp op;
  op.kind = kind;
  op.to = to;
  op.feed = feed;
  ops.push_back(op);
  at = to;
}

/// The ops in the text form of the spec's vectors (cycles.md §1.1, §8), joined by " | ": each
/// position lists the axes that change from the previous one (start first), numbers rounded to
/// 4 decimals: "G0 X10 Y10 | G0 Z2 | G1 Z-5 F120 | G0 Z2". `axes` names the three slots;
/// `diameter` (bit a: slot a) prints that axis doubled, as a diameter-programmed program would.
std::string opsText(const Vec3& start, const std::vector<CycleOp>& ops,
                    std::string_view axes = "XYZ", unsigned diameter = 0);

} // namespace gcx::cycles
