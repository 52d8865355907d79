// Comparing two motion-event lists (gcx's and the oracle's) within a tolerance: the first
// divergence, with both sides' source lines, as a readable report.
//
// Both lists are normalised the same way before the 1:1 walk:
//  1. only the kinds in CompareOptions::kinds are kept (default Rapid, Feed, Arc, Dwell and the
//     oriented spindle stop, which decides whether a boring bar may shift sideways), so
//     events one side does not emit (spindle, coolant, messages, plane/units/feed-mode
//     changes, ...) do not matter;
//  2. zero-length straight moves are dropped (rs274 prints e.g. `G0 X0` at X0, G85 prints one);
//     a move that only turns a rotary axis is not zero-length;
//  3. consecutive collinear Feed pieces in the same direction (and with the same feed when
//     feeds are compared) are merged into one line, so a straight move split differently on
//     either side still matches. Every interior point must lie within the tolerance of the
//     merged line, so chords of a shallow arc are not merged into a straight line. Collinear
//     means in axis space: X Y Z and the extra axes A B C U V W together.
// Then: same kind in order; straight moves by start and end; arcs by plane, start, end,
// centre, direction and extra turns; dwells by time; optionally feeds. Starts and ends include
// the extra axes A B C (degrees) and U V W (mm).
//
// Tolerance: points are compared per coordinate (max norm), angles in degrees alike. rs274 prints 4
// decimals in the program's units, so in mm its rounding is <= 5e-5 mm (< the default 1e-4); in
// inch programs it is up to 1.27e-3 mm - use a larger tolerance there or programs exact at 4 inch
// decimals.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "ir/source.h"
#include "motion/event.h"

namespace gcx::oracle {

struct CompareOptions {
  double tolerance = 1e-4;      // mm: points, centres; degrees: rotary axes
  double dwellTolerance = 1e-4; // seconds
  bool compareFeed = true;      // Feed/Arc feed values and per-revolution flag
  double feedTolerance = 1e-3;  // mm/min (or mm/rev)
  bool dropZeroLength = true;
  bool mergeCollinearFeeds = true;
  bool mergeCollinearRapids = false; // rapids are only defined by their end points anyway
  std::vector<motion::Kind> kinds = {motion::Kind::Rapid, motion::Kind::Feed, motion::Kind::Arc,
                                     motion::Kind::Dwell, motion::Kind::SpindleOrient};
  std::string leftName = "gcx";
  std::string rightName = "rs274";
  /// Optional: to print file names and the text of the source lines in the report.
  const SourceManager* leftSources = nullptr;
  const SourceManager* rightSources = nullptr;
};

struct CompareResult {
  bool equivalent = false;
  std::size_t matched = 0; // normalised events that matched before the divergence
  /// Indices into the input lists of the first divergent events (npos: that side had ended).
  std::size_t leftIndex = npos;
  std::size_t rightIndex = npos;
  std::string report; // empty when equivalent
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  explicit operator bool() const { return equivalent; }
};

CompareResult compareEvents(const std::vector<motion::Event>& left,
                            const std::vector<motion::Event>& right,
                            const CompareOptions& options = {});

} // namespace gcx::oracle
