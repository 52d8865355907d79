// Drilling cycles given by levels on the cycle axis (FMS-3000 G81-G88, fms3000.md §5.1-§5.2,
// cycles.md appendix A): U the start of the feed (point 1), Z the bottom (point 2), I the exit
// (point 4), under G91 each from the point before. A pure function of its inputs: the ops of
// one hole, in program coordinates, from the position where the cycle starts (point 0).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cycles/level_cycle.h"
#include "cycles/ops.h"

namespace gcx::cycles {

struct LevelDrillRequest {
  LevelCycle cycle = LevelCycle::Drill;
  std::string code = "the cycle";    // as the program wrote it, for messages: "G81"
  int axis = 2;                      // the cycle axis: 2 under G17, 1 under G18, 0 under G19
  int firstAxis = 0, secondAxis = 1; // the plane's axes (G88's X/Y shift)
  Vec3 position = Vec3::Zero();      // point 0
  bool incremental = false;          // G91: U from point 0, Z from point 1, I from point 2
  std::map<char, double> words;      // the cycle's parameters, remembered ones included
  double feed = 0;                   // F when not among the words
  int spindleDirection = 0;          // +1 M3, -1 M4, 0 stopped: what G84/G85/G88 restore
  double dwellSecondsPerUnit = 0.1;  // E and G87's W
  // FMS G156/G157 on the G83 sequence: the k-th step is V * stepFactor^(k-1); with a factor
  // below 1 a step never drops below minimumStep (once below, minimumStep to the end)
  double stepFactor = 1;
  double minimumStep = 0;
};

/// The ops, or the message of a missing, extra or bad parameter. Zero-length moves are left out.
std::variant<std::vector<CycleOp>, std::string> expandLevelHole(const LevelDrillRequest& req);

} // namespace gcx::cycles
