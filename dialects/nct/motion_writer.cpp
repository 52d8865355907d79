#include "dialects/nct/motion_writer.h"

#include "dialects/nct/emitter.h"
#include "dialects/nct/hole_writer.h"
#include "dialects/nct/profile.h"
#include "dialects/nct/structured_spelling.h"
#include "translate/flat_writer.h"

namespace gcx::nct {

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
  s.comment = structuredSpelling().commentLine;
  if (opt.keepCycles) s.holes = makeHoleWriter();
  return std::make_unique<emit::FlatWriter>(makeEmitter(out), std::move(s), opt, diags);
}

} // namespace gcx::nct
