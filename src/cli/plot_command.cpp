// gcx plot FILE -o OUT.svg: the tool path as a picture (rapids dashed, feeds solid), in the
// work frame unless --frame machine or --frame program.
#include "cli/commands.h"
#include "cli/execute.h"
#include "motion/svg_plotter.h"

namespace gcx::cli {

int runPlot(const std::string& file, const PlotOptions& opt) {
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  motion::SvgOptions sopt;
  sopt.view = motion::parseView(opt.view).value_or(motion::View::XY);
  sopt.title = file;
  const bool machineFrame = opt.frame == "machine";
  // In the machine frame the marker shows where the program's zero starts out.
  if (machineFrame) sopt.origin = initialWorkOrigin(s, setup);
  sopt.title += ", " + opt.frame + " frame";
  AtomicOutput out(opt.output);
  PrintOutput print(opt.common, false);
  if (!out.ok() || !print.ok()) return UsageError;
  motion::SvgPlotter plotter(out.stream(), sopt);
  const bool ok =
      executeProgram(s, opt.common, setup, plotter, print.stream(), frameNamed(opt.frame));
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
