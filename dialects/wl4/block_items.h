// What a WL4 block's items are, whichever parser found them (the hand parser of block_parser.cpp
// or the grammar's tree builder): the checks on N, L, IF<p>, %name and function names, and the IR
// each item becomes. One copy of each rule keeps the two paths' IR and errors the same.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "diag/diagnostic.h"
#include "front/raw_block.h"
#include "ir/block.h"

namespace gcx::wl4 {

/// Nested expressions and signed factors a block may hold (GCX017).
inline constexpr int kMaxExpressionDepth = 64;

/// A range of at least one character.
SourceRange rangeOf(const front::RawBlock& raw, std::size_t pos, std::size_t len);

/// Resets out to the empty block that raw begins.
void startBlock(const front::RawBlock& raw, ir::Block& out);
/// A block with nothing but comments and messages is a comment line.
void finishBlock(ir::Block& out);

/// The value of N's digits (text from `at`, the N, to `end`): 1-65535 (wl4.md §1.4), or a
/// located error.
std::optional<long long> nValue(const front::RawBlock& raw, std::size_t at, std::size_t end,
                                const std::string& digits, diag::Engine& diags);
/// N first in the block: its number, or a label when written with a leading 0 (§1.8).
void setSequence(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
                 const std::string& digits, long long n);
/// An N that is not first: after the block, continue at label N0.. (§6.6).
void addJump(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
             const std::string& digits, long long n);
/// L nn: program %nn once; L nnpp: pp times (§6.7); false after a located error.
bool addCall(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end,
             const std::string& digits, diag::Engine& diags);
/// IF<p>: compare at p decimals, one digit (§6.5); empty after a located error.
std::optional<int> guardPrecision(const front::RawBlock& raw, std::size_t digitsAt,
                                  const std::string& digits, diag::Engine& diags);
/// %name: at most 80 characters (§1.2); false after a located error.
bool checkProgramName(const front::RawBlock& raw, std::size_t nameAt, std::string_view name,
                      diag::Engine& diags);
/// `.` where a word would start: a message from `at` to `end` (§1.6).
void addMessage(const front::RawBlock& raw, ir::Block& out, std::size_t at, std::size_t end);
/// The `$` comment the block reader found, if any.
void addLineComment(const front::RawBlock& raw, ir::Block& out);
/// The function a name spells (§6.3), or null.
const ir::Func* functionNamed(std::string_view name);
/// The operator of §6.3 spelled at the start of s, with its length: level 1 `** * / MOD` binds
/// tighter than level 2 `== <> <= >= < > + - AND OR XOR`. A keyword must be a whole letter run.
std::optional<std::pair<std::size_t, ir::Op>> operatorAt(std::string_view s, int level);
/// GCX017 at `at`: the expression there is one level too deep.
void reportTooDeep(const front::RawBlock& raw, std::size_t at, diag::Engine& diags);
/// A word's literal value: `sign` is '-', '+' or 0; the text keeps a minus only.
void setLiteral(ir::Word& w, char sign, const std::string& number);

} // namespace gcx::wl4
