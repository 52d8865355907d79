// How a dialect's programs call, return and keep variables: the hooks and tables the one
// control-flow engine (passes/macro) reads. The engine owns frames, jumps, loops, calls, modal
// calls and repeat counts; a dialect says which codes do what (its remap table), how its
// variables are laid out, how a call binds its arguments, which variable writes are messages,
// and how a program name becomes a file. docs/control-flow.md describes the whole.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/word_value_rules.h"

namespace gcx {

namespace ir {
struct Block;
struct Word;
} // namespace ir
namespace diag {
class Engine;
}
namespace machine {
class Interpreter;
}
namespace macro {
class SystemVariableStore;
}

/// What a remapped code does (LinuxCNC's remap is the model: a code becomes a built-in, a
/// program or a cycle). In a block with CallSubprogram, Return or EndProgram the block's other
/// words run first (nct.md §1.4 K5); a macro call's other words are its arguments.
enum class FlowAction : unsigned char {
  Builtin,             // the machine executes the code itself (FMS GG<n>: the built-in G<n>)
  CallSubprogram,      // run a program after the block (NCT M98, FMS P019, WL4 L0703)
  CallMacro,           // run a program whose arguments are the block's words (NCT G65)
  CallCycle,           // CallMacro of a system cycle: the profile's cycleMacro checks it first
  Return,              // back to the caller, or repeat by the callee's count (NCT M99)
  ModalCall,           // register a call made after every block that moves an axis (G66)
  ModalCallEveryBlock, // register a call made after every NC block, and call now (G66.1)
  ModalCancel,         // remove the most recent modal call (G67)
  EndProgram,          // the program ends here (FMS M98)
  RepeatStart,         // the blocks after this one up to RepeatEnd run repeatWord times (FMS G25 L)
  RepeatEnd,           // the last block of a repeated fragment (FMS M25)
  /// Run a program once, the block's axis words its target: the other words run first, the
  /// system variables take the target, and the program moves (WL4 G70 calls %1, wl4.md §5.1).
  CallOpenCycle,
};

/// Where the called program's name comes from.
enum class ProgramSource : unsigned char {
  None,       // no program (Return, ModalCancel, EndProgram, Builtin)
  Word,       // the digits of another word of the block (NCT `M98 P12`: "12")
  CodeDigits, // the digits of the remapped word itself (FMS `P019`: "019"; WL4 `L0703`: "07";
              // WL4 G81: "81"; with namePrefix "G", FMS G1: "G1")
  Fixed,      // always fixedProgram
};

/// How the callee's local variables start.
enum class LocalFrame : unsigned char {
  Shared,    // the caller's frame (NCT M98)
  Arguments, // a new frame from the bound arguments (NCT G65)
  Copy,      // a new frame, a copy of the caller's (WL4 `L nnpp`, wl4.md §5.1)
};

/// One row of a dialect's remap table: a code and what it does.
struct Remap {
  std::string address;        // "G", "M", "P", "L", "GG"
  std::optional<double> code; // the word's value; nullopt: any value of the address
  std::optional<double> last; // with code: a range code..last (WL4 G81-G89)
  FlowAction action = FlowAction::Builtin;
  ProgramSource program = ProgramSource::None;
  char programWord = 0;     // ProgramSource::Word: its letter (also M99 P: where to return)
  std::string fixedProgram; // ProgramSource::Fixed
  std::string namePrefix;   // CodeDigits: put before the digits (FMS G-subprogram "G1")
  std::string builtin;      // Builtin: the address the machine executes (FMS GG -> G)
  std::optional<double> onlyProgram; // the row applies only when the program word has this value
  /// CodeDigits: how many leading digits name the program; the rest count repeats
  /// (WL4 `L nnpp`: 2). 0: all digits name the program.
  int nameDigits = 0;
  char repeatWord = 0; // the word giving the repeat count (NCT L)
  LocalFrame frame = LocalFrame::Shared;
  bool onlyIfProgramExists = false; // a user program overrides a built-in (FMS G<n>)
  /// A G code whose later words in the block are its parameters: the row does not apply to them
  /// (FMS `G150 ... P10`: P is the cycle's cone length, no call). Null: always applies.
  bool (*parameterCode)(double g) = nullptr;
  bool programWordIsNumber = false; // round and range-check the program word as a call number
  bool fileWord = false; // a `<file>` word may name the program instead (NCT M98 <a.nct>)
  /// A repeat count below 1: an error citing this rule, or (empty) no call at all.
  std::string repeatBelowOneRule;
  int modalGroup = 0; // Modal*: the machine's modal group reporting it (0: none), this code ×10
  int modalCode10 = 0;
  /// ModalCall: the registering block's other words run, and a move among them makes the
  /// first call (WL4 `G81 X10`, wl4.md §5.1); otherwise the block only registers (NCT G66).
  bool registerRunsBlock = false;
  /// ModalCall: the registration replaces the one in force instead of nesting on it (WL4's
  /// group 7 holds one cycle: G81 then G83 drills by %83 only, and G80 cancels it).
  bool replacesModalCall = false;
  /// CallOpenCycle: letters besides the axes that belong to the cycle, not to the block's NC
  /// part (WL4 G31: I the lead increment, P the phase).
  std::string cycleWords;
  /// The row does not apply to a block that has this word (0: always applies): WL4 G77 with P
  /// is the internal contour cycle the machine runs, without P the open cycle of %1 (§5.1).
  char unlessWord = 0;
  const char* spec = ""; // where the dialect specifies the row, for messages
};

/// A remap table, searched in order: the first matching row wins for a word.
struct RemapTable {
  std::vector<Remap> rows;
  /// The row for a word `address value`, the program word's value given when the block has
  /// one; null when the code is not remapped.
  const Remap* find(std::string_view address, double value,
                    std::optional<double> programValue = std::nullopt) const;
  /// True if some row's address starts with the letter of `address`: a cheap test before
  /// find for every word of every block.
  bool mayMatch(std::string_view address) const {
    return !address.empty() && address[0] >= 'A' && address[0] <= 'Z' &&
           (letters() >> (address[0] - 'A') & 1u);
  }

private:
  std::uint32_t letters() const;
  mutable std::uint32_t letters_ = 0;
  mutable std::size_t lettersOf_ = static_cast<std::size_t>(-1); // rows counted into letters_
};

/// A remapped code's program, resolved from a word's digits: the unit name and repeat count.
struct ProgramCall {
  std::string unit;          // "12", "019", "07"
  std::optional<long> times; // repeats taken from the digits (WL4 `L0703`: 3)
};
/// The program and repeats `digits` (the word's digits as written, no sign) give under row r.
ProgramCall programFromDigits(const Remap& r, std::string_view digits);
/// The digits a word names a program with: its text as written when that is all digits (FMS
/// P019 keeps its zero, WL4 L0703 its four digits), else its value as a whole number.
std::string programDigits(const ir::Word& w);

/// Variable numbers: the local frame, the commons (globals), and everything above is the
/// dialect's system variables.
struct VariableSpace {
  int localFirst = 1;
  int localLast = 33; // NCT #1-#33; WL4 #1-#29
  int commonFirst = 100;
  int commonLast = 999;
  /// false: a variable never written reads 0, there is no vacant state (WL4, wl4.md §6.1).
  bool vacant = true;
  /// Slots of a local frame (indices 0..frameSize-1; NCT 34 for #1-#33).
  int frameSize() const { return localLast + 1; }
};

/// A write to a variable that is a message or alarm (NCT #3000 alarm, #3006 stop with message).
struct MessageRule {
  enum Kind : unsigned char { Alarm, Stop, Note } kind = Note;
  int alarmBase = 0; // Alarm: the diagnostic code is alarmBase + the written number
  int maxNumber = 0; // the written number must be 0..maxNumber
};

/// One argument of a call: a local variable from a word, or a fixed control value.
struct ArgumentBinding {
  int variable = 0;
  const ir::Word* word = nullptr; // the value comes from this word
  std::optional<double> literal;  // or is this number (NCT #10 = the call's G code)
  bool vacant = false;            // or is vacant
};
struct CallArguments {
  std::vector<ArgumentBinding> bindings;
  const ir::Word* offending = nullptr; // set after an error
  const char* code = nullptr;
  std::string message;
  bool ok() const { return offending == nullptr; }
};
/// How a call binds: a G65-type call (the program word and the repeat word are control words),
/// a call by a configured code (every other word is an argument), or a call made by a modal
/// every-block registration (the block's G, P, L become control values).
enum class CallKind : unsigned char { Explicit, ConfiguredG, ConfiguredM, EveryBlock };
struct CallSite {
  const ir::Block* block = nullptr; // the words to bind (the call word removed)
  CallKind kind = CallKind::Explicit;
  double callCode = 0; // the call's code value
  const ir::Word* programWord = nullptr;
  /// Is this word's value a vacant bare reference (then it binds nothing)?
  std::function<bool(const ir::Word&)> vacant;
};

/// A code the machine's parameters turn into a call (nct-macro.md §5.8).
struct ConfiguredCall {
  enum Kind : unsigned char { MacroG, ModalG, MacroM, SubprogramM, SubprogramLetter } kind;
  std::string unit; // the program called
  const ir::Word* word = nullptr;
  int valueVariable = 0; // the common variable receiving the word's value (0: none)
};
using ParameterLookup = std::function<double(const std::string& key, double fallback)>;

struct ControlFlow {
  RemapTable remaps;
  VariableSpace variables;
  bool hasVariables = true; // false: the language has no variables (FMS-3000)
  /// Rounding and range of a value an expression gives to an address (`X#1`, `G#29`).
  WordValueRules wordValues;
  /// The channel's axes by number, 1 first: AX[n] and the axis-number functions (NCT "XYZABC").
  std::string channelAxes;
  /// Words that mark a file as needing the expansion pass (calls, loops, jumps, prints).
  std::vector<std::string> expansionMarkers;
  /// A file is a sequence of program units `%name ... %` (WL4, wl4.md §1.2): the library
  /// loads units and finds a called one by name in the caller's file first. Otherwise a file
  /// is one program.
  bool namedUnits = false;
  /// The local frame a Call statement (WL4 `L0703`) gives the program it calls.
  LocalFrame callFrame = LocalFrame::Shared;
  /// `#n=e` may stand inside an expression and assigns there (WL4, wl4.md §6.4).
  bool assignsInExpressions = false;
  /// A block whose axis words are no move (WL4 `G4 X2`, `G92 X0`): no modal call after it;
  /// null: every block with an axis word moves.
  std::function<bool(const ir::Block& flat)> axisWordsNoMove;
  /// A return in the main program is this error (WL4 M99, wl4.md §6.7); null: it restarts
  /// the main program or goes to its block P (NCT).
  const char* returnInMainError = nullptr;
  /// A return in the main program ends it like the end of its file (FMS-3000 M99: "run
  /// standalone, it acts like M02 without machine signals", fms3000.md §2.2, 001:336-340).
  bool returnInMainEnds = false;
  /// Calls may nest this deep (WL4: 5, wl4.md §6.7); 0: as deep as the run's --max-depth.
  int maxCallDepth = 0;
  /// Whether a block number is a label a Jump statement may reach (WL4: written with a leading
  /// 0, `N010`, wl4.md §1.8); null: every block number is.
  std::function<bool(std::string_view sequenceText)> isLabel;

  /// The rule of a message variable #n, nullopt for an ordinary variable.
  std::function<std::optional<MessageRule>(int number)> messageVariable;
  /// Binds a call's arguments to local variables (NCT specifications I and II).
  std::function<CallArguments(const CallSite&)> bindArguments;
  /// The system variables of a run (NCT #1000 and up, #_NAME).
  std::function<std::unique_ptr<macro::SystemVariableStore>(machine::Interpreter&, diag::Engine&)>
      systemVariables;
  /// A code the machine's parameters configure as a call; nullopt when none (or after
  /// reporting an error: the caller compares the error count).
  std::function<std::optional<ConfiguredCall>(const ir::Block& flat, const ParameterLookup&,
                                              diag::Engine&)>
      configuredCall;
  /// A common variable protected against writes: the message to report, nullopt if writable.
  std::function<std::optional<std::string>(int number, const ParameterLookup&)> writeProtected;
  /// The setup parameter key of PRM[id, bit], in the dialect's spelling.
  std::function<std::string(int id, std::optional<int> bit)> parameterKey;
  /// DPRNT leaves out the '+' sign and leading zeros (a machine parameter of the dialect).
  std::function<bool(const ParameterLookup&)> printOmitsSign;

  /// The file names, in search order, that may hold program `unit` called from a file with
  /// extension `ext` (NCT "12" -> O0012.nct, O00000012.nct; FMS "019" -> 019.fms).
  std::function<std::vector<std::string>(const std::string& unit, const std::string& ext)>
      programFiles;
  /// How messages name program `unit` (NCT "12" -> "O0012").
  std::function<std::string(const std::string& unit)> programLabel;
  /// The text of a program the dialect ships (WL4's canned cycles %81-%89), a file of units;
  /// found after the user's files, so a user program of the same name overrides it.
  std::function<std::optional<std::string_view>(const std::string& unit)> systemProgram;
};

} // namespace gcx
