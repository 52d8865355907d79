// gcx plot FILE -o OUT.svg: the tool path as a picture (rapids dashed, feeds solid).
#include "cli/commands.h"
#include "cli/execute.h"
#include "motion/svg_plotter.h"

namespace gcx::cli {

int runPlot(const std::string& file, const PlotOptions& opt) {
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  motion::SvgOptions sopt;
  sopt.view = opt.view == "xz"    ? motion::View::XZ
              : opt.view == "yz"  ? motion::View::YZ
              : opt.view == "iso" ? motion::View::Iso
                                  : motion::View::XY;
  sopt.title = file;
  AtomicOutput out(opt.output);
  PrintOutput print(opt.common, false);
  if (!out.ok() || !print.ok()) return UsageError;
  motion::SvgPlotter plotter(out.stream(), sopt);
  const bool ok = executeProgram(s, opt.common, setup, plotter, print.stream());
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
