// Blocks, words and statements: the one intermediate representation every dialect parses into.
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
/// <a.nct>`.
struct Word {
  std::string address;      // upper case: "X", "G", ",C", "AX"
  bool incremental = false; // NCT I operator (nct.md §1.2 rule 4)
  ValueKind kind = ValueKind::Number;
  double number = 0;
  Expr expr;                   // when kind == Expression
  std::string path;            // when kind == Path, as written (case kept)
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
  Expr target;                   // Assign / IfThen: the variable written
  Expr value;                    // Assign / IfThen: right side; Goto / IfGoto: the label
  std::optional<Condition> cond; // IfGoto, IfThen, While
  int loopId = 0;                // While / Do / End
  bool binaryPrint = false;      // Print: BPRNT instead of DPRNT
  std::vector<PrintItem> items;  // Print
  std::optional<double> device;  // Popen / Pclos / Fopen number
  std::optional<double> program; // Fopen P<n>
  std::string path;              // Fopen <file>
  std::string message;           // text of the comment after #3000= / #3006= ... (macro L4)
  SourceRange range;
  SourceRange loopRange; // While / Do / End: the `DOm` / `ENDm` keyword with its number
};

struct Comment {
  std::string text; // without the parentheses, as written
  SourceRange range;
};

enum class BlockKind : unsigned char {
  Normal,       // NC words and/or one macro statement
  ProgramStart, // a `%` or `%O0001` heading line
  Data,         // a record inside G10 L52 ... G11 (N is a parameter id, nct.md §1.10)
};

struct Block {
  BlockKind kind = BlockKind::Normal;
  int skipLevel = 0;                    // 0: none, 1..9 for `/n` (`/` alone = 1)
  std::optional<std::int64_t> sequence; // first N (nct.md §1.7)
  SourceRange sequenceRange;
  std::optional<std::int64_t> programNumber; // `%O0001`
  std::vector<Word> words;
  std::optional<Stmt> stmt;
  std::vector<Comment> comments;
  SourceRange range;          // begin = first byte of the block
  std::uint32_t lastLine = 0; // a comment may carry the block over several lines

  bool empty() const { return words.empty() && !stmt && !sequence; }
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
