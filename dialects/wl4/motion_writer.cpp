#include "dialects/wl4/motion_writer.h"

#include "dialects/wl4/emitter.h"
#include "dialects/wl4/hole_writer.h"
#include "dialects/wl4/profile.h"
#include "dialects/wl4/structured_spelling.h"
#include "translate/flat_writer.h"

namespace gcx::wl4 {

std::unique_ptr<emit::MotionWriter>
makeMotionWriter(std::ostream& out, const emit::MotionWriterOptions& opt, diag::Engine& diags) {
  emit::FlatSyntax s;
  s.profile = &profile();
  s.label = "WL4";
  s.decimals = 3; // resolution 0.001 mm (002:40); more decimals are rounded when used
  s.programName = mainProgramName(opt.programName);
  s.comment = emit::lineComment;
  if (opt.keepCycles) s.holes = makeHoleWriter();
  return std::make_unique<emit::FlatWriter>(makeEmitter(out), std::move(s), opt, diags);
}

} // namespace gcx::wl4
