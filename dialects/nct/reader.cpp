#include "dialects/nct/reader.h"

#include "dialects/nct/fast_parser.h"
#include "dialects/nct/lexical_rules.h"
#include "dialects/nct/profile.h"

namespace gcx::nct {

Reader::Reader(std::istream& in, FileId file, diag::Engine& diags, front::ReaderLimits limits,
               std::optional<front::Encoding> encoding)
    : bytes_(in, file, diags, lexicalRules(), encoding.value_or(lexicalRules().encoding), limits),
      diags_(diags), profile_(profile()) {}

bool Reader::next(ir::Block& out) {
  while (bytes_.next(raw_)) {
    if (raw_.failed) {
      ++stats_.failed;
      continue;
    }
    bool ok = true;
    if (fastPath_ && parseFast(raw_, out, diags_) == FastResult::Parsed) {
      ++stats_.fastPath;
    } else {
      ok = grammar_.parse(raw_, out, diags_);
      ++stats_.grammar;
    }
    if (!ok) {
      ++stats_.failed;
      continue;
    }
    ++stats_.blocks;
    updateDataMode(out);
    return true;
  }
  return false;
}

// G10 L52 (parameters) and G10 L75-L77 (tool tables) switch to data records until G11
// (nct.md §1.10): in those records N is a parameter id, not a block number.
void Reader::updateDataMode(ir::Block& b) {
  bool g10 = false, g11 = false;
  const ir::Word* l = nullptr;
  for (const ir::Word& w : b.words) {
    if (w.is('G') && w.isLiteral()) {
      g10 |= w.number == 10;
      g11 |= w.number == 11;
    }
    if (w.is('L') && w.isLiteral()) l = &w;
  }
  if (dataMode_) {
    if (g11)
      dataMode_ = false;
    else
      b.kind = ir::BlockKind::Data;
    return;
  }
  if (g10 && l)
    for (int code : profile_.dataModeLCodes)
      if (l->number == code) dataMode_ = true;
}

} // namespace gcx::nct
