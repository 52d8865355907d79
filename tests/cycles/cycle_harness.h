// Runs the program text of a cycles.md §8 vector on the real interpreter and prints the motion
// of every source block the way the vectors do ("N2: G0 X10 Y10 | G0 Z2 | G1 Z-5 F120"): each
// move names the axes whose (rounded) value changes, diameter axes (`diameter` bits) doubled;
// feeds carry F; spindle-synchronised feeds print as RTAP with the spindle speed and direction
// they run with, or as G33 with their lead when `threads` is set. Blocks are labelled by their
// N number, or "#line" without one. Programs with turning contours run through the expansion
// pass (it holds the program for the contour's blocks), the others stream.
#pragma once
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "cycles/drilling_state.h"
#include "support/run_support.h"

namespace gcx::test {

class CycleHarness {
public:
  cycles::DrillConfig config; // written into the setup's parameters (cycles.md §2.8)
  bool wIsAxis = false;       // N0103: W is an axis parallel to Z (cycles.md §2.2)
  machine::Setup setup;       // anything else
  unsigned diameter = 0;      // bit a: axis a is printed as a diameter
  bool threads = false;       // synchronised feeds are G33 threads, not rigid taps

  /// Runs the program; false when it reported an error (error() names it).
  bool run(const std::string& program) {
    labelLines(program);
    applyConfig();
    const bool whole =
        program.find("G70.7") != std::string::npos || program.find("G71.7") != std::string::npos ||
        program.find("G72.7") != std::string::npos || program.find("G73.7") != std::string::npos;
    ProgramRun r =
        whole ? runMacro({{"O0001.nct", program}}, "O0001.nct", {}, setup) : runNct(program, setup);
    for (std::string& e : r.errors) // "O0001.nct:2:1 CODE" -> "2:1 CODE"
      if (e.starts_with("O0001.nct:")) e.erase(0, 10);
    for (const motion::Event& e : r.events)
      render(e);
    // "test.nct:2:1: warning: ... [CODE]" -> "2:1 CODE"
    static const std::regex warning(R"(^[^:]*:(\d+:\d+): warning: .*\[([^\]]+)\]$)");
    std::istringstream rendered(r.rendered);
    for (std::string line; std::getline(rendered, line);)
      if (std::smatch m; std::regex_match(line, m, warning))
        warnings.push_back(fmt::format("{} {}", m[1].str(), m[2].str()));
    if (r.errors.empty()) return true;
    const std::string& first = r.errors.front(); // "line:col CODE"
    const int line = std::stoi(first);
    const auto space = first.find(' ');
    error_ = fmt::format("{} {} {}", label(line), first.substr(space + 1), first.substr(0, space));
    return false;
  }
  /// "N2 2053 2:1": the block, the code and the location of the first error.
  const std::string& error() const { return error_; }

  std::map<std::string, std::string> out; // block label -> its motion
  std::vector<std::string> warnings;      // "line:col CODE"

private:
  void labelLines(const std::string& program) {
    std::istringstream in(program);
    static const std::regex n(R"(^\s*(?:/\d?)?\s*(N\d+))");
    int line = 0;
    for (std::string text; std::getline(in, text);) {
      std::smatch m;
      ++line;
      if (std::regex_search(text, m, n)) labels_[line] = m[1];
    }
  }
  std::string label(int line) const {
    auto it = labels_.find(line);
    return it != labels_.end() ? it->second : fmt::format("#{}", line);
  }
  void applyConfig() {
    auto& p = setup.parameters;
    p["N1500"] = config.returnG73, p["N1501"] = config.clearanceG83;
    p["N1502"] = config.extractionG85G89, p["N1504"] = config.tapReturn;
    p["N1505"] = config.tapClearance, p["N1506"] = config.tapExtraction;
    p["N1507"] = config.tapReturnOverride, p["N1503.TSC"] = config.tapOrient;
    p["N1503.PTC"] = config.tapNormalPeck, p["N1503.EOE"] = config.extractionEnabled;
    p["N1503.ROE"] = config.returnEnabled, p["N0607.ORI"] = config.orient;
    p["N0607.INX"] = config.indexable, p["N0823"] = config.closeLoopMCode;
    if (wIsAxis) p["N0103.W"] = 1;
  }
  void render(const motion::Event& e) {
    std::string s;
    switch (e.kind) {
    case motion::Kind::Rapid:
    case motion::Kind::Feed:
      s = e.kind == motion::Kind::Rapid ? "G0" : e.lead > 0 ? (threads ? "G33" : "RTAP") : "G1";
      for (int a = 0; a < 3; ++a) {
        const double k = (diameter >> a) & 1u ? 2 : 1;
        if (n4(k * e.end[a]) != n4(k * e.start[a]))
          s += fmt::format(" {}{}", "XYZ"[a], n4(k * e.end[a]));
      }
      for (int a = 0; a < 6; ++a)
        if (n4(e.extraEnd[a]) != n4(e.extraStart[a]))
          s += fmt::format(" {}{}", motion::kExtraAxisNames[a], n4(e.extraEnd[a]));
      if (e.lead > 0 && threads) {
        s += " F" + n4(e.lead);
        break;
      }
      // a tap prints the F of a G94 program: its lead times the spindle speed
      if (e.kind == motion::Kind::Feed) s += " F" + n4(e.lead > 0 ? e.lead * speed_ : e.feed);
      if (e.lead > 0) s += fmt::format(" S{} DIR={}", n4(speed_), direction_ > 0 ? "CW" : "CCW");
      break;
    case motion::Kind::Arc:
      s = e.clockwise ? "G2" : "G3";
      for (int a = 0; a < 3; ++a) {
        const double k = (diameter >> a) & 1u ? 2 : 1;
        if (n4(k * e.end[a]) != n4(k * e.start[a]))
          s += fmt::format(" {}{}", "XYZ"[a], n4(k * e.end[a]));
      }
      s += " R" + n4(e.startRadius) + " F" + n4(e.feed);
      break;
    case motion::Kind::Dwell:
      s = "G4 P" + n4(e.value);
      break;
    case motion::Kind::Spindle:
      speed_ = e.value, direction_ = e.direction;
      s = e.direction > 0 ? "M3" : e.direction < 0 ? "M4" : "M5";
      break;
    case motion::Kind::SpindleOrient:
      s = "M19";
      break;
    case motion::Kind::Stop:
      s = e.optional ? "M1" : "M0";
      break;
    case motion::Kind::Coolant:
      s = "M" + n4(e.value);
      break;
    case motion::Kind::ToolChange:
      s = "T" + n4(e.value) + " M6";
      break;
    case motion::Kind::OverrideLock:
      s = e.value != 0 ? "G63" : "G64";
      break;
    default:
      return; // ends, modal changes
    }
    std::string& text = out[label(e.from.at.line)];
    text += (text.empty() ? "" : " | ") + s;
  }

  std::map<int, std::string> labels_;
  std::string error_;
  double speed_ = 0;
  int direction_ = 0;
};

/// A cycle variable as programmed, without a location (for direct calls of the library).
inline cycles::DrillWord val(double v, bool incremental = false) {
  return cycles::DrillWord{v, incremental, {}};
}

/// Runs a program that must not fail (an error fails the test) under these drilling parameters.
inline CycleHarness run(const std::string& program, cycles::DrillConfig config = {}) {
  CycleHarness h;
  h.config = config;
  EXPECT_TRUE(h.run(program)) << h.error();
  return h;
}

/// Runs a program that must fail; its first error as "label code line:col".
inline std::string failing(const std::string& program, cycles::DrillConfig config = {},
                           bool wIsAxis = false) {
  CycleHarness h;
  h.config = config;
  h.wIsAxis = wIsAxis;
  EXPECT_FALSE(h.run(program));
  return h.error();
}

} // namespace gcx::test
