// The machine setup of a differential test program: the sidecar `NAME.setup.json` next to
// `NAME.nct`, e.g.
//   {"work_offsets": {"G55": [x, y, z]}, "tools": {"1": {"length": 101.6, "radius": 5}}}
// Lengths in mm. Work offsets not given are zero; tool keys are the tool (and H/D) numbers.
// This is the subset of gcx's --setup file (src/machine/setup.h) that rs274 can be given:
// "parameters", "variables", "reference_points" and the dialect sections ({"nct":
// {"parameters": ..., "variables": ...}}) are ignored, "rapid_rate" is kept for times; a "common"
// offset, "G54.1 Pn" systems, a non-zero "initial_position" or "block_skip" switches are
// errors (rs274 has no way to take them), so such a program is outside the common subset.
// `//` and `/* */` comments are allowed, as in gcx's reader.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "oracle/rs274.h"

namespace gcx::oracle {

struct OracleSetup {
  std::vector<OracleWorkOffset> workOffsets; // index 1..6 = G54..G59
  std::vector<OracleTool> tools;             // diameter = 2 * radius
  double rapidRate = 10000;                  // mm/min, for time estimates (not given to rs274)
};

/// Parses the sidecar text; false (and a message in error) when it is malformed.
bool parseSetupJson(std::string_view text, OracleSetup& out, std::string& error);

/// Puts the setup into rs274 options (work offsets through the parameter file, tools through
/// the tool table).
void applySetup(const OracleSetup& setup, Rs274Options& options);

} // namespace gcx::oracle
