// How a target dialect writes a program's structure (docs/translation.md, "Structure across
// dialects"): its loops and jumps, its statements, its calls and program units. Its codes come from
// its profile by meaning; this is the rest, given by each dialect in
// dialects/<d>/structured_spelling.* (listed in dialects/structured_spellings.cpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"
#include "translate/hole_lowering.h"

namespace gcx::xlate {

struct StructuredSpelling {
  const Profile* profile = nullptr;
  const char* label = ""; // the dialect as messages name it: "FMS-3000"
  std::string extension;  // of its files: ".nct"
  int decimals = 3;       // literal values are rounded to the control's resolution
  int codeDigits = 1;     // G and M numbers written with at least this many digits (G00)

  /// WHILE [c] DOm ... ENDm nests this deep (NCT: 3); 0: the dialect has no WHILE.
  int maxWhileNesting = 0;
  /// GOTO n and IF [c] GOTO n to a block numbered n (NCT): a label is a block number.
  bool gotoJumps = false;
  /// A jump is a block number after the block's first word, to a label written with a leading
  /// zero, and IF (c) guards the rest of a block (WL4).
  bool guardJumps = false;
  int maxLabels = 0; // per program unit (WL4: 127); 0: no limit
  /// Loops are named uniquely in the file (LinuxCNC o-words), not by their nesting depth (NCT DOm).
  bool uniqueLoopIds = false;
  /// `do ... while [c]` loops, tested after each pass (LinuxCNC): a jump back to a label becomes
  /// one where the target has no jumps.
  bool doWhileLoops = false;
  /// A call stands in a block of its own (LinuxCNC `o<n> call`).
  bool callsAlone = false;
  /// A unit returns at its closing line (LinuxCNC `endsub`): the source's last return is that.
  bool returnAtEnd = false;
  /// The called units come before the main program in their file (LinuxCNC finds a subroutine
  /// defined before its call).
  bool subprogramsFirst = false;
  /// Assignments stand in a block with its words, after them (WL4); else one to a block (NCT).
  bool statementsBesideWords = false;
  /// The highest repeat count one call writes (WL4 `L nnpp`: 99); more are a counted loop.
  long maxCallTimes = 0;
  /// Whether the dialect writes this expression node (its operator or function, not its
  /// arguments); null: none (no variables, so no expressions).
  std::function<bool(const ir::Expr&)> writes;

  /// A comment on a block (NCT `( )`, WL4 `$`); null: comments stand on lines of their own.
  std::function<ir::Comment(const std::string&)> blockComment;
  /// A comment line.
  std::function<ir::Block(const std::string&)> commentLine;

  /// Several units in one file (WL4 `%name ... %`); else a file each.
  bool unitsInOneFile = false;
  /// The name of a called unit in this dialect for the source's unit `source` (its digits as
  /// written), not one of `taken`; empty when the dialect has no name left.
  std::function<std::string(const std::string& source, const std::set<std::string>& taken)>
      subprogramName;
  /// The main program's name for the source file's stem.
  std::function<std::string(const std::string& stem, const std::set<std::string>& taken)> mainName;
  /// The file of a unit written in a file of its own ("O0012.nct", "12.fms").
  std::function<std::string(const std::string& unit)> fileName;
  /// Blocks that open and close a unit (NCT `O12`, WL4 `%12` ... `%`).
  std::function<std::vector<ir::Block>(const std::string&unit, bool main)> opening, closing;
  /// Adds to `b` the call of `unit`, `times` times (at most maxCallTimes when that is set).
  std::function<void(ir::Block& b, const std::string& unit, long times)> call;
  /// The dialect's drilling cycles for the holes a source's cycle drilled; null: none kept.
  std::function<std::unique_ptr<HoleLowering>()> holes;
};

/// The structured spelling of a dialect, or null when gcx writes no structure in it yet.
const StructuredSpelling* structuredSpellingFor(std::string_view dialect);

} // namespace gcx::xlate
