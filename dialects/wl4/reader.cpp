#include "dialects/wl4/reader.h"

#include <fmt/format.h>

#include "diag/codes.h"
#include "dialects/wl4/block_parser.h"
#include "dialects/wl4/block_rules.h"
#include "dialects/wl4/control_flow.h"
#include "dialects/wl4/fanuc_traps.h"
#include "dialects/wl4/lexical_rules.h"

namespace gcx::wl4 {

Reader::Reader(std::istream& in, FileId file, diag::Engine& diags,
               std::optional<front::Encoding> encoding)
    : bytes_(in, file, diags, lexicalRules(), encoding.value_or(lexicalRules().encoding)),
      diags_(diags) {}

bool Reader::next(ir::Block& out) {
  while (bytes_.next(raw_)) {
    if (raw_.failed || !parse(out) || duplicateLabel(out) || !checkBlockRules(out, diags_)) {
      ++failed_;
      continue;
    }
    warnFanucTraps(out, diags_);
    return true;
  }
  return false;
}

bool Reader::parse(ir::Block& out) {
  if (fastPath_) return parseBlock(raw_, out, diags_);
  if (!grammar_) grammar_ = std::make_unique<GrammarParser>();
  return grammar_->parse(raw_, out, diags_);
}

bool Reader::duplicateLabel(const ir::Block& b) {
  if (b.kind == ir::BlockKind::ProgramStart) labels_.clear(); // labels are per program
  const bool label = b.sequence && isLabel(b.sequenceText);
  if (!label) return false;
  if (labels_.insert(*b.sequence).second) {
    if (labels_.size() <= 127) return false;
    diags_.error(diag::code::Wl4TooManyLabels, b.sequenceRange,
                 fmt::format("label {} is the 128th of this program: a program has at most 127 "
                             "(wl4.md §1.8, 002:2020-2021)",
                             *b.sequence));
    return true;
  }
  diags_.error(diag::code::Wl4DuplicateLabel, b.sequenceRange,
               fmt::format("label {} appears twice in this program (wl4.md §1.8)", *b.sequence));
  return true;
}

} // namespace gcx::wl4
