// Builds one ir::Block from the pieces a parser recognises. Both parse paths (the fast path for
// plain word-address blocks and the ANTLR path) go through it, so they cannot disagree on how
// a piece becomes IR.
#pragma once
#include <algorithm>
#include <string_view>

#include "diag/diagnostic.h"
#include "front/raw_block.h"
#include "ir/block.h"
#include "ir/new_expr.h"
#include "ir/short_text.h"

namespace gcx::nct {

class BlockBuilder {
public:
  /// reuseWords: out's words are overwritten in place rather than destroyed and built again
  /// (the fast path, one block after another into the same ir::Block); finish() then drops
  /// those left over. Only for a builder that never reads out's words while it builds.
  BlockBuilder(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags,
               bool reuseWords = false);
  /// Ends a block built with reuseWords.
  void finish() {
    if (reuse_ && words_ != out_.words.size()) out_.words.resize(words_);
  }

  /// `/` or `/n` at pos; digits empty for a bare `/`. With report false (the fast path, which
  /// leaves any block with a diagnostic to the grammar): a level that would be reported
  /// (out of range, or the warned-of 9) sets nothing, reports nothing and returns false.
  bool skip(std::size_t pos, std::size_t len, std::string_view digits, bool report = true);
  /// The first N of the block; report as for skip().
  bool sequence(std::size_t pos, std::size_t len, std::string_view digits, bool report = true);
  /// `%` or `%O0001`.
  void programStart(std::size_t pos, std::string_view number);
  /// An address with a literal number: `X-40`, `XI-40`, `G84.2`; sign is '-', '+' or 0 (none).
  void literalWord(std::string_view address, std::size_t pos, std::size_t len, bool incremental,
                   char sign, std::string_view digits);
  /// The same, for digits of at most 15 digits whose value the caller computed exactly (the
  /// same double front::decimalValue gives): such a number never has too many digits. `text`
  /// is the value as written: the sign, if any, and the digits with no blank between. Always
  /// inline: the fast path's every word, where a call's argument passing costs as much as the
  /// work.
  [[gnu::always_inline]] inline void literalWord(char letter, std::size_t pos, std::size_t len,
                                                 bool incremental, bool negative,
                                                 std::string_view text, double value);
  /// A comment whose '(' is at pos and ')' at pos+len-1.
  void comment(std::size_t pos, std::size_t len);

  /// A number token as a double; reports digits beyond the profile limit.
  double number(std::string_view digits, std::size_t pos);
  ir::Word& newWord(std::string_view address, std::size_t pos, std::size_t len);
  /// The block's next statement, placed in source order at pos.
  ir::Stmt& newStmt(ir::StmtKind kind, std::size_t pos, std::size_t len);
  SourceRange range(std::size_t pos, std::size_t len) const { return raw_.rangeAt(pos, len); }
  const front::RawBlock& raw() const { return raw_; }
  ir::Block& block() { return out_; }
  diag::Engine& diags() { return diags_; }
  bool ok() const { return ok_; }
  void fail() { ok_ = false; }

private:
  /// The next word: a new one, or with reuse the next word of the block before (reused true),
  /// whose fields still hold that block's.
  ir::Word& nextWord(bool& reused) {
    reused = words_ < reusable_; // not words.size(): a division by sizeof(Word) every word
    if (reuse_) ++words_;
    return reused ? out_.words[words_ - 1] : out_.words.emplace_back();
  }

  const front::RawBlock& raw_;
  ir::Block& out_;
  diag::Engine& diags_;
  bool ok_ = true;
  bool reuse_ = false;
  std::size_t words_ = 0;    // with reuse_: words of this block so far
  std::size_t reusable_ = 0; // with reuse_: the words of the block before, to overwrite
};

void BlockBuilder::literalWord(char letter, std::size_t pos, std::size_t len, bool incremental,
                               bool negative, std::string_view text, double value) {
  bool reused = false;
  ir::Word& w = nextWord(reused);
  if (reused) { // the fields below set the rest
    ir::resetExpr(w.expr);
    if (!w.axisIndex.empty()) w.axisIndex.clear();
  }
  if (w.address.size() == 1)
    w.address[0] = letter;
  else
    w.address.assign(1, letter);
  raw_.writeRange(w.range, pos, len);
  w.order = static_cast<std::uint32_t>(pos);
  w.incremental = incremental;
  w.kind = ir::ValueKind::Number;
  w.number = negative ? -value : value;
  if (text.size() <= 16)
    ir::assignShort(w.text, text.data(), text.size());
  else
    w.text.assign(text);
}

/// Whole units of a number token such as "0012" or "12.": false if it has a fraction.
bool wholeNumber(std::string_view digits, std::int64_t& value);

} // namespace gcx::nct
