// Program statistics from the motion stream: path lengths, machining time at the programmed feed,
// dwell time, tool changes and the exact bounds of the tool path (`gcx run --stats`).
#pragma once
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "motion/event.h"
#include "motion/geometry.h"

namespace gcx::motion {

struct StatsOptions {
  double rapidRate = 5000; // mm/min; G0 speed is machine data, not part of the program
};

struct Stats {
  std::size_t rapidMoves = 0, feedMoves = 0, arcMoves = 0; // feedMoves counts lines only
  double rapidLength = 0;                                  // mm
  double feedLength = 0;                                   // mm, lines and arcs
  double arcLength = 0;                                    // mm, the arc part of feedLength
  double rapidSeconds = 0, feedSeconds = 0, dwellSeconds = 0;
  std::size_t dwells = 0, toolChanges = 0;
  /// Rapid and feed lines that turn rotary axes only (also in rapidMoves / feedMoves). Lengths
  /// are X Y Z, so theirs is 0. A feed line without X Y Z motion takes the travel of its extra
  /// axes over F (degrees/min for rotary-only moves, nct.md §3.4); such a rapid takes no time
  /// (rapid rates of the extra axes are machine data).
  std::size_t rotaryMoves = 0;
  /// Feed moves and dwells whose time is unknown: F0, or per-revolution with the spindle stopped.
  /// They add nothing to the times above.
  std::size_t untimed = 0;
  Box3 bounds; // of all motion, arcs exact; empty when nothing moved

  double totalLength() const { return rapidLength + feedLength; }
  double totalSeconds() const { return rapidSeconds + feedSeconds + dwellSeconds; }
};

class StatsCollector : public Sink {
public:
  explicit StatsCollector(StatsOptions opt = {});
  void event(const Event& e) override;
  const Stats& stats() const { return stats_; }

private:
  void addFeedTime(const Event& e, double length);

  StatsOptions opt_;
  Stats stats_;
  double spindleRpm_ = 0; // 0 while the spindle is stopped
};

/// A few aligned lines for people, e.g. "length       rapid 50.000 mm, feed ...".
std::string formatReport(const Stats& s);
/// {"moves":{"rapid":n,"feed":n,"arc":n,"rotary":n},"length_mm":{...},"time_s":{...},
///  "dwells":n,"tool_changes":n,"untimed":n,
///  "bounds":{"min":[x,y,z],"max":[x,y,z]} or null}; numbers rounded to 6 decimals.
nlohmann::json toJson(const Stats& s);

} // namespace gcx::motion
