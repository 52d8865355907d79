// Spirals (an arc whose end radius differs from its start radius), which neither RS274/NGC nor
// the dialects can write as one block, as the lines every writer of flat motion puts in their
// place.
#pragma once
#include <vector>

#include "motion/event.h"
#include "motion/geometry.h"

namespace gcx::emit {

/// True when the arc must be written as lines. From the radii alone: the angles ArcGeometry
/// adds (two atan2 and a fmod) are needed only for a spiral's lines.
bool isSpiral(const motion::Event& arc);
/// True when the arc's producer declares it a circle although its end is off the start radius
/// within the dialect's arc tolerance (equal radii in the event, WL4 §3.4): canonical motion
/// writes it as G2/G3 as programmed.
inline bool declaredCircle(const motion::Event& e) {
  return e.startRadius > 0 && e.startRadius == e.endRadius;
}

struct LinePoint {
  motion::Vec3 at;
  motion::Extra extra;
};

/// The end points of lines within `chord` mm of the spiral; the extra axes move linearly along
/// it like the height, and the last point is the event's end.
std::vector<LinePoint> spiralLines(const motion::Event& e, const motion::ArcGeometry& arc,
                                   double chord);

} // namespace gcx::emit
