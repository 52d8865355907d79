// The motion trace as JSON Lines: one object per event, with provenance (`gcx run --trace`).
//
// Keys, in this order, only where they apply:
//   kind     "rapid" "feed" "arc" "dwell" "spindle" "spindle_orient" "tool_change" "coolant"
//            "stop" "end" "message" "plane" "units" "feed_mode"
//   start, end                      motion: [x,y,z] in mm, machine frame
//   extra_start, extra_end          motion, only when an extra axis is off zero at either end:
//                                   {"A":0,"C":90}, the axes off zero at either end (A B C in
//                                   degrees, U V W in mm)
//   center, plane, dir, turns       arc: centre [x,y,z], "XY"|"ZX"|"YZ", "cw"|"ccw", extra turns
//   points                          arc in sample mode, instead of the four above: [[x,y,z],...]
//                                   from start to end at the chord tolerance
//   feed, per_rev                   feed and arc: mm/min (mm/rev with "per_rev":true)
//   seconds | revolutions           dwell
//   speed, dir                      spindle: rpm, "cw"|"ccw"|"stop"
//   value                           spindle_orient
//   tool                            tool_change
//   code                            coolant: 7, 8 or 9
//   optional                        stop: true for M1
//   text                            message
//   plane, axes                     plane: "XY"|"ZX"|"YZ", and the axis names when parallel
//                                   axes form it ("UV")
//   code                            units: 20 or 21; feed_mode: 94 or 95
//   at                              "file:line:col" of the block (left out when unknown)
//   chain                           [{"what":"O9010","at":"main.nct:12:1"}, ...], outermost first,
//                                   left out when empty
// Numbers have at most 6 decimals and never an exponent.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <unordered_map>
#include <vector>

#include "motion/event.h"

namespace gcx::motion {

/// File name for a FileId, e.g. [&sm](FileId f) { return sm.name(f); }.
using FileNames = std::function<std::string(FileId)>;

struct TraceOptions {
  bool sample = false;     // write arcs as sampled points
  double tolerance = 0.01; // mm, chord tolerance of sample mode
};

class TraceWriter : public Sink {
public:
  /// Without names, files are written by number ("#0:12:1").
  TraceWriter(std::ostream& out, FileNames names = {}, TraceOptions opt = {});
  void event(const Event& e) override;
  void finish() override { out_.flush(); }

  /// The line (without newline) event() writes for e.
  std::string line(const Event& e);

private:
  void appendLoc(std::string& s, const SourceLoc& loc);

  std::ostream& out_;
  FileNames names_;
  TraceOptions opt_;
  std::vector<Vec3> points_; // reused sample buffer
  std::unordered_map<FileId, std::string>
      fileText_; // per FileId: opening quote + escaped name, once seen
};

/// "rapid", "feed", "arc", ... as written in the trace.
const char* kindName(Kind k);

} // namespace gcx::motion
