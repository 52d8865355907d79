// A drilled hole by its meaning, the neutral form a drilling cycle is lifted into when a
// translation keeps cycles (docs/translation.md): read back from the motion the source's cycle
// ran, whichever dialect wrote it (NCT G81 R Z, FMS-3000 G81 U Z I, WL4 G81 calling %81), and
// lowered by the target's HoleLowering (translate/hole_lowering.h) into its own cycle.
// Levels are machine-frame Z in mm, like the rest of a translation to another dialect.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "cycles/drilling_state.h"
#include "motion/event.h"

namespace gcx::xlate {

enum class HoleKind : unsigned char {
  Drill,       // feed to the bottom, rapid out
  DrillDwell,  // the same with a dwell at the bottom
  BoreFeedOut, // feed to the bottom, feed back to the R level, rapid on to the exit
  Peck,        // equal pecks from R, back to R after each and down to a clearance above the last
  ChipBreak,   // equal pecks from R, each after a short rapid back to break the chip
};

/// "drilling", "drilling with dwell", "boring with feed out", "peck drilling", ...
std::string_view holeKindName(HoleKind k);

/// The drilling cycle of the cycles library that drills such a hole (NCT's and LinuxCNC's codes
/// name their cycles by it).
cycles::DrillCycle drillCycleOf(HoleKind k);

struct Hole {
  HoleKind kind = HoleKind::Drill;
  double x = 0, y = 0;     // the hole in the XY plane; the cycle drills along Z
  double start = 0;        // Z where the cycle begins, above the hole
  double r = 0;            // Z where the feed starts
  double bottom = 0;       // Z of the bottom
  double exit = 0;         // Z where the tool is left
  double feed = 0;         // mm/min into the hole
  double retractFeed = 0;  // BoreFeedOut: mm/min back to r
  double dwell = 0;        // DrillDwell: seconds at the bottom
  double peck = 0;         // Peck: the depth of each peck
  double clearance = 0;    // Peck: how far above the last depth the rapid down stops
  double backOff = 0;      // ChipBreak: how far each rapid backs off
  bool positioned = false; // its first event is the rapid to x, y at `start`
  SourceLoc at;            // the block of the cycle (the call of WL4's %8n)
};

/// What the events at the front of a buffer are.
struct HoleMatch {
  enum Status { NoHole, NeedMore, Found } status = NoHole;
  Hole hole;
  std::size_t length = 0; // Found: the events the hole takes
};

/// Whether `events` start with one hole of a drilling cycle: an optional rapid in the XY plane,
/// an optional rapid down to R, one feed down (or equal pecks, each back to R and down again to
/// a clearance above the last depth, or each after a short rapid back), an optional dwell, and
/// a rapid (or feed) out,
/// all on one line in Z, from one cycle: one block, or one call of a cycle program (the
/// provenance chain). Without `complete`, an answer that a later event could change is
/// NeedMore. `before`: the event written just before, which must not belong to the same cycle
/// (a cycle with more moves than a hole, such as a peck, is not lifted halfway).
HoleMatch matchHole(std::span<const motion::Event> events, bool complete,
                    const motion::Event* before);

} // namespace gcx::xlate
