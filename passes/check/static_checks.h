// Static checks of a program, block by block as it streams past (gcx check): addresses and
// their values against the dialect's table, repeated words, modal-group conflicts, loop
// pairing (nct-macro.md §4.5) and GOTO targets. Needs no machine state.
#pragma once
#include <optional>
#include <unordered_set>
#include <vector>

#include "diag/diagnostic.h"
#include "dialect/profile.h"
#include "ir/block.h"

namespace gcx::check {

class StaticChecker {
public:
  StaticChecker(const Profile& profile, diag::Engine& diags) : profile_(profile), diags_(diags) {}

  void block(const ir::Block& b);
  /// End of the file: unclosed loops, missing GOTO targets, an empty program (unless blocks
  /// were there but failed to parse: hadBadBlocks).
  void finish(FileId file, bool hadBadBlocks);
  /// Takes in the checks of the next part of the file, made by a new checker (gcx check on
  /// several threads): true when they are exactly what this checker would have found reading
  /// on; false, joining nothing, when they could depend on this checker's state (an open loop, a
  /// pending '%', a '%' that comes after blocks).
  /// lineShift: next numbered the lines of its part from a provisional first line; its findings
  /// kept for finish() move to the lines they stand at.
  bool join(StaticChecker&& next, std::int64_t lineShift = 0);

private:
  void words(const ir::Block& b);
  void literal(const ir::Word& w, const AddressSpec& spec);
  void literalFindings(const ir::Word& w, const AddressSpec& spec);
  void dataRecord(const ir::Block& b);
  void callArguments(const ir::Block& b);
  void statement(const ir::Stmt& s);
  void finiteLiterals(const ir::Expr& e);

  struct OpenLoop {
    int id;
    SourceRange where;
  };
  struct Jump {
    std::int64_t target;
    SourceRange where;
    bool conditional; // IF[...]GOTO: the control alarms only when the jump is taken
  };

  const Profile& profile_;
  diag::Engine& diags_;
  std::size_t blocks_ = 0;
  std::optional<SourceRange> percentAfterStart_;
  bool startBeforeBlocks_ = false; // a '%' came while blocks_ was 0 (join)
  std::vector<OpenLoop> loops_;
  std::vector<std::pair<std::string_view, int>> wordCounts_; // words(): per address, this block
  std::vector<Jump> jumps_;
  std::unordered_set<std::int64_t> labels_;
};

} // namespace gcx::check
