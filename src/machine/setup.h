// The machine setup a program runs under (`--setup FILE`): work offsets, tool table, machine
// parameters, preset macro variables, start position, block-skip switches, reference points.
// A JSON file; every section is optional and a missing one means the reference machine
// (machine at 0,0,0, no offsets). docs/setup.md has the whole format:
//   {"work_offsets": {"G54": [x, y, z], "G54.1 P1": [x, y, z], "common": [x, y, z]},
//    "tools": {"1": {"length": 101.6, "radius": 5}, "11": {"turning": [152.3, 0, 96.5]}},
//    "parameters": {...}, "variables": {"#500": 1.5},   (the program's dialect's)
//    "nct": {"parameters": {...}, "variables": {...}},  (a dialect's own section)
//    "initial_position": [x, y, z],
//    "block_skip": [1, 3],
//    "reference_points": {"1": [x, y, z], "2": [x, y, z]},
//    "rapid_rate": 10000}
// The keys of work offsets, parameters and variables are the dialect's (setup_syntax.h).
// Lengths in mm, positions in machine coordinates. `//` and `/* */` comments are allowed.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "diag/diagnostic.h"
#include "ir/source.h"
#include "machine/setup_syntax.h"

namespace gcx::machine {

struct ToolData {
  double length = 0; // mm, offset register n = tool n
  double radius = 0; // mm
  /// The cutting edge's nose radius Rt, >= 0 (WL4's lathe tool data, wl4.md §4.1), mm
  double noseRadius = 0;
  /// G43.7 turning offsets X Y Z (geometry + wear), mm in the machine frame (nct.md §3.16)
  std::array<double, 3> turning{0, 0, 0};
};

struct Setup {
  /// Machine coordinates of each work zero. Key as written: "G54".."G59", "G54.1 P1"..
  /// "G54.1 P99", "common" (the G10 L2 P0 external shift added to all of them).
  std::map<std::string, std::array<double, 3>> workOffsets;
  std::map<int, ToolData> tools; // 0..999
  /// The program's dialect's parameters under their canonical keys (SetupSyntax::parameterKey).
  std::map<std::string, double> parameters;
  std::map<int, double> variables; // #n -> value, the program's dialect's
  std::array<double, 3> initialPosition{0, 0, 0};
  std::set<int> blockSkip; // switches that are ON, 1..9
  /// G28/G30 reference points 1..4 in machine coordinates; all four are always present.
  std::map<int, std::array<double, 3>> referencePoints{{1, {}}, {2, {}}, {3, {}}, {4, {}}};
  double rapidRate = 10000; // mm/min, for time estimates

  /// The offset stored under key ("G54", "G54.1 P7", "common"), zeros if absent.
  std::array<double, 3> workOffset(const std::string& key) const;
  /// The parameter's value under its canonical key, or fallback if the setup does not set it.
  double parameter(const std::string& key, double fallback) const;
};

/// Reads a setup file for a program of dialects.own; on any error reports located diagnostics
/// (all of them, not only the first) and returns nullopt. An unreadable file is GCX024 without
/// a location.
std::optional<Setup> loadSetup(const std::string& path, SourceManager& sources, diag::Engine& diags,
                               const SetupDialects& dialects);
/// Parses setup text already registered as file (locations point into it).
std::optional<Setup> parseSetup(const std::string& text, FileId file, diag::Engine& diags,
                                const SetupDialects& dialects);

} // namespace gcx::machine
