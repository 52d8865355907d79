// Blocks, words and statements: the one intermediate representation every dialect parses into.
// A block is an ordered list of items (words, statements, comments); see ir/items.h for the
// walk in source order.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ir/expr.h"
#include "ir/source.h"

namespace gcx::ir {

enum class ValueKind : unsigned char {
  Number,     // a literal with its sign folded in
  Expression, // #n, -#n, [e], -[e] ... kept unevaluated for the macro pass
  Path,       // <file> of M98 / G65 (nct.md §5.1)
};

/// The address of a `<file>` word: the program of M98 / G65 given by file name.
inline constexpr const char* kPathAddress = "<>";

/// One address word: `X-40`, `XI-40` (incremental operator), `Z#1`, `,C5`, `AX[2]=10`, `M98
/// <a.nct>`, FMS `LIMS2000`, WL4 `L0703`.
struct Word {
  // User-provided, not defaulted: a defaulted one lets `Word()` (vector::resize, emplace_back)
  // zero the whole ~250 bytes before the member initializers run, a microcoded `rep stos` that
  // words reused block after block pay whenever a block has more words than the one before.
  Word() {}

  std::string address;      // upper case: "X", "G", ",C", "AX", "LIMS", "GG"
  bool incremental = false; // NCT I operator (nct.md §1.2 rule 4)
  ValueKind kind = ValueKind::Number;
  std::uint32_t order = 0; // place among the block's items (see Block)
  double number = 0;
  /// The value as written. A literal: sign and digits without blanks, "-40", "07" (FMS P07 is
  /// not P7), "0703" (WL4 L: program 07, 3 times), "1.". A Path: the file name (case kept).
  /// Empty for an expression. One string for both keeps a word small: blocks copy words.
  std::string text;
  Expr expr;                   // when kind == Expression
  std::vector<Expr> axisIndex; // AX[e]=: one element
  SourceRange range;

  bool isLiteral() const { return kind == ValueKind::Number; }
  bool is(char letter) const { return address.size() == 1 && address[0] == letter; }
};

enum class StmtKind : unsigned char {
  Assign, // target = value
  Goto,   // GOTO value
  IfGoto, // IF [cond] GOTO value
  IfThen, // IF [cond] THEN target = value
  While,  // WHILE [cond] DO loopId
  Do,     // DO loopId (endless loop)
  End,    // END loopId
  Print,  // DPRNT / BPRNT
  Popen,
  Pclos,
  Fopen,
  Fclos,
  Guard, // IF<p> (value): the items after it run only when value holds (wl4.md §6.5)
  Jump,  // after the block, continue at the label `label` (an N that is not first, wl4.md §6.6)
  Call,  // after the block, run program `callee` value times (WL4 L0703, FMS P019)
  CycleCall, // the canned cycle `callee` with its parameter words `args`, kept as one cycle
};

/// An item of DPRNT/BPRNT: literal text or a variable with its digit format `#v[cd]`.
struct PrintItem {
  bool isVariable = false;
  std::string text;
  int variable = 0;
  int intDigits = 0;
  int fracDigits = 0;
};

struct Stmt {
  StmtKind kind = StmtKind::Assign;
  Expr target; // Assign / IfThen: the variable written
  /// Assign / IfThen: right side; Goto / IfGoto / Jump: the label; Guard: the condition;
  /// Call: the repeat count.
  Expr value;
  std::optional<Condition> cond; // IfGoto, IfThen, While
  int loopId = 0;                // While / Do / End
  bool binaryPrint = false;      // Print: BPRNT instead of DPRNT
  std::vector<PrintItem> items;  // Print
  std::optional<double> device;  // Popen / Pclos / Fopen number
  std::optional<double> program; // Fopen P<n>
  std::string path;              // Fopen <file>
  std::string message;           // text of the comment after #3000= / #3006= ... (macro L4)
  std::optional<int> precision;  // Guard: IF<p> compares rounded to p decimals; none = full
  std::string label;             // Jump: the label's digits as written ("17" jumps to N017)
  std::string callee;            // Call: program name ("07", "019"); CycleCall: cycle ("G81")
  std::vector<Word> args;        // Call / CycleCall: argument or parameter words, in order
  SourceRange range;
  SourceRange loopRange;   // While / Do / End: the `DOm` / `ENDm` keyword with its number
  std::uint32_t order = 0; // place among the block's items (see Block)
};

enum class CommentKind : unsigned char {
  Inline,    // NCT `( ... )`
  ToLineEnd, // WL4 `$ ...`, FMS `rem ...`: the rest of the line
  Message,   // WL4 `. ...` where a word would start: shown to the operator at a stop
};

struct Comment {
  std::string text; // without its delimiters, as written
  CommentKind kind = CommentKind::Inline;
  SourceRange range;
  std::uint32_t order = 0; // place among the block's items (see Block)
};

enum class BlockKind : unsigned char {
  Normal,       // NC words and/or macro statements
  ProgramStart, // a heading line naming a program unit: NCT `%` / `%O0001`, WL4 `%name`
  Data,         // a record inside G10 L52 ... G11 (N is a parameter id, nct.md §1.10)
  ProgramEnd,   // the line closing a program unit: WL4 `%`
  CommentLine,  // a line that holds only a comment or message: FMS `rem`, WL4 `$` / `.`
  ContourEnd,   // the end of a cycle's contour blocks: FMS `endcont` (G164/G165)
};

/// A block. Its items (words, statements, comments) sit in three vectors; each item's `order`
/// gives its place in the source, so the left-to-right order that WL4 evaluates in and that
/// FMS cycle blocks depend on is kept without a side list that an edit could leave stale.
/// Parsers use the item's byte offset in the block; each vector is in source order.
struct Block {
  BlockKind kind = BlockKind::Normal;
  int skipLevel = 0;                    // 0: none, 1..9 for `/n` (`/` alone = 1)
  std::optional<std::int64_t> sequence; // first N (nct.md §1.7), its value
  std::string sequenceText;             // its digits as written: WL4 `N010` (a label) is not `N10`
  SourceRange sequenceRange;
  /// ProgramStart: the unit's name. Several units may share a file (WL4 `%name ... %`); NCT
  /// names a program by its number, `%O1` is "O0001".
  std::string programName;
  std::vector<Word> words;
  std::vector<Stmt> stmts; // NCT: at most one
  std::vector<Comment> comments;
  SourceRange range;          // begin = first byte of the block
  std::uint32_t lastLine = 0; // a comment may carry the block over several lines

  bool empty() const { return words.empty() && stmts.empty() && !sequence; }
  const Word* find(char letter) const {
    for (const Word& w : words)
      if (w.is(letter)) return &w;
    return nullptr;
  }
};

/// A whole program file, for the passes that need random access (jumps, subprograms).
struct Program {
  FileId file = 0;
  std::string name;
  std::vector<Block> blocks;
};

} // namespace gcx::ir
