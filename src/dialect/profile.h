// What differs between dialects, as data: the address table, the G-code table with its modal
// groups, M-code rules. The core reads a Profile; it never asks which dialect it is running.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/machine_rules.h"
#include "motion/event.h"

namespace gcx {

namespace ir {
struct Block;
struct Word;
} // namespace ir
namespace diag {
class Engine;
}
struct ControlFlow;

struct AddressSpec {
  std::string address;      // "X", ",C", "AX"
  bool decimal = true;      // a fraction may be written
  bool sign = true;         // a minus sign may be written
  bool incremental = false; // the I operator may follow the address
  double min = -1e300;      // inclusive limits of a literal value (after the sign)
  double max = 1e300;
  bool repeatable = false; // may stand more than once in a block (G, M)
  const char* meaning = "";
};

/// What a G code does, independent of its number in a dialect. The interpreter executes
/// actions; each dialect's table maps its codes onto them.
enum class GAction : unsigned char {
  Unsupported, // known to the dialect, not executable by gcx yet (reported, never ignored)
  Rapid,
  Linear,
  ArcCW,
  ArcCCW,
  FilletCW,  // a 90° arc to the end point, its centre a corner of the quadrant (WL4 G12)
  FilletCCW, // (WL4 G13)
  Dwell,
  ExactStopOnce,
  DataInput,
  DataInputEnd,
  PlaneXY,
  PlaneZX,
  PlaneYZ,
  Inch,
  Metric,
  Absolute,
  Incremental,
  FeedPerMinute,
  FeedPerRevolution,
  ReferenceReturn,
  OtherReferenceReturn,
  MachineCoordinates,
  LocalCoordinates,
  SetCoordinates,
  WorkOffset,         // arg = 1..6 (G54..G59)
  ExtendedWorkOffset, // G54.1 P
  LengthPlus,
  LengthMinus,
  LengthCancel,
  TurningOffsets, // G43.7 H: the tool's X Y Z turning offsets on all three axes
  RadiusCompOff,
  RadiusCompLeft,
  RadiusCompRight,
  ScaleOff,
  ScaleOn,
  MirrorOff,
  MirrorOn,
  MirrorBySign, // per axis word: -1 mirrors the axis about 0, 1 ends it; S: spindle limit (WL4 G51)
  RotateOn,
  RotateOff,
  PolarOff,
  PolarOn,
  ExactStopMode,
  CornerOverride,
  TappingMode,
  ContinuousMode,
  CycleCancel,
  DrillCycle,
  TurningCycle,
  ReturnInitial,
  ReturnR,
  MacroCall,
  ModalMacroCall,
  ModalMacroCallEveryBlock,
  ModalMacroCancel,
  SurfaceSpeedOn,
  SurfaceSpeedOff,
  StrokeLimitOn,
  StrokeLimitOff,
  DiameterMode,        // G10.9: axis words 1 = diameter, 0 = radius programming
  Modeless,            // state the motion model does not depend on (polar interpolation off...)
  HelicalQualifier,    // with G02/G03: a helix by pitch (FMS-3000 G10, the normal axis's I/J/K)
  OneSidedPositioning, // a rapid whose final approach always comes from one side (FMS G60)
  ImplicitPlus,        // the other plane axis moves by +|the programmed one's travel| (FMS G47)
  ImplicitMinus,       // ... by -|travel| (FMS G48); on an arc, a quarter circle of that radius
  LevelDrillCycle,     // a cycle whose parameters follow its code (FMS G81-G88 by U/Z/I levels,
                       // cycles/level_drilling.h; G150-G167, cycles/level_turning.h); arg = the
                       // cycle number
  PolePolar,           // polar coordinates about a pole the plane's axis words set: I the radius,
                       // A the angle from the first plane axis (FMS G36, machine/pole_polar.cpp)
  CornerArc,           // radius compensation: an arc of the tool radius at the next outer corner
  VectorHold,          // radius compensation: the block ends with the vector it starts with
  ThreadMotion,        // spindle-synchronised line, F the lead of the longest axis (WL4 G32)
  ThreadReciprocating, // the same out, spindle reversed, back to the start (WL4 G33)
  ProbeReturn,         // the block's move runs out and back to its start (WL4 G38)
  SkipMove,            // the block's move ends early on a touch signal (FMS-3000 G32)
  ThreadOnce,          // the block's G1 move is spindle-synchronised, F the lead (FMS-3000 G33)
  ContourCycle,        // passes along a contour given by P Q block numbers, its start the
                       // block's axis words (WL4 G76, G77 P, G78 P); arg = cycles::ContourCycle
};

struct GCodeSpec {
  int code10 = 0; // G code times ten: G84.2 -> 842
  int group = 0;  // modal group, 0 = one-shot
  const char* meaning = "";
  GAction action = GAction::Unsupported;
  int arg = 0;
};

/// A G65 call of a system cycle written as a macro program (NCT G65 P9999 pocket milling,
/// cycles.md §5), as its argument check sees it.
struct CycleMacroCall {
  const ir::Block* block = nullptr;   // the call block as written: word locations
  const ir::Word* callWord = nullptr; // the call code's word
  /// The local frame as bound (index = variable number, the dialect's frame size); nullopt =
  /// vacant.
  std::vector<std::optional<double>> args;
  motion::Plane plane = motion::Plane::XY;
  std::string planeCode; // how messages name the plane's code ("G17")
  bool inch = false;     // lengths in inches
  /// Radius in tool register n (mm, geometry + wear), 0 when the register is not set.
  std::function<double(int)> toolRadius;
};

/// A cycle the control implements as a macro program: the expander checks the call's
/// arguments before the call and replaces "program not found" by `missingCode`.
struct CycleMacro {
  std::int64_t program = 0; // G65 P<program>
  const char* name = "";    // "pocket-milling cycle"
  const char* missingCode = "";
  const char* spec = ""; // where the cycle is specified, for messages
  /// Reports a located error and returns false when the arguments are wrong.
  std::function<bool(const CycleMacroCall&, diag::Engine&)> check;
};

/// Canned-cycle behaviour the dialect's manual leaves open, chosen per dialect (cycles.md §9).
struct CycleChoices {
  /// G71/G72 roughing ends with a semi-finishing pass along the shifted contour (Fanuc, with
  /// its parameter RF1 = 0; Q-15).
  bool roughingFinalPass = true;
  /// G73 pattern repeat: relief step Δi/d (the textbook, 003:8930-8931) instead of Fanuc's
  /// Δi/(d-1).
  bool patternStepByPassCount = false;
  /// Contour cycles (GAction::ContourCycle): the most blocks a level cycle's contour may have
  /// (0: no limit), and the letters of contour blocks that are ignored, not run.
  int maxContourBlocks = 0;
  std::string contourIgnoredWords;
};

/// What one data-input block (NCT G10 L<n>) sets.
enum class DataEntry : unsigned char {
  WorkOffset,         // P0 the common shift, P1..n the standard work offsets
  ExtendedWorkOffset, // P1..MachineRules::extendedWorkOffsets
  ToolLength,         // register P = R (its geometry; the wear is kept)
  ToolLengthWear,     // the wear of register P = R
};
struct DataEntryCode {
  int l;
  DataEntry entry;
};

/// A parameter record of a data-entry section (NCT G10 L52: N<id> [P<i>] [Q<bit>] R<value>,
/// nct-macro.md §9.1): the block's sequence number is the parameter's number.
struct DataRecordFormat {
  std::int64_t maxNumber = 0; // parameters are numbered 0..this
  char valueWord = 0;         // the new value (0: the dialect has no records)
  char bitWord = 0;           // selects one bit 0..maxBit of the parameter
  int maxBit = 0;
  std::string words;     // the letters allowed beside the value word
  const char* name = ""; // how messages name a record
};

struct Profile {
  std::string name;
  const ControlFlow* controlFlow = nullptr; // calls, variables, remaps (control_flow.h)
  CycleChoices cycleChoices;
  std::vector<AddressSpec> addresses;
  std::vector<GCodeSpec> gcodes;
  int maxMCodesPerBlock = 8;
  std::vector<int> exclusiveMCodes; // at most one of these per block (spindle M3 M4 M5 M19)
  int maxSignificantDigits = 15;
  std::int64_t minSequenceNumber = 1; // the range of N
  std::int64_t maxSequenceNumber = 99999999;
  /// Several G codes of one modal group in a block: the last one wins (FMS-3000), not an error.
  bool lastOfModalGroupWins = false;
  int maxSkipLevel = 9;
  int documentedSkipLevel = 8;            // levels above it are accepted with a warning
  std::vector<int> dataModeLCodes;        // G10 L<n> starts a data-entry section ended by G11
  std::vector<DataEntryCode> dataEntries; // what G10 L<n> sets in one block
  DataRecordFormat dataRecord;            // the records of a data-entry section
  std::vector<int> macroCallGCodes10;     // G65, G66, G66.1: every other letter is an argument
  std::vector<int> powerOnGCodes10;       // modal state at power-on and after reset
  bool uvwIncremental = false;            // U V W are incremental X Y Z when not axes
  MachineRules machine;                   // word roles, M codes, settings (machine_rules.h)
  /// Static check of a macro call block's arguments (the dialect's argument specification).
  std::function<void(const ir::Block&, diag::Engine&)> checkCallArguments;
  /// System cycles written as macro programs, by program number (NCT: 9999, cycles.md §5).
  std::vector<CycleMacro> cycleMacros;
  const CycleMacro* cycleMacro(std::int64_t program) const;

  /// Inline for a single letter: the static checks ask it for every word.
  const AddressSpec* address(std::string_view a) const {
    if (a.size() == 1 && a[0] >= 'A' && a[0] <= 'Z') return letterAddress(a[0]);
    return addressNamed(a);
  }
  /// The address of one letter A-Z, or null.
  const AddressSpec* letterAddress(char letter) const {
    const int slot = letters_[static_cast<std::size_t>(letter - 'A')];
    return slot ? &addresses[static_cast<std::size_t>(slot - 1)] : nullptr;
  }
  /// Builds the lookup tables; call once after filling the vectors.
  void index();
  /// True if a G code of the table has the action (before index(): true, not knowing), so that
  /// a rule for an action the dialect lacks is not looked for in every block.
  bool defines(GAction a) const {
    const auto bit = static_cast<unsigned>(a);
    return !indexed_ || ((actions_[bit / 64] >> (bit % 64)) & 1u);
  }
  /// Inline for the whole codes G0-G255 of the table, the codes of nearly every block.
  const GCodeSpec* gcode(double value) const {
    if (indexed_ && value >= 0 && value < 256 && value == static_cast<int>(value)) {
      const int slot = wholeGCodes_[static_cast<std::size_t>(value)];
      return slot ? &gcodes[static_cast<std::size_t>(slot - 1)] : nullptr;
    }
    return gcodeByTenths(value);
  }

  /// True if G<value> is one of macroCallGCodes10: a block with it is a macro call. Inline for
  /// the whole codes G0-G255, the codes of nearly every block.
  bool macroCallGCode(double value) const {
    if (indexed_ && value >= 0 && value < 256 && value == static_cast<int>(value)) {
      const auto code = static_cast<unsigned>(value);
      return (wholeMacroCalls_[code / 64] >> (code % 64)) & 1u;
    }
    return macroCallByTenths(value);
  }

private:
  const AddressSpec* addressNamed(std::string_view a) const;
  const GCodeSpec* gcodeByTenths(double value) const;
  bool macroCallByTenths(double value) const;

  std::array<int, 26> letters_{}; // index+1 into addresses of single letters (0: none)
  // index+1 into gcodes of the whole codes G0-G255 (0: none), the codes of nearly every block
  std::array<int, 256> wholeGCodes_{};
  std::array<std::uint64_t, 4> actions_{};         // the actions of the table's codes, as bits
  std::array<std::uint64_t, 4> wholeMacroCalls_{}; // macroCallGCodes10 among G0-G255, as bits
  bool indexed_ = false;
};

/// G code value as an integer number of tenths, if it has at most one decimal (G84.2 -> 842).
std::optional<int> gcodeTenths(double value);

} // namespace gcx
