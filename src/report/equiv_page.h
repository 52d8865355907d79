// What the equivalence report shows, as plain data the `gcx equiv` command fills in; the paths
// themselves come from a PathRecorder per side (report/equiv_html.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "motion/event.h"
#include "report/excerpt.h"

namespace gcx::report {

/// The source around one side's first divergence.
struct SourceExcerpt {
  std::string file;               // as the user named it
  int line = 0, column = 0;       // 1-based; 0: no location (nothing diverged, or an unknown one)
  std::vector<ExcerptLine> lines; // numbered lines around `line` (readExcerpt)
  std::string chain; // provenance: "in O9010 called from main.nct:12, loop iteration 3"
};

struct EquivSide {
  std::string name;  // "A", "B"
  std::string file;  // the program
  double length = 0; // path length, mm (up to the divergence when there is one)
  double time = 0;   // estimated time, s (likewise)
  SourceExcerpt excerpt;
};

struct EquivPage {
  bool equivalent = false;
  std::string summary; // one line: "same motion" or what differs and by how much
  EquivSide a, b;
  std::optional<motion::Vec3> divergence; // machine frame, where the paths part
  double maxDeviation = 0;                // mm, largest distance seen before the divergence
  double tolerance = 0.001;               // mm
};

} // namespace gcx::report
