// Where each NCT system variable lives (nct-macro.md §2.9): variable numbers, their long forms
// and the #_NAME[i] symbols all decode to one reference, so every form shares the same rules.
#pragma once
#include <compare>
#include <optional>
#include <string>

namespace gcx::nct::sysvar {

enum class Kind : unsigned char {
  Vacant,              // #0, #3100, #_EMPTY (§2.9.1)
  Pi,                  // #3101
  E,                   // #3102
  PlcInput,            // #1000-#1035: index 0-31 bits, 32 the bit word, 33-35 values
  PlcOutput,           // #1100-#1135, indices as PlcInput
  Message,             // #3000 #3006 #3106: write-only messages (§2.9.2); index = number
  MessageBox,          // #3107
  Clock,               // #3001, #3002: index 1, 2 (§2.9.3)
  Date,                // #3011
  Time,                // #3012
  Control,             // #3003, #3004: index 1, 2
  ControlBit,          // #_M_SBK (index 1, sub 0), #_M_FHD #_M_OV #_M_EST (index 2, sub 0-2)
  RunState,            // #_CNTBS (sub -1) and its bits #_BSEARCH #_TEST #_MCHLOCK (sub 0-2)
  Mirror,              // #3007
  Parts,               // #3901, #3902: index 1, 2
  MainProgram,         // #4000
  ModalGroup,          // #4001-#4039 (§2.9.4): index = group, sub = Slot
  ModalWord,           // #4101-#4130: index = number - 4100, sub = Slot
  Position,            // §2.9.5: index = axis, sub = Pos
  WorkOffset,          // §2.9.7: index = axis, sub = 0 common, 1-6 G54-G59, 100 + p G54.1 Pp
  BasicRotation,       // index = plane 1 XY, 2 ZX, 3 YZ; sub as WorkOffset (no common)
  DynamicOffset,       // G54.2 Pp table: index = axis, sub = p 1-8
  DynamicOffsetActive, // #5500 (index 0: active P) and #5501-#5520 (index = axis)
  ToolOffset,          // §2.9.6: index = register 1-999, sub = Tool
  ToolData,            // #8400-#8534 tool and pallet data (§2.9.8); index = number
};

/// Modal items of the block read last, executing, or interrupted (#40xx, #42xx, #44xx).
enum Slot : int { Buffered = 0, Active = 1, Interrupted = 2 };
/// Axis-indexed position rows of §2.9.5, in short-form order.
enum Pos : int {
  EndPoint = 0,     // #5001 #_ABSIO
  Machine = 1,      // #5021 #_ABSMT
  Current = 2,      // #5041 #_ABSOT
  Probe = 3,        // #5061 #_ABSKP
  LengthOffset = 4, // #5081 #_TOFS
  ServoLag = 5,     // #5101 #_SVERR
  Handwheel = 6,    // #100651 #_MIRTP
  DistanceToGo = 7, // #5181 #_DIST
};
/// Tool offset rows of §2.9.6 that exist with N1416 TOL=0.
enum Tool : int {
  LengthGeometry = 0, // #10001
  LengthWear = 1,     // #11001
  RadiusGeometry = 2, // #12001
  RadiusWear = 3,     // #13001
  CornerGeometry = 4, // #21001
  CornerWear = 5,     // #22001
};

struct Ref {
  Kind kind = Kind::Vacant;
  int index = 0;
  int sub = 0;
  auto operator<=>(const Ref&) const = default;
};

/// Highest G54.1 P number (the interpreter's limit; P49 and up have long forms only).
inline constexpr int kMaxExtendedOffset = 99;

/// The variable #n, or nullopt if §2.9 does not list n (#34-#99 included).
std::optional<Ref> decode(int number);
/// The variable #_NAME or #_NAME[index] (name without "#_", any case), or nullopt.
std::optional<Ref> decodeNamed(const std::string& name, std::optional<int> index);
/// The number a symbol stands for (#_ABSIO[3] -> 100003, #_ALM -> 3000); nullopt for
/// symbols without a number (#_M_SBK, #_CNTBS) and for unknown ones.
std::optional<int> numberOf(const std::string& name, std::optional<int> index);

} // namespace gcx::nct::sysvar
