// The streaming comparison: both sides' motion events are read as they come, turned into
// pieces carrying their state, and walked together along the path, so it does not matter how
// either side cuts its path into segments (docs/equivalence.md). Memory is constant: only the
// current piece of each side is held.
#pragma once
#include <vector>

#include "equiv/piece.h"
#include "equiv/result.h"

namespace gcx::equiv {

struct WalkOptions {
  double tolerance = 0.001; // mm: how far the paths may be apart
  /// mm added to the tolerance for the resolution of the numbers read: 1e-6 for the 6 decimals
  /// of gcx's canonical output, 1e-4 when a side is read through rs274 (it prints 4 decimals).
  double resolution = 1e-6;
  bool strictRapids = false; // compare rapids by their path, not by the end of each run
  double rapidRate = 5000;   // mm/min, for the times in the statistics (A, and B unless...)
  double rapidRateB = 0;     // ... B's own, when > 0
};

/// A pull source of one side's events.
class EventSource {
public:
  virtual ~EventSource() = default;
  /// The next event; false at the end of the program.
  virtual bool next(motion::Event& e) = 0;
};

/// Events from a list (tests, and the one-shot API).
class ListSource : public EventSource {
public:
  explicit ListSource(const std::vector<motion::Event>& events) : events_(events) {}
  bool next(motion::Event& e) override;

private:
  const std::vector<motion::Event>& events_;
  std::size_t i_ = 0;
};

EquivResult walk(EventSource& a, EventSource& b, const WalkOptions& options = {});

} // namespace gcx::equiv
