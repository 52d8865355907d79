#include "dialects/fms3000/printer.h"

#include "emit/number.h"

namespace gcx::fms3000 {

namespace {

// A word's text as written when there is one, else its value in millimetres: FMS-3000 reads a
// number without a point as millimetres too (fms3000.md §1.2).
std::string valueText(const ir::Word& w) {
  if (!w.text.empty()) return w.text;
  return emit::formatNumber(w.number);
}

} // namespace

std::string printBlock(const ir::Block& b) {
  if (b.kind == ir::BlockKind::ContourEnd) return "endcont";
  std::string out;
  auto separate = [&] {
    if (!out.empty()) out += ' ';
  };
  if (b.kind == ir::BlockKind::CommentLine) {
    for (const ir::Comment& c : b.comments) {
      separate();
      out += "rem";
      if (!c.text.empty()) out += ' ' + c.text;
    }
    return out;
  }
  if (!b.sequenceText.empty() || b.sequence) {
    out = "N" + (b.sequenceText.empty() ? std::to_string(*b.sequence) : b.sequenceText);
  }
  for (const ir::Word& w : b.words) {
    separate();
    out += w.address + valueText(w);
  }
  return out;
}

} // namespace gcx::fms3000
