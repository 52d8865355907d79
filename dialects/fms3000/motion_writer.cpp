#include "dialects/fms3000/motion_writer.h"

#include "dialects/fms3000/emitter.h"
#include "dialects/fms3000/hole_writer.h"
#include "dialects/fms3000/profile.h"
#include "translate/flat_writer.h"

namespace gcx::fms3000 {

// A program is named by its file (fms3000.md §1.3): the text has no name of its own.
std::unique_ptr<emit::MotionWriter>
makeMotionWriter(std::ostream& out, const emit::MotionWriterOptions& opt, diag::Engine& diags) {
  emit::FlatSyntax s;
  s.profile = &profile();
  s.label = "FMS-3000";
  // 0.1 µm: the control's resolution is 0.001 mm (001:417-419), but an arc's end and centre each
  // rounded to it can leave radii 0.0014 mm apart, beyond N3020's 0.001 mm
  s.decimals = 4;
  s.codeDigits = 2; // G00, G04, M03 as the manual writes them
  s.comment = emit::lineComment;
  if (opt.keepCycles) s.holes = makeHoleWriter();
  return std::make_unique<emit::FlatWriter>(makeEmitter(out), std::move(s), opt, diags);
}

} // namespace gcx::fms3000
