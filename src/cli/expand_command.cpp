// gcx expand FILE --to canonical: the flat RS274/NGC program of the program's motion.
// gcx expand FILE --to nct --expand macros,subprograms: the program with macro statements,
// variables and calls flattened into plain NCT blocks, canned cycles kept.
#include <filesystem>

#include "cli/commands.h"
#include "cli/execute.h"
#include "cycles/kept_contours.h"
#include "dialects/nct/printer.h"
#include "emit/canonical.h"
#include "passes/macro/expander.h"

namespace gcx::cli {

namespace {

class DiscardMotion : public motion::Sink {
public:
  void event(const motion::Event&) override {}
};

int expandToNct(Session& s, const ExpandOptions& opt, const machine::Setup& setup) {
  if (opt.expand != "macros,subprograms" && opt.expand != "subprograms,macros") {
    reportUsage("--to nct supports --expand macros,subprograms (cycles stay cycles); expanding "
                "cycles is not implemented yet");
    return UsageError;
  }
  AtomicOutput out(opt.output);
  PrintOutput print(opt.common, opt.output.empty());
  if (!out.ok() || !print.ok()) return UsageError;
  macro::ProgramLibrary library(s.dialect(), s.sources(), s.diags(), opt.common.libraryDirs);
  const macro::LoadedProgram* main = library.load(s.path());
  if (!main) {
    s.flushDiagnostics();
    return ProgramErrors;
  }
  DiscardMotion discard;
  machine::Interpreter interp(s.dialect().profile(), setup, discard, s.diags());
  interp.setDeferCycles(true);
  std::error_code sizeError;
  const std::uintmax_t programBytes = std::filesystem::file_size(s.path(), sizeError);
  limitMachine(interp, opt.common, sizeError ? 0 : programBytes);
  macro::Expander expander(library, interp, s.diags(), expansionLimits(opt.common));
  expander.setPrintOutput(&print.stream());
  if (opt.common.fanucVacantOrder) expander.setVacantOrder(macro::VacantOrder::Fanuc);
  cycles::KeptContours contours(main->blocks, s.dialect().profile());
  expander.onFlatBlock([&](const ir::Block& b) {
    ir::Block flat = b; // comments and numbers do not survive, but those kept cycles refer to
    if (flat.sequence && !contours.keepsNumber(*flat.sequence)) {
      flat.sequence.reset();
      flat.sequenceText.clear();
    }
    flat.comments.clear();
    if (flat.words.empty()) return;
    contours.written(flat);
    out.stream() << nct::printBlock(flat) << '\n';
  });
  const bool ok = expander.run(*main) && contours.check(s.diags());
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace

int runExpand(const std::string& file, const ExpandOptions& opt) {
  if (opt.to != "canonical" && opt.to != "nct") {
    reportUsage("--to " + opt.to + " is not implemented yet; --to canonical and --to nct are");
    return UsageError;
  }
  if (!opt.keep.empty() && (opt.keep != "cycles" || opt.to != "nct")) {
    reportUsage(opt.keep != "cycles" ? "--keep takes cycles"
                                     : "--keep cycles needs a target with canned cycles (--to "
                                       "nct); canonical motion has none");
    return UsageError;
  }
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  if (opt.to == "nct") return expandToNct(s, opt, setup);
  AtomicOutput out(opt.output);
  PrintOutput print(opt.common, opt.output.empty());
  if (!out.ok() || !print.ok()) return UsageError;
  emit::CanonicalOptions copt;
  copt.provenance = opt.provenance;
  copt.fileName = [&](FileId id) { return s.sources().name(id); };
  emit::CanonicalEmitter emitter(out.stream(), copt);
  const bool ok = executeProgram(s, opt.common, setup, emitter, print.stream());
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
