// A program's blocks by meaning, between a source dialect and a target (docs/translation.md,
// "Structure across dialects"): what each block selects (G codes by action, M codes by action),
// the words it moves with, and its control flow (assignments, calls, repeats, loops, jumps),
// with no dialect's numbers left. translate/lift.h builds steps from a dialect's blocks;
// translate/structured_writer.h writes them in another.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialect/machine_rules.h"
#include "dialect/profile.h"
#include "ir/expr.h"
#include "ir/source.h"

namespace gcx::xlate {

/// A word's value: a literal, or an expression over variables numbered as the source numbers
/// them (structured_writer renumbers them for the target).
struct Value {
  bool literal = true;
  double number = 0;
  ir::Expr expr; // when !literal
  SourceRange range;
};

/// A G code by meaning.
struct Mode {
  GAction action = GAction::Unsupported;
  int arg = 0;              // WorkOffset: 1..6
  const char* meaning = ""; // as the source's table says it, for messages
  SourceRange range;
};

/// A word of the block's NC part by its role: an axis X Y Z A B C, arc centre I J K, radius R,
/// feed F, speed S, tool T, compensation registers D H. `letter` is that role's letter.
struct Operand {
  char letter = 0;
  Value value;
};

/// An M code by meaning, with when it acts in the source.
struct Machine {
  MAction action = MAction::Stop;
  int code = 0; // the source's number: a coolant code's own value is its meaning (M7 M8 M9)
  MTiming timing = MTiming::AfterMotion;
  SourceRange range;
};

enum class FlowKind : unsigned char {
  Assign,      // target = value
  Call,        // run `unit` `times` times, after the block
  Return,      // back to the caller
  EndProgram,  // the program ends (after the block's NC part)
  RepeatStart, // the steps after this one up to RepeatEnd run `times` times
  RepeatEnd,   // this step is the last of the repeated ones
  WhileStart,  // while `condition` holds, the steps up to the WhileEnd of `loop` run
  WhileEnd,
  Jump,    // continue at `label` (when `condition` holds, if it is given)
  DoStart, // the steps up to DoEnd of `loop` run, again while DoEnd's `condition` holds
  DoEnd,
};

struct Flow {
  FlowKind kind = FlowKind::Assign;
  ir::Expr target;                   // Assign: the variable
  ir::Expr value;                    // Assign: the value
  std::optional<ir::Expr> condition; // WhileStart, Jump: a relational or logical expression
  std::string unit;                  // Call: the source's unit name
  long times = 1;                    // Call, RepeatStart
  std::string label;                 // Jump: the label's number as digits ("10")
  int loop = 0;                      // WhileStart / WhileEnd pair, unique in their unit
  SourceRange range;
};

/// One block of the source by meaning. Its parts act in this order: `before` (statements that
/// run before the NC part), the guard, the NC part (modes, words, dwell, M codes with their
/// timing), then `after` (calls, returns, repeat ends, jumps).
struct Step {
  SourceRange range;
  std::string label;    // a jump's target here: its number as digits ("10"), else empty
  std::string sequence; // the block number as the source wrote it, when it is no label
  std::vector<Flow> before;
  /// The rest of the step runs only when this holds (WL4 `IF (c) ...`, NCT `IF [c] THEN`).
  std::optional<ir::Expr> guard;
  /// What runs instead when the guard fails: the NC words before a WL4 IF in the middle of a
  /// block (`G1 X0 Z100 IF (c) Z0` moves to Z0 when c holds, to Z100 when not, wl4.md §6.5).
  std::shared_ptr<Step> otherwise;
  std::vector<Mode> modes;
  std::vector<Operand> words;
  std::optional<Value> dwellSeconds;
  std::vector<Machine> machine;
  std::vector<Flow> after;
  std::vector<std::string> comments;
  /// The block drills by a canned cycle (its code, or a position in the cycle's mode): its
  /// positions and cycle words are not in `words`; the holes its runs drilled are written in
  /// their place (structured_writer.h). Its other modes and M codes stay.
  bool cycle = false;
  /// A fillet (WL4 G12/G13, a quarter circle whose centre follows from where it starts): a target
  /// without one writes an arc with the centre offset its runs had (the same in every run).
  std::optional<GAction> fillet; // FilletCW / FilletCCW in force where the step moves
  bool cycleMoves = false;       // the cycle block has a position: it drills where it runs
  /// Its positions as written (X Y ... with their expressions): a hole that each run drills
  /// elsewhere is written at these.
  std::vector<Operand> cyclePositions;

  bool hasNcPart() const {
    return !modes.empty() || !words.empty() || dwellSeconds || !machine.empty();
  }
};

/// A program unit by meaning: the main program or one it calls.
struct UnitSteps {
  std::string name; // the source's unit name ("12", "019", "07"); the main program's file stem
  bool main = false;
  std::vector<Step> steps;
};

/// What structured translation could not keep, and why: the translation falls back to the flat
/// motion with this in its note.
struct Unkept {
  SourceRange where;
  std::string what, why;
};

} // namespace gcx::xlate
