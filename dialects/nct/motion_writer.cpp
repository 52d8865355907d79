#include "dialects/nct/motion_writer.h"

#include "dialects/nct/emitter.h"
#include "dialects/nct/hole_writer.h"
#include "dialects/nct/profile.h"
#include "translate/flat_writer.h"

namespace gcx::nct {

namespace {

// O0001-O9999 (nct.md §1.1): the number in the source's name (O1001.nct, FMS-3000's 0019.fms),
// else 1.
int programNumber(const std::string& name) {
  std::string digits;
  for (char c : name)
    if (c >= '0' && c <= '9') digits += c;
  if (digits.empty() || digits.size() > 4) return 1;
  const int n = std::stoi(digits);
  return n == 0 ? 1 : n;
}

ir::Block comment(const std::string& text) {
  ir::Block b;
  ir::Comment c;
  c.text = text;
  for (char& ch : c.text) // a parenthesis would end or nest the comment
    if (ch == '(' || ch == ')') ch = ch == '(' ? '[' : ']';
  b.comments.push_back(std::move(c));
  return b;
}

} // namespace

std::unique_ptr<emit::MotionWriter>
makeMotionWriter(std::ostream& out, const emit::MotionWriterOptions& opt, diag::Engine& diags) {
  emit::FlatSyntax s;
  s.profile = &profile();
  s.label = "NCT";
  s.decimals = 3; // the least input increment, 0.001 mm
  ir::Block o;
  ir::Word w;
  w.address = "O";
  w.number = programNumber(opt.programName);
  o.words.push_back(w);
  s.opening.push_back(std::move(o));
  s.comment = comment;
  if (opt.keepCycles) s.holes = makeHoleWriter();
  return std::make_unique<emit::FlatWriter>(makeEmitter(out), std::move(s), opt, diags);
}

} // namespace gcx::nct
