// How a dialect's control reads its words and settings, as data the machine model asks: which
// word gives a dwell and in what unit, what M codes do and when, how a block skip switch acts,
// and which setup key holds each machine setting. The core names a setting by what it means
// (Setting::ArcRadiusTolerance); the dialect maps it to its own parameter key.
// docs/machine-model.md.
#pragma once
#include <string>
#include <vector>

namespace gcx {

enum class GAction : unsigned char; // dialect/profile.h

/// A machine setting the core reads, named by its meaning. The setup file holds it under the
/// dialect's key (SettingSpec::key).
enum class Setting : unsigned char {
  ArcRadiusTolerance,   // mm: |end radius - start radius| an arc accepts without alarm
  ParallelAxisU,        // 1: U is an axis parallel to X, not an incremental X
  ParallelAxisV,        // 1: V likewise for Y
  ParallelAxisW,        // 1: W likewise for Z
  DiameterX,            // 1: X is programmed as a diameter at reset
  DiameterY,            // 1: Y likewise
  DiameterZ,            // 1: Z likewise
  RolloverOn,           // 1: rotary axes roll over
  RolloverBySign,       // 1: an absolute rotary value's sign gives the direction
  RolloverShortest,     // 1: an absolute rotary move takes the shortest way
  RolloverAmount,       // degrees of one rollover
  DwellSecondsAlways,   // 1: a dwell is in seconds under feed per revolution too
  ArcCentreAbsolute,    // 1: arc centre words are absolute in the work system, not incremental;
                        // 2: absolute under G90, incremental under G91
  PeckReturn,           // mm: high-speed peck retract
  PeckClearance,        // mm: peck drilling clearance
  BoreExtractionPct,    // %: retract override of the feed-out boring cycles
  TapReturn,            // mm: peck rigid tapping retract
  TapClearance,         // mm: peck rigid tapping clearance
  TapExtractionPct,     // %: rigid tapping retract override
  TapReturnPct,         // %: rigid tapping return override
  TapOrients,           // 1: rigid tapping orients the spindle instead of closing its loop
  TapPeckToR,           // 1: peck rigid tapping retracts to R
  TapExtractionEnabled, // 1: the rigid tapping retract override applies
  TapReturnEnabled,     // 1: the return override applies to peck retracts
  SpindleOrientable,    // 1: the spindle can be oriented
  SpindleIndexable,     // 1: the spindle has a position loop
  CloseLoopMCode,       // the M code that closes the spindle position loop
  CompLookAhead,        // blocks radius compensation reads ahead beyond the 2 it always reads
  CompInterference,     // 1: a compensated move against its programmed direction is an alarm
  SetCoordinatesMode,   // set-coordinates words: 0 the tool's position in the new system, 1 the
                        // new origin in machine coordinates, 2 a shift of the origin (adds up)
  CompMergeDistance,    // mm: corner vectors closer than this on both axes are merged
  ModalLevelCycles,     // bit n: level drilling cycle 81+n repeats after each block with an axis
                        // word until it is cancelled
  PowerOnGearRange,     // the spindle gear range M code in force before the program selects one
};

/// Where the setup holds a setting in this dialect.
struct SettingSpec {
  Setting setting;
  const char* key;             // the setup's parameter key ("N" + 4 digits in NCT)
  const char* alias = nullptr; // read when key is not set (a bit by number)
  double fallback = 0;         // when the setup sets neither
  const char* label = "";      // how messages name it
};

/// What an M code does in the motion model.
enum class MAction : unsigned char {
  Stop,
  OptionalStop,
  End,       // end of program
  EndRewind, // end of program and rewind
  SpindleCW,
  SpindleCCW,
  SpindleStop,
  SpindleOrient,
  Coolant, // mist, flood, off: the code itself is the event's value
  ToolChange,
  Subprogram, // a call or return the expansion pass handles; reaching the machine is an error
  GearRange,  // a spindle gear range (WL4 M41-M48): kept in the modal state, no event
};

/// When an M code acts relative to the motion of its block.
enum class MTiming : unsigned char { BeforeMotion, AfterMotion };

struct MCodeSpec {
  int code = 0;
  MAction action = MAction::Stop;
  MTiming timing = MTiming::AfterMotion;
};

/// How block skip `/n` acts with switch n on.
enum class SkipSense : unsigned char {
  SkipWhenOn, // the block is left out while the switch is on
  RunWhenOn,  // the block runs only while the switch is on
};

/// The dwell: which word gives the time and its unit.
struct DwellRule {
  char word = 'P';           // the word that carries the time
  double secondsPerUnit = 1; // 0.1 for tenths of a second
  /// Messages: the word missing, and a letter that is no dwell word in this dialect.
  const char* missingMessage = "";
  char rejectedWord = 0;
  const char* rejectedMessage = "";
  char alternateWord = 0; // another word that may carry the time (WL4's cycles write G4 X)
};

/// The words of the programmable transformations (rotation, scaling).
struct TransformWords {
  char rotationAngle = 'R'; // the rotation's angle in degrees
  char uniformScale = 'P';  // one factor for all axes (0: none)
  /// Per-axis factors for X Y Z; when they are the axis words themselves, scaling has no
  /// centre words and scales about the work system's origin.
  std::string axisScale = "IJK";
  const char* rotationWithoutAngle = ""; // warnings: the angle or the factors are missing
  const char* scaleWithoutFactor = "";
};

/// A machine parameter of which gcx models only some values: a setup giving another value is
/// a located setup error (GCX023) with `why`, never a silent other meaning.
struct ModelledValues {
  const char* key;            // the setup's parameter key
  std::vector<double> values; // the values gcx models
  const char* why;            // what the others mean and why they are refused
};

/// How the programmable transformations may be combined and ended.
struct TransformRules {
  /// Mirroring is switched on or off only while no rotation or scaling is active.
  bool mirrorOnlyWithoutRotationOrScaling = false;
  /// Rotation and scaling are switched off in the reverse order of switching on.
  bool switchOffsMustNest = false;
  const char* spec = ""; // where the dialect states them, for messages
};

/// The meaning of L in an arc block.
enum class ArcLMeaning : unsigned char {
  Turns, // the number of started turns (a spiral or a multi-turn arc)
  None,  // not an arc word
};

/// Cutter radius compensation (docs/compensation.md): what interrupts its look-ahead. The
/// vector is removed at the end of the block before, the block runs uncompensated, and the
/// next plane motion rebuilds the vector.
struct CompensationRules {
  std::vector<GAction> breakers;      // G codes (by action) whose block breaks the look-ahead
  std::vector<MAction> breakerMCodes; // M codes likewise
  bool lengthWordBreaks = false;      // a tool length word (H) likewise
  /// The dialect's corner rules (docs/compensation.md, "Per dialect"); the defaults are NCT's.
  bool outerCornerArcs = false; // outer corners on an arc of the radius about the corner point
  double arcGapLimit = 0;       // mm: a smaller gap between the offsets meets at their intersection
  bool startUpPerpendicular = false; // start-up ends on the next element's start perpendicular
  bool cancelPerpendicular = false;  // the last element ends on its end perpendicular
  int lookAheadBlocks = 0; // blocks read for the next plane element; 0: the CompLookAhead setting
  /// Warn at a block without motion in the plane while compensation is on: a control that reads
  /// only the next block cannot process the corner across it (WL4, wl4.md §4.2).
  bool warnWithoutPlaneMotion = false;
};

/// The words of the automatic contour geometry (nct.md §4): a chamfer or a rounding between a
/// block and the next, and the direction angle of a line. Empty: the dialect has none.
struct ContourWords {
  std::string chamfer, rounding, angle;
  /// A rotary axis letter (A-C) that is the chamfer word instead when the setup's parameter
  /// chamferAxisKey is 1 (WL4 B with `B.role = chamfer`, wl4.md §0.2, §3.16); 0: none.
  char chamferAxis = 0;
  std::string chamferAxisKey;
};

/// The blocks of a contour cycle's profile (FMS-3000 G164/G165 up to `endcont`): what they may
/// hold. Empty: the dialect has no such cycle.
struct ProfileBlockWords {
  std::vector<GAction> codes;         // the G codes allowed, by action
  std::vector<GAction> approachCodes; // allowed in the first (approach) block besides
  std::string letters;                // the other addresses allowed
  const char* list = "";              // how messages list what is allowed
};

/// What the machine model follows for a dialect, beside its code tables.
struct MachineRules {
  std::vector<SettingSpec> settings;
  std::vector<ModelledValues> modelledValues;
  /// A data-entry parameter record's setup key: this prefix and the record's number written
  /// with at least this many digits (NCT: "N" and four digits, docs/machine-model.md).
  std::string parameterKeyPrefix;
  int parameterKeyDigits = 1;
  /// Numbered parameters have bits: key + "." + 0-7 or a bit's name (NCT, docs/setup.md).
  bool parameterBits = false;
  std::vector<MCodeSpec> mcodes;
  MTiming speedTiming = MTiming::AfterMotion; // S (and G96's surface speed)
  MTiming toolTiming = MTiming::AfterMotion;  // T selects the next tool
  /// Lathe tool data (WL4, wl4.md §4.1): T makes the tool's working-point offsets (the setup's
  /// `turning` of tool T) move the program zero, T0 clears them; the compensation radius is
  /// the tool's nose radius (`nose_radius`) plus the value of register D, which may be
  /// negative, but not below 0 in sum (an error, not a change of side).
  bool toolSelectsOffsets = false;
  SkipSense skipSense = SkipSense::SkipWhenOn;
  DwellRule dwell;
  TransformWords transform;
  TransformRules transformRules;
  /// A motion code ends the canned-cycle mode as the cycle-cancel code does.
  bool motionCancelsCycle = false;
  ArcLMeaning arcL = ArcLMeaning::Turns;
  /// A dwell written with a motion runs after the motion of its block (FMS-3000 §3.9), instead
  /// of the block being a dwell only.
  bool dwellAfterMotion = false;
  /// An arc by R is an error when R is 0, R is shorter than half the chord or the in-plane end
  /// point is missing (FMS-3000 §3.5), instead of NCT's tolerant readings.
  bool strictArcRadius = false;
  /// An arc whose end radius differs from its start radius within the tolerance is a circle
  /// about the programmed centre (WL4 §3.4), not NCT's spiral between the two radii.
  bool arcWithinToleranceIsCircle = false;
  /// I J K only on arcs: in a G0/G1 block they are an error (FMS-3000 §3.4).
  bool centreWordsOnlyOnArcs = false;
  /// Reference returns go straight to their point, the axis values only naming the axes
  /// (FMS-3000 G28/G30/G31, §3.8). The point of G-code arg n > 0 is read from the setup
  /// parameters under this fmt pattern ({0}: axis 0-2, {1}: n); arg 0 is machine zero.
  const char* directReferencePointKey = nullptr;
  /// One-sided positioning: the sign is the direction of the final approach, the magnitude the
  /// overshoot an axis moving the other way (or not at all) goes beyond its target first.
  double oneSidedOvershoot = 0;
  /// The tool length offset acts along the normal of the selected plane (else along Z).
  bool lengthAlongPlaneNormal = false;
  /// Constant surface speed: the axis whose distance from zero is the radius (0 X, 1 Y, 2 Z).
  int surfaceSpeedAxis = 0;
  /// Constant surface speed selected without S holds the surface speed the spindle has at that
  /// moment (its rpm at the tool's radius), not the last one programmed.
  bool surfaceSpeedHoldsCurrent = false;
  /// Switching between rpm and constant surface speed needs a new S in the same block (an
  /// error without one; WL4, wl4.md §2.4).
  bool surfaceSpeedSwitchNeedsS = false;
  /// A sequence of spindle-synchronised lines (GAction::ThreadMotion) ends with an exact stop
  /// on its last move (a warning without one) and a G0-G3 (an error otherwise; WL4, §3.6).
  bool threadSequenceEnds = false;
  /// S in a set-coordinates block is the constant surface speed's spindle limit.
  bool setCoordinatesSIsSpindleLimit = false;
  /// The address whose value is the constant surface speed's spindle limit in rpm, modal
  /// (FMS-3000 LIMS); null: none.
  const char* spindleLimitAddress = nullptr;
  /// The error that the main program's file ran out without a program end, null when it may
  /// (nct.md Q31).
  const char* endOfFileError = nullptr;
  /// Selecting a work offset (or the machine system) ends the set-coordinates shift (WL4:
  /// G92 is cancelled by G53-G59); otherwise the shift holds in every work system.
  bool workOffsetEndsSetCoordinates = false;
  /// The setup's names of the work offsets: the standard ones 1..n in order, and the prefix of
  /// the numbered extended ones (prefix + number).
  std::vector<std::string> workOffsetNames;
  std::string extendedWorkOffsetPrefix;
  int extendedWorkOffsets = 0; // numbered 1..this
  CompensationRules compensation;
  ContourWords contour;
  /// Reference points a reference return by number may name: P1..this.
  int referencePoints = 0;
  ProfileBlockWords profileBlock;
  /// The warning of a probing move: gcx has no probe model and assumes no touch.
  const char* probeWithoutTouch = "";

  const SettingSpec* setting(Setting s) const;
  const MCodeSpec* mcode(int code) const;
};

} // namespace gcx
