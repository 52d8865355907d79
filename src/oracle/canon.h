// Reading rs274's canonical-call output into gcx motion events (machine frame, mm).
//
// Line format (LinuxCNC 2.9 saicanon): `%5d` counter, the block's N word (`N.....` when the
// block has none; `N123456` may touch the call name), `NAME(args)`; numbers are `%.4f` in the
// program's current length units. Lines of other shapes (`(print,...)` output) are ignored.
//
// What was verified about the frames (rs274 2.9.0~pre1 on Debian 12, see
// tests/oracle/canon_test.cpp and rs274_test.cpp, which repeat the measurements):
//  * Points in STRAIGHT_TRAVERSE / STRAIGHT_FEED / ARC_FEED are PROGRAM coordinates: work offset
//    (SET_G5X_OFFSET), G92/G52 offset (SET_G92_OFFSET), G10 L2 R rotation (SET_XY_ROTATION) and
//    tool length (USE_TOOL_LENGTH_OFFSET) are NOT applied to them; they are reported as separate
//    calls. Evidence: with G55 = (200,0,0) R30, `G0 X10 Y0` prints STRAIGHT_TRAVERSE(10, 0, 5);
//    after `G43 H1` (tool 101.6 mm) `G0 Z5` prints Z 5.0000.
//  * LinuxCNC's real canon layer (emccanon.cc, rotate_and_offset_pos) maps a program point p to
//    the machine position of the controlled (gauge) point as
//        m = Rot_z(R) * (p + g92) + g5x + tool        (tool = (tx, ty, tz) of the TLO)
//    and we do exactly that. rs274 never prints machine positions, but its interpreter's own
//    bookkeeping follows the same map, which shows whenever it re-expresses the physical
//    position in a new frame: with G54 = (2540, 1270, -254), TLO 101.6, at program (1, 2, 5),
//    a switch to G55 = (5080, 0, 0) R30 makes `G1 X10` print Y 2371.0843 Z -249.0000, which is
//    exactly Rot(-30)*(m - g5x - tool) - g92 for m = (2541, 1272, -147.4). The test
//    "Rs274Run.FramesMatchInterpreterBookkeeping" repeats this with a G92 offset as well.
//  * Units: every number is in the length units current when the call is printed
//    (USE_LENGTH_UNITS). After G20, points, offsets printed later (SET_G5X_OFFSET on a G55
//    switch, USE_TOOL_LENGTH_OFFSET on G43) and SET_FEED_RATE are inches; offsets printed
//    earlier keep their mm value (rs274 does not re-print them on G20, and emccanon converts
//    each call's arguments with the units current at that call). So we convert each call's
//    numbers with the units current at that call and keep all state in mm.
//  * SET_G5X_OFFSET always describes the ACTIVE system: `G10 L2 P2 ...` while G54 is active
//    prints nothing, the later `G55` prints SET_G5X_OFFSET(2, ...). G52 prints SET_G92_OFFSET.
//  * ARC_FEED(e1, e2, c1, c2, rot, e3, a, b, c): plane coordinates XY -> (X,Y,Z),
//    YZ -> (Y,Z,X), XZ -> (Z,X,Y); centre absolute (program frame); rot = +n CCW / -n CW seen
//    from the positive normal (for XZ the (Z,X) order makes the normal +Y, so G2 in G18 prints
//    -1), n-1 extra full turns; end == start is a full circle.
//  * Rotary axes: STRAIGHT_TRAVERSE / STRAIGHT_FEED(x, y, z, a, b, c) and ARC_FEED's last three
//    arguments are A B C in program coordinates, degrees under G20 too (measured: after G20,
//    `G1 X1 B30` prints STRAIGHT_FEED(1.0000, 0.0000, 0.0000, 180.0000, 30.0000, 5.0000)); the
//    machine angle adds the G92 and work offsets' a b c (`G92 A0` at A10 then `G1 A20` prints
//    A 20.0000 and SET_G92_OFFSET(..., 10.0000, ...)) and the tool offset's, unrotated. The
//    standalone rs274 is an XYZABC machine: it prints no U V W and rejects those words.
//  * CHANGE_TOOL(n) prints the tool-table INDEX, not the tool number (T7 in pocket 3 as the
//    first table entry prints CHANGE_TOOL(1)); the tool number is the preceding SELECT_TOOL(7).
//  * M9 prints MIST_OFF() and FLOOD_OFF(): both become one Coolant(9) event.
//  * Rounding: `%.4f` in program units, so mm coordinates carry up to 5e-5 mm of rounding and
//    inch coordinates up to 5e-5 in = 1.27e-3 mm (the comparison tolerance must allow for that
//    in G20 programs, or the programs must use values exact at 4 inch decimals).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "ir/source.h"
#include "motion/event.h"

namespace gcx::oracle {

struct CanonOptions {
  FileId file = 0; // put into every event's provenance (Event::from.at.file)
  /// Machine position before the first move (rs274's standalone machine starts at 0,0,0).
  motion::Vec3 initialPosition = motion::Vec3::Zero();
  /// Optional: the program text rs274 ran (before N numbering). When given, events get col 1
  /// and the byte offset of their line, so SourceManager::lineText() can show the line. Must
  /// outlive the reader's construction only (line starts are copied).
  std::string_view programText;
};

/// One canonical call split into its parts.
struct CanonCall {
  std::uint32_t line = 0;        // the N number (0 for `N.....`)
  std::string name;              // STRAIGHT_FEED
  std::vector<std::string> args; // comma/space separated arguments, trimmed
};

/// Splits one output line; false for lines that are not canonical calls.
bool splitCanonLine(std::string_view line, CanonCall& out);

/// Streaming converter: feed it lines, collect events.
///
/// Mapping: STRAIGHT_TRAVERSE -> Rapid, STRAIGHT_FEED -> Feed, ARC_FEED -> Arc (start = the
/// previous end; their a b c arguments give extraEnd's A B C), DWELL -> Dwell (seconds),
/// SET_SPINDLE_SPEED / START_SPINDLE_CLOCKWISE / START_SPINDLE_COUNTERCLOCKWISE /
/// STOP_SPINDLE_TURNING -> Spindle (only when speed or direction changes; calls from one source
/// line are merged into one event), CHANGE_TOOL -> ToolChange (tool number from the last
/// SELECT_TOOL), FLOOD_ON/MIST_ON/FLOOD_OFF/MIST_OFF -> Coolant 8/7/9 (consecutive offs merged),
/// PROGRAM_STOP / OPTIONAL_PROGRAM_STOP -> Stop, PROGRAM_END -> End, MESSAGE -> Message.
/// SET_FEED_RATE / SET_FEED_MODE (per revolution) and START_SPEED_FEED_SYNC (pitch per rev) set the
/// feed of later Feed/Arc events. RIGID_TAP, STRAIGHT_PROBE and inverse-time (G93) feeds are not
/// modelled: they are reported in unsupported().
class CanonReader {
public:
  explicit CanonReader(CanonOptions options = {});

  /// Processes one output line (ignored if it is not a canonical call).
  void line(std::string_view text);
  void lines(const std::vector<std::string>& all) {
    for (const std::string& l : all)
      line(l);
  }

  const std::vector<motion::Event>& events() const { return events_; }
  std::vector<motion::Event> take() { return std::move(events_); }
  /// "line N: CALL(...): why" for calls that could not be converted faithfully.
  const std::vector<std::string>& unsupported() const { return unsupported_; }

  /// Current machine position (mm) of the gauge point.
  const motion::Vec3& position() const { return pos_; }
  /// Program point (in the units current now) -> machine frame, mm.
  motion::Vec3 toMachine(const motion::Vec3& programPoint) const;
  /// Machine frame (mm) -> program point in mm (inverse of toMachine without the unit factor).
  motion::Vec3 toProgramMm(const motion::Vec3& machine) const;

private:
  void call(const CanonCall& c, std::string_view text);
  bool numbers(const CanonCall& c, std::size_t n, std::vector<double>& v, std::string_view text);
  motion::Event make(motion::Kind k, std::uint32_t line) const;
  void push(motion::Event e);
  /// Sets e's A B C end (and the reader's) from program angles v[first..first+2], if present.
  void rotaryTarget(const std::vector<double>& v, std::size_t first, motion::Event& e);
  void spindle(std::uint32_t line);
  void note(std::uint32_t line, std::string_view text, std::string_view why);

  CanonOptions options_;
  std::vector<motion::Event> events_;
  std::vector<std::string> unsupported_;
  std::vector<std::uint64_t> lineStarts_; // byte offset of each line of programText

  motion::Vec3 pos_;                         // machine frame, mm
  double unit_ = 1.0;                        // mm per program unit (25.4 after CANON_UNITS_INCHES)
  motion::Vec3 g5x_ = motion::Vec3::Zero();  // mm
  motion::Vec3 g92_ = motion::Vec3::Zero();  // mm
  motion::Vec3 tool_ = motion::Vec3::Zero(); // mm
  // Rotary axes, degrees: the machine's A B C (U V W stay 0) and the offsets' a b c.
  motion::Extra extra_ = motion::Extra::Zero();
  motion::Vec3 g5xRotary_ = motion::Vec3::Zero();
  motion::Vec3 g92Rotary_ = motion::Vec3::Zero();
  motion::Vec3 toolRotary_ = motion::Vec3::Zero();
  double rotationDeg_ = 0;
  motion::Plane plane_ = motion::Plane::XY;
  double feed_ = 0; // mm/min or mm/rev
  bool perRev_ = false;
  bool inverseTime_ = false; // G93 (told apart only by the interpreter's comment)
  bool synced_ = false;      // between START_SPEED_FEED_SYNC and STOP_SPEED_FEED_SYNCH
  double syncPitch_ = 0;     // mm/rev
  double spindleSpeed_ = 0;
  int spindleDir_ = 0;
  double emittedSpeed_ = 0; // state of the last Spindle event
  int emittedDir_ = 0;
  int selectedTool_ = -1;
};

/// Whole-output conveniences.
std::vector<motion::Event> parseCanon(const std::vector<std::string>& lines,
                                      const CanonOptions& options = {});
std::vector<motion::Event> parseCanonText(std::string_view text, const CanonOptions& options = {});

} // namespace gcx::oracle
