// What an equivalence check found: equivalent, or the first divergence with both sides' events
// and provenance, the largest deviation before it, and both programs' path lengths and times.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "motion/event.h"
#include "motion/stats.h"

namespace gcx::equiv {

enum class DivergenceKind {
  Geometry, // the paths part: an end point, or a deviation larger than the tolerance
  State,    // a segment moves with another feed, spindle, coolant, tool, or rapid vs feed
  Event,    // dwells, stops or tool changes differ, or one side has one the other lacks
  Ended,    // one program ended while the other still moves
};
const char* kindName(DivergenceKind k);

/// One side at the divergence: the event to blame (absent when that side had ended).
struct SideAt {
  bool present = false;
  motion::Event event;
  std::string description; // motion::describeEvent() of the event
};

struct Divergence {
  DivergenceKind kind = DivergenceKind::Geometry;
  std::string summary;                       // "end point X differs by 0.500 mm"
  double amount = 0;                         // mm (geometry), or the value difference
  motion::Vec3 where = motion::Vec3::Zero(); // machine frame, where it happens
  SideAt a, b;
  /// State: the blocks that set the differing spindle or coolant state (line 0: not set, or
  /// not that kind of state).
  SourceLoc stateSetA, stateSetB;
};

/// Per program: what was compared and its statistics up to where the comparison stopped (the
/// whole program when equivalent).
struct SideSummary {
  std::size_t segments = 0; // motion pieces compared (rapid runs count once)
  std::size_t events = 0;   // dwells, stops, tool changes compared
  motion::Stats stats;
};

struct EquivResult {
  bool equivalent = false;
  std::optional<Divergence> divergence;
  double maxDeviation = 0; // mm, largest distance between the paths before the divergence
  SideSummary a, b;
};

} // namespace gcx::equiv
