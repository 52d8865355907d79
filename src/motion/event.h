// Motion events: what a program does to the machine, in the machine frame, with provenance.
// Everything downstream of the interpreter (canonical emitter, trace writer, SVG plotter,
// statistics, equivalence checker) is a Sink of one stream of these (cf. CAMotics' machine
// pipeline, DESIGN.md).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "ir/source.h"

namespace gcx::motion {

using Vec3 = Eigen::Vector3d;
/// Axes beyond X Y Z, in this order: rotary A B C (degrees) and U V W when the machine has them
/// as axes parallel to X Y Z (mm). They move linearly with the path, like a helix's height.
using Extra = Eigen::Matrix<double, 6, 1>;
inline constexpr char kExtraAxisNames[] = {'A', 'B', 'C', 'U', 'V', 'W'};

/// Where an event came from: the source block and the chain of calls that led to it
/// ("in O9010 called from main.nct:12, loop iteration 3").
struct Frame {
  SourceLoc call;   // the calling block (or the loop head)
  std::string what; // "O9010", "G65 P9010", "WHILE iteration 3", "G81 hole 2"
};
struct Provenance {
  SourceLoc at;             // the block that produced the event
  std::vector<Frame> chain; // outermost first
};

enum class Plane { XY, ZX, YZ }; // G17, G18, G19

enum class Kind {
  Rapid,          // straight traverse start -> end
  Feed,           // straight feed start -> end
  Arc,            // arc/helix/spiral start -> end about center in plane
  Dwell,          // seconds (or revolutions when perRevolution)
  Spindle,        // speed and direction (+1 CW M3, -1 CCW M4, 0 stop M5)
  SpindleOrient,  // M19
  ToolChange,     // tool number
  Coolant,        // on/off (M7 mist, M8 flood, M9 off)
  Stop,           // M0 / M1 (optional)
  End,            // M2 / M30
  Message,        // operator message (#3006, DPRNT to screen, ...)
  PlaneChange,    // G17/G18/G19: plane; text names its axes when parallel axes form it ("UV")
  UnitsChange,    // G20/G21 of the program (value 20 or 21); event values stay in mm
  FeedModeChange, // G94/G95 (value 94 or 95)
  OverrideLock,   // value 1: feed and speed overrides fixed at 100 %, feed hold off (NCT G63,
                  // a tapping cycle's NOOVR-ON); value 0: released again
  RadiusComp,     // cutter radius compensation kept for the target (expand --keep comp): value
                  // +1 left (G41), -1 right (G42), 0 off (G40); startRadius the tool radius
};

struct Event {
  Kind kind = Kind::Feed;
  Provenance from;

  // geometry, machine frame, mm (the gauge point: tool tip + length offset + work offset)
  Vec3 start = Vec3::Zero();
  Vec3 end = Vec3::Zero();
  Extra extraStart = Extra::Zero(); // A B C U V W at start and end (see Extra)
  Extra extraEnd = Extra::Zero();
  Vec3 center = Vec3::Zero(); // Arc: centre at the start point's height along the normal
  Plane plane = Plane::XY;    // Arc, PlaneChange
  bool clockwise = false;     // Arc: seen from the positive normal axis
  int turns = 0;              // Arc: extra full turns beyond the first sweep (NCT L-1)
  double startRadius = 0;     // Arc: |start - center| in the plane (after transformations)
  double endRadius = 0;       // Arc: |end - center|; differs from startRadius for spirals

  // feed and other values
  double feed = 0; // mm/min, or mm/rev when perRevolution
  /// Feed: > 0 when spindle-synchronised (G33 thread, rigid tap): mm per revolution; such a
  /// feed is `lead` per revolution (feed = lead, perRevolution set).
  double lead = 0;
  bool perRevolution = false; // G95 feed, or G4 in revolutions
  double value = 0;      // Dwell time, Spindle speed (emitted whenever S or the direction changes),
                         // ToolChange tool, Coolant code, UnitsChange / FeedModeChange code
  int direction = 0;     // Spindle: +1 CW, -1 CCW, 0 stop
  bool optional = false; // Stop: M1
  std::string text;      // Message; PlaneChange axis names
};

/// A consumer of motion events.
class Sink {
public:
  virtual ~Sink() = default;
  virtual void event(const Event& e) = 0;
  virtual void finish() {}
};

} // namespace gcx::motion
