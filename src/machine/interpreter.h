// The semantic engine: modal state, positions, offsets and transformations of one channel,
// executing flat blocks (all word values literal) and emitting machine-frame motion events.
// The macro pass (later) drives the same engine block by block, so system variables read the
// true state; there is no second copy of any rule.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cycles/level_cycle.h"
#include "diag/diagnostic.h"
#include "dialect/profile.h"
#include "ir/block.h"
#include "machine/block_words.h"
#include "machine/compensation.h"
#include "machine/contour_corners.h"
#include "machine/setup.h"
#include "machine/transforms.h"
#include "motion/event.h"

namespace gcx::cycles {
struct CycleOp;
struct ContourSegment;
struct Profile;
struct TurningWords;
enum class TurningCycle : unsigned char;
} // namespace gcx::cycles

namespace gcx::machine {

struct CycleState; // cycle_state.h

/// Owns the cycle state; a copy of the interpreter (the contour probe) copies it.
class CycleStateBox {
public:
  CycleStateBox();
  ~CycleStateBox();
  CycleStateBox(const CycleStateBox& other);
  CycleStateBox& operator=(const CycleStateBox& other);
  CycleState& operator*() const { return *state_; }
  CycleState* operator->() const { return state_.get(); }

private:
  std::unique_ptr<CycleState> state_;
};

/// The modal state a block inherits (nct.md §2.1 groups that affect motion).
struct ModalState {
  GAction motion = GAction::Rapid;
  motion::Plane plane = motion::Plane::XY;
  bool inch = false;
  bool incremental = false;
  bool perRevolution = false;
  bool polar = false;
  int workOffset = 1;          // 1..6 = G54..G59; 100 + p = G54.1 Pp
  int lengthSign = 0;          // +1 G43, -1 G44, 0 G49
  int lengthRegister = 0;      // H
  bool turningOffsets = false; // G43.7: the H register's turning offsets are on
  GAction radiusComp = GAction::RadiusCompOff;
  GAction cycle = GAction::CycleCancel;
  bool returnToR = false; // G99 (group 10); G98 at power-on, reset and cycle cancel
  GAction feedControl = GAction::ContinuousMode;
  double feed = 0; // mm/min or mm/rev
  double spindleSpeed = 0;
  int spindleDirection = 0;  // +1 M3, -1 M4, 0 M5
  int selectedTool = 0;      // T
  int tool = 0;              // in the spindle after M6
  int coolant = 9;           // the last coolant code (M7, M8, M9)
  int gearRange = 0;         // the last gear range M code (WL4 M41-M48), 0 before one
  std::string planeAxes;     // the plane's axes when parallel axes form it ("UV"), else empty
  bool surfaceSpeed = false; // G96: S is a surface speed (m/min or ft/min)
  double surfaceSpeedValue = 0;
  double maxSpindleSpeed = 0; // G92 S clamp for G96 (0: none)
  unsigned diameterAxes = 0;  // bit a: axis a (X=0) programmed as a diameter (G10.9, setup)
  // the last value of words that only macro variables report (#4107-#4120, nct-macro.md §2.9.4)
  int lastD = 0, lastH = 0, lastM = 0, lastO = 0; // lastO: O word or setCalledProgram
  std::int64_t lastN = 0;                         // first N of the block
  double lastE = 0, lastS = 0;                    // as programmed (S: rpm, or m/min in G96)
};

/// Rotary-axis rollover (nct.md §3.10; the dialect's rollover settings).
struct Rollover {
  bool enabled = false;
  bool absoluteBySign = false; // ABS=1: the sign of the value gives the direction
  bool shortest = false;       // ASH=1: the shortest way
  double amount = 360;
};

/// A block of a turning contour (cycles.md §4.7) as the driver holding the program hands it
/// over: flat (all values literal) unless it is a macro statement, with its provenance.
struct ContourBlock {
  ir::Block block;
  motion::Provenance from;
};
/// Fills `out` with the blocks ns..nf of the current program; false when one is not found.
using ContourSource =
    std::function<bool(std::int64_t ns, std::int64_t nf, std::vector<ContourBlock>& out)>;

class Interpreter {
public:
  Interpreter(const Profile& profile, const Setup& setup, motion::Sink& sink, diag::Engine& diags);

  /// Executes one block. False when execution must stop: an alarm (reported) or program end.
  bool execute(const ir::Block& block, const motion::Provenance& from);
  /// The input ended; a program may end without M2/M30 (nct.md Q31).
  void finish();
  /// The main program's file ran out: finish(), or the dialect's error when a program must end
  /// with an end code (MachineRules::endOfFileError). False after an error.
  /// `lastBlock`: where the error points when no NC block ran (a file of only G25 L2).
  bool endOfFile(SourceRange lastBlock = {});
  /// For `--to nct` without cycle expansion: canned-cycle blocks pass through unexecuted; the
  /// programmed position follows the hole positions in the plane (not the drilling axis).
  void setDeferCycles(bool on) { deferCycles_ = on; }
  /// For a target that compensates itself (expand --keep comp): G40/G41/G42 become RadiusComp
  /// events with the side and radius, and the path stays the programmed one.
  void setKeepCompensation(bool on) { keepCompensation_ = on; }
  /// The most moves a run may make (--max-moves): each rapid, feed and arc, and each turn of a
  /// multi-turn arc, counts one; past it execution stops with a located error.
  void setMaxMoves(std::uint64_t n) { maxMoves_ = n; }
  /// Asked after every move: a reason to stop (an output limit was crossed), or nothing.
  void setStopCheck(std::function<std::optional<std::string>()> check) {
    stopCheck_ = std::move(check);
  }
  /// Told each block's provenance before the block runs: a consumer learns which run of which
  /// block each event belongs to (a structured translation, docs/translation.md).
  void setBlockObserver(std::function<void(const motion::Provenance&)> observer) {
    blockObserver_ = std::move(observer);
  }
  /// Where G70.7-G73.7 find their contour blocks; without one they are an error.
  void setContourSource(ContourSource source) { contours_ = std::move(source); }
  /// After G71.7-G73.7: the N of the last contour block. When the contour follows the cycle
  /// block, the driver resumes after it; the contour is not run again (cycles.md §4.7).
  std::optional<std::int64_t> takeResumeAfter() { return std::exchange(resumeAfter_, {}); }
  /// An operator message (#3006, #3106, DPRNT...); with stop, a program stop follows it.
  void message(const std::string& text, const motion::Provenance& from, bool stop);

  bool ended() const { return ended_; }
  /// A block with skip level n is left out (the dialect's skip sense and the setup's switches).
  bool skips(int level) const;
  const ModalState& state() const { return state_; }
  /// Last programmed point, untransformed, in the current work system (mm).
  const Vec3& programPosition() const { return program_; }
  /// Gauge point in the machine frame (mm).
  const Vec3& machinePosition() const { return machine_; }
  const motion::Extra& extraPosition() const { return extra_; }

  // --- what macro system variables read and write (nct-macro.md §2.9) ---------------------
  /// The G code (times ten) last in force in modal group g (0 if none), e.g. 170 for G17.
  int modalCode(int group) const;
  /// Records a modal G code handled outside the engine (G66/G66.1/G67 by the macro pass).
  void setModalCode(int group, int code10) {
    if (group > 0 && group < static_cast<int>(modalCodes_.size())) modalCodes_[group] = code10;
  }
  /// Records the code as the one in force in its group (null: nothing).
  void setModalCode(const GCodeSpec* g) {
    if (g) setModalCode(g->group, g->code10);
  }
  const Setup& setup() const { return setup_; }
  /// The last probing move's end (WL4 G38 without a probe model: its end point).
  struct ProbeResult {
    Vec3 machine = Vec3::Zero();  // machine coordinates
    Vec3 work = Vec3::Zero();     // the active work system, tool offsets included
    Vec3 distance = Vec3::Zero(); // from the block's start
  };
  const ProbeResult& probeResult() const { return probe_; }
  const Profile& profile() const { return profile_; }
  /// Active length offset (signed, mm) and the G92 / G52 shifts.
  double lengthOffset() const { return offsets_.length; }
  const Vec3& g92Shift() const { return offsets_.g92; }
  const Vec3& localOrigin() const { return offsets_.g52; }
  /// Writes a work offset ("G54", "G54.1 P3", "common"); the tool does not move.
  void setWorkOffset(const std::string& key, const Vec3& value);
  /// Writes a tool length register (takes effect when H is programmed again, nct.md §2.3).
  void setToolLength(int reg, double length);
  /// Basic rotation of a work system (G10 L2 I J K, #120001...): plane 1 = XY (I), 2 = ZX (J),
  /// 3 = YZ (K), degrees. Stored and readable; moving in a rotated system is not implemented.
  double workRotation(const std::string& key, int plane) const;
  void setWorkRotation(const std::string& key, int plane, double degrees);
  void setToolRadius(int reg, double radius);
  /// Wear part of a length (radius false) or radius register as G10 L11 or #11000+n / #13000+n
  /// set it; the register itself holds geometry + wear (nct-macro.md §2.9.6).
  double toolWear(int reg, bool radius) const;
  /// Sets the wear and keeps the geometry: the register changes by the difference.
  void setToolWear(int reg, bool radius, double wear);
  /// Machine position of program zero: all offsets and the active length, no transforms.
  Vec3 workOrigin() const;
  const Transforms& transforms() const { return transforms_; }
  /// The program called last (#4115) for calls the interpreter does not see (M98, G65).
  void setCalledProgram(int number) { state_.lastO = number; }
  /// A machine parameter as the setup or a G10 L52 record set it.
  double parameter(const std::string& key, double fallback) const {
    return setup_.parameter(key, fallback);
  }
  bool hasParameters() const { return !setup_.parameters.empty(); }

private:
  struct Offsets {
    Vec3 common = Vec3::Zero();
    Vec3 g92 = Vec3::Zero();
    Vec3 g52 = Vec3::Zero();
    double length = 0;           // along Z, or the plane's normal (MachineRules)
    Vec3 turning = Vec3::Zero(); // G43.7 (nct.md §3.16)
  };

  bool fail(const char* code, const SourceRange& where, std::string message);
  bool executeBlock(const ir::Block& block);
  /// A motion event's numbers are finite and writable, and the move limit holds; else the run
  /// stops with a located error.
  bool admitMotion(const motion::Event& e);
  double mm(double v) const { return state_.inch ? v * 25.4 : v; }
  Vec3 toMachine(const Vec3& program) const; // full pipeline
  void reexpress();                          // program position from the machine position
  Vec3 currentWorkOffset() const;
  /// The setup's key of work offset n (1..n: the standard ones; 100 + p: extended p).
  std::string workOffsetKey(int offset) const;
  /// The active tool length offset as a vector (MachineRules::lengthAlongPlaneNormal).
  Vec3 lengthVector() const;
  void resetModal();

  /// Applies a G code that only changes modal state; false if it needs more than that.
  bool setModal(const GCodeSpec& g);
  bool applyModal(const BlockWords& w);
  bool applyNonMotion(const BlockWords& w, bool& consumedAxes);
  bool move(const BlockWords& w);
  bool arc(const BlockWords& w, const Vec3& target, const motion::Extra& extraEnd,
           bool haveInPlaneEnd);
  /// WL4 G51 (mirror_by_sign.cpp): X-1 mirrors X about 0, X1 ends it; S limits the spindle.
  bool mirrorBySign(const BlockWords& w);
  /// A quarter-circle fillet to `end` (fillet.cpp): the centre is the corner of the quadrant
  /// the two points bound that gives the programmed direction (wl4.md §3.5).
  bool fillet(const Vec3& end, const motion::Extra& extraEnd);
  /// After a WL4 G38 block's move: the results, and the same path back (probe_move.cpp).
  bool probeBack(const ir::Word& code, const Vec3& from);
  /// Before a skip move's motion (FMS-3000 G32): refused under radius compensation, and without
  /// a probe model the move runs to its end (probe_move.cpp).
  bool skipWithoutTouch(const ir::Word& code);
  /// Before a one-block thread's move (FMS-3000 G33): its G1 becomes a thread move at the
  /// lead F; under G0 an error, with G2/G3 not implemented (thread_motion.cpp).
  bool threadOnce(const ir::Word& code);
  /// A WL4 G32/G33 thread move to `to` (thread_motion.cpp, wl4.md §3.6).
  bool threadMove(const BlockWords& w, const Vec3& to, const motion::Extra& extraTo);
  /// After the block's modal codes: a thread-line sequence that ends here ends with an exact
  /// stop and G0-G3 (MachineRules::threadSequenceEnds); `ending`: the program ends.
  bool threadSequenceEnd(const BlockWords& w, bool ending);
  /// G96 <-> G97 without S in the block (MachineRules::surfaceSpeedSwitchNeedsS).
  bool surfaceSpeedSwitch(const BlockWords& w, const ModalState& before);
  /// The arc from the current position about `centre` (program coordinates) to `end`.
  bool arcTo(const Vec3& end, const Vec3& centre, bool cw, int turns, const motion::Extra& extraEnd,
             double feed);
  /// An axis word in mm, halved on a diameter axis.
  double coordinate(int axis, const ir::Word& w) const;
  /// The block's M codes timed before its motion.
  bool beforeMotion(const BlockWords& w);
  /// S, T and the M codes timed after the block's motion.
  bool afterMotion(const BlockWords& w);
  /// S, T and the M codes of one phase, as the dialect times them.
  bool auxiliary(const BlockWords& w, MTiming phase);
  /// Executes the block's M codes of one timing from the dialect's M table.
  bool mcodes(const BlockWords& w, MTiming timing);
  /// Target of the axis words in program coordinates (G90/G91, I operator, U/V/W, polar).
  Vec3 target(const BlockWords& w, bool allowPolar) const;
  bool axisGiven(const BlockWords& w, int axis) const { return w.axis[axis] || w.uvw[axis]; }
  bool setCoordinates(const BlockWords& w);
  /// The other meanings of the set-coordinates words (Setting::SetCoordinatesMode 1, 2):
  /// the new origin in machine coordinates, or a shift of the current origin that adds up
  /// (machine/coordinate_origin.cpp).
  bool setCoordinateOrigin(const BlockWords& w, bool additive);
  bool localCoordinates(const BlockWords& w);
  bool dataInput(const BlockWords& w, const ir::Block& b);
  bool oneSidedRapid(const BlockWords& w, const Vec3& to, const motion::Extra& extraTo);
  bool implicitCoordinate(const BlockWords& w, Vec3 to, const motion::Extra& extraTo);
  /// A block with a level drilling cycle: its words before the code first, then the hole.
  bool levelCycleBlock(const ir::Block& block, const ir::Word& code, const GCodeSpec& spec);
  /// Under a modal level cycle (Setting::ModalLevelCycles), a block with an axis word runs,
  /// then the cycle's hole from where it ends; nullopt when the block does not repeat a cycle.
  std::optional<bool> levelCycleRepeat(const ir::Block& block);
  /// The hole of the level cycle levelCycle_ with levelWords_, from the current position.
  bool levelHole(const SourceRange& code);
  /// The level turning cycle levelCycle_ with levelWords_ (machine/level_turning.cpp).
  bool levelTurning(const SourceRange& code, const cycles::Profile* profile = nullptr);
  /// While G164/G165 waits for `endcont`: keeps a profile block, or runs the cycle at `endcont`
  /// (machine/level_profile.cpp).
  bool profileBlock(const ir::Block& block, const motion::Provenance& from);
  bool profileCycle();
  /// A block that sets the pole (GAction::PolePolar) or moves by I radius and A angle about it:
  /// run here, with the polar words turned into plane axis words; nullopt for any other block.
  std::optional<bool> polePolarBlock(const ir::Block& block);
  bool runRewritten(const ir::Block& rest); // the polar block as plane axis words
  bool directReferenceReturn(const BlockWords& w, int point);
  bool referenceReturn(const BlockWords& w, int point);
  bool machineMove(const BlockWords& w);
  bool transforms(const BlockWords& w);
  /// A straight move; `lead` > 0 makes a feed spindle-synchronised (G33, rigid tapping).
  void emitLine(motion::Kind kind, const Vec3& to, const motion::Extra& extraTo, double feed,
                double lead = 0);
  void emitLine(motion::Kind kind, const Vec3& to, const motion::Extra& extraTo) {
    emitLine(kind, to, extraTo, state_.feed);
  }
  void emitLine(motion::Kind kind, const Vec3& to) { emitLine(kind, to, extra_); }
  void emitDwell(double p);
  void emitSpindle();

  // --- turning cycles (turning_cycles.cpp, cycles.md §4) ------------------------------------
  /// A block with a one-shot turning cycle G70.7-G76.7 (pendingTurning_).
  bool turningBlock(const BlockWords& w);
  /// G70.7: the contour blocks run as ordinary blocks, then a rapid back (§4.11).
  bool finishingCycle(const BlockWords& w);
  /// The blocks ns..nf named by the block's P and Q, checked against §4.7; false if reported.
  bool contourBlocks(const BlockWords& w, std::vector<ContourBlock>& out);
  /// The contour's moves as a scratch copy of this interpreter makes them, in program
  /// coordinates; G40-G42 are left out (roughing ignores them, Q-14). The copy starts where
  /// this one stands, or at `start` (program coordinates).
  bool traceContour(const std::vector<ContourBlock>& blocks,
                    std::vector<cycles::ContourSegment>& out, const Vec3* start = nullptr);
  /// A turning-cycle block: stores a first block's values or runs the cycle (G71.7-G79.7).
  bool turningCycle(cycles::TurningCycle cycle, const BlockWords& w);
  /// The block's words for the turning library: raw values in mm, diameters not halved.
  cycles::TurningWords turningWords(cycles::TurningCycle cycle, const BlockWords& w) const;
  // --- contour cycles (contour_cycles.cpp, wl4.md §5.6) --------------------------------------
  /// The block's G41/G42 belong to the cycle (pendingContour_): they give contourSide_ and
  /// leave compensation off; it must be off before the block. False if reported.
  bool contourCycleSide(const BlockWords& w, const ModalState& before);
  /// A block with a contour cycle: trace the contour P..Q from the block's start point, apply
  /// the allowances, run the passes; F acts only inside the cycle.
  bool contourCycleBlock(const BlockWords& w, const ModalState& before);
  Vec3 toProgram(const Vec3& machine) const {
    return transforms_.applyInverse(machine - workOrigin());
  }

  // --- drilling cycles (drill_cycles.cpp, cycles.md §2-§3) -------------------------------
  /// A block executed in cycle mode: stores its cycle words, drills its holes and runs its
  /// M S T functions after op 1 of the first hole (000:10360-10362).
  bool drillBlock(const BlockWords& w, bool consumedAxes);
  /// Cycle mode ends (G80, a group-1 code, reset): the variables go, G98 returns (000:9456).
  void cancelCycleMode();
  /// Executes cycle ops; the block's M S T run before ops[auxAt] (never if auxAt is npos).
  /// `drillSlot` 3-5 when a parallel axis U V W drills: its value travels in the normal slot.
  /// With passName, each op step is a frame of the provenance chain ("G71.7 pass 3").
  bool runCycleOps(const std::vector<cycles::CycleOp>& ops, std::size_t auxAt, const BlockWords& w,
                   int drillSlot, const char* passName = nullptr);
  /// End positions of A B C (rollover rules) and of U V W axes for the words of a block.
  motion::Extra extraTarget(const BlockWords& w) const;
  double rotaryDelta(double current, double value) const;
  void selectPlaneAxes(const BlockWords& w);

  // --- cutter radius compensation (radius_compensation.cpp, docs/compensation.md) ----------
  CompensationStage::Options compensationOptions() const;
  /// The offset of the tool-centre path: register D's radius (negative swaps the side), or
  /// with the lathe tool data the selected tool's nose radius plus D, never below 0. Nullopt
  /// after reporting (no register D, a negative sum).
  std::optional<double> compensationRadius(const BlockWords& w);
  /// The block's G40/G41/G42, D, plane and look-ahead breakers, handed to the stage.
  bool radiusCompensation(const BlockWords& w, const ModalState& before);
  /// G39 I J K: the corner arc towards the perpendicular of the vector, now.
  bool cornerArcTowards(const BlockWords& w, const ir::Word& g39);
  /// Reports a stage's failure as a located error; always false.
  bool compensationFailed(const CompensationFailure& f);
  /// ,A completes `to`; ,C and ,R are requested from the corner stage (contour_geometry.cpp).
  bool contourGeometry(const BlockWords& w, Vec3& to);
  /// An over-determined line or circle (nct.md §4.3, contour_intersections.cpp): ends the
  /// element before at the intersection, starts there (`over`), `to` its absolute end.
  bool intersection(const BlockWords& w, Vec3& to, bool& over);
  void rememberPlaneMove(const motion::Event& e);
  void emitModalChanges(const ModalState& before);
  // An Event is some 300 bytes: taken by rvalue reference, not built a second time per move.
  void emit(motion::Event&& e);

  const Profile& profile_;
  Setup setup_;
  motion::Sink* sink_;
  diag::Engine& diags_;
  ModalState state_;
  Offsets offsets_;
  Transforms transforms_;
  Vec3 program_ = Vec3::Zero();
  std::optional<double> threadLead_; // the lead of the running G32/G33 sequence
  struct ThreadEnd {                 // the last move of an open thread-line sequence
    SourceRange block;
    bool exactStop = false;
  };
  std::optional<ThreadEnd> threadEnd_;   // (MachineRules::threadSequenceEnds)
  bool probing_ = false;                 // a G38 block's move: its events are kept
  std::vector<motion::Event> probePath_; // to run back along
  ProbeResult probe_;
  Vec3 machine_ = Vec3::Zero();
  motion::Extra extra_ = motion::Extra::Zero(); // A B C (continuous, degrees), U V W (mm)
  unsigned parallelAxes_ = 0; // bit i: U/V/W is an axis parallel to X/Y/Z (a setting)
  Rollover rollover_;
  std::array<int, 64> modalCodes_{}; // per modal group: the G code (x10) last in force
  // settings read for every arc, read again when a data record (G10 L52) sets a parameter
  double radiusTolerance_;
  double arcCentreMode_; // Setting::ArcCentreAbsolute
  void cacheSettings();
  motion::Provenance from_;
  SourceRange blockRange_;
  std::map<std::string, std::array<double, 3>> rotations_; // basic rotations per work system
  std::map<int, double> wear_;                             // G10 L11 length wear per register
  std::map<int, double> radiusWear_;                       // #13000+n radius wear per register
  CycleStateBox cycles_;       // the cycles library's modal memory (cycle_state.h)
  ContourCornerStage corners_; // chamfers and roundings, before compensation
  CompensationStage comp_;     // between the programmed path and the sink
  ContourSource contours_;
  std::optional<std::int64_t> resumeAfter_;
  const GCodeSpec* pendingTurning_ = nullptr; // a one-shot turning cycle in the current block
  const GCodeSpec* pendingContour_ = nullptr; // a contour cycle in the current block
  int contourSide_ = 0; // its G41 (+1) / G42 (-1): allowance side and compensation in the cycle
  std::optional<cycles::LevelCycle> levelCycle_; // the level cycle whose words are kept
  std::string levelCode_;                        // its code as written, for messages: "G81"
  std::map<char, double> levelWords_;            // its parameters, remembered until G80 or another
  bool repeatingLevelCycle_ = false;             // inside the block that repeats a modal cycle
  bool levelRapidFlag_ = false;                  // `G0` among a turning cycle's parameters
  struct PendingProfile {                        // G164/G165 before its `endcont`
    SourceRange code;
    motion::Provenance from;
    std::vector<ContourBlock> blocks;
  };
  std::optional<PendingProfile> pendingProfile_;
  std::optional<std::array<double, 2>> pole_; // the polar pole on the plane's two axes (G36)
  bool polarRewritten_ = false;               // running a polar block's plane axis words
  std::optional<double> pendingDwell_; // seconds, run after the block's motion (dwellAfterMotion)
  const GCodeSpec* turningMode_ = nullptr; // the modal G77.7-G79.7 while group 1 holds it
  std::optional<Vec3> turningEnd_;         // its last end point: omitted X/Z repeat it (§4.1)
  std::optional<double> turningTaper_;     // and its R
  int lockedFrom_ = 0;                     // the group-15 code a tapping cycle's G63 replaced
  bool deferCycles_ = false;
  bool keepCompensation_ = false;
  struct DirectionLine { // a line by ,A alone, waiting for the line that ends it (§4.3)
    double degrees;
    motion::Provenance from;
    GAction motion;
    double feed;
  };
  std::optional<DirectionLine> directionLine_;
  struct PlaneMove { // the last move in the plane (machine frame), for intersections (§4.3)
    comp::Path2 path;
    std::uint64_t block = 0;
  };
  std::optional<PlaneMove> lastPlaneMove_;
  std::uint64_t blockSerial_ = 0;
  std::optional<Vec3> overCentre_; // an over-determined circle's centre (program frame)
  int keptSide_ = 0;               // the side and radius of the last RadiusComp event
  double keptRadius_ = 0;
  bool ended_ = false;
  bool speedProgrammed_ = false; // an S word was given (before it, the speed is unknown)
  bool stopped_ = false;         // a limit or a value out of range stopped the run inside a block
  std::uint64_t moves_ = 0, maxMoves_ = UINT64_MAX; // moves beyond the first of each block
  std::uint64_t blockMoves_ = 0;                    // moves of the block being executed
  std::function<std::optional<std::string>()> stopCheck_;
  std::function<void(const motion::Provenance&)> blockObserver_;
  bool dataMode_ = false;
};

} // namespace gcx::machine
