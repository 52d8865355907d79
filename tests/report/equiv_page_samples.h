// Two small paths that part at one corner, and the page describing them, for the report tests.
#pragma once
#include "motion/event_builders.h"
#include "report/equiv_page.h"
#include "report/path_recorder.h"

namespace gcx::report::test {

using motion::test::feed;
using motion::test::rapid;

/// A: a 100 × 60 rectangle after a rapid approach. B: the same but 70 high, so the two part at
/// X100 Y60 (B goes on up where A turns).
inline void recordSamplePaths(PathRecorder& a, PathRecorder& b, bool withB = true) {
  for (PathRecorder* r : {&a, &b}) {
    if (r == &b && !withB) continue;
    const double h = r == &a ? 60 : 70;
    r->event(rapid({0, 0, 10}, {0, 0, 0}));
    r->event(feed({0, 0, 0}, {100, 0, 0}));
    r->event(feed({100, 0, 0}, {100, h, 0}));
    r->event(feed({100, h, 0}, {0, h, 0}));
    r->event(feed({0, h, 0}, {0, 0, 0}));
  }
}

inline EquivPage samplePage() {
  EquivPage p;
  p.equivalent = false;
  p.summary = "end point Y differs by 10.000 mm (60 < 70)";
  p.a = {"A", "part<1>.nct", 330, 24.5, {}};
  p.b = {"B", "out&.ngc", 350, 26.25, {}};
  p.a.excerpt = {"part<1>.nct", 12, 4, {{11, "G1 X100 (A & B <C>)"}, {12, "G1 Y60"}}, ""};
  p.b.excerpt = {"out&.ngc", 7, 1, {{7, "G1 Y70"}, {8, "G1 X0"}}, "in O9010 called from 3"};
  p.divergence = motion::Vec3(100, 60, 0);
  p.maxDeviation = 0.00025;
  p.tolerance = 0.001;
  return p;
}

} // namespace gcx::report::test
