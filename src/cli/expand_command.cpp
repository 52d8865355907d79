// gcx expand FILE --to canonical: the flat RS274/NGC program of the program's motion.
// gcx expand FILE --to <dialect> --expand macros,subprograms: the program with macro statements,
// variables and calls flattened into plain blocks written by the dialect's emitter, canned
// cycles kept (the target must have them). Without --expand, a target whose programs hold no
// variables but calls and repeats (FMS-3000) keeps them: the program as written.
#include <filesystem>
#include <fmt/format.h>

#include "cli/commands.h"
#include "cli/execute.h"
#include "cycles/kept_contours.h"
#include "emit/canonical.h"
#include "passes/macro/expander.h"

namespace gcx::cli {

namespace {

class DiscardMotion : public motion::Sink {
public:
  void event(const motion::Event&) override {}
};

// Whether the dialect's machine runs canned cycles itself (NCT G81, FMS-3000 G81 by levels).
// WL4's G81-G89 and G70-G78 are programs, which --expand flattens like any other call.
bool runsCyclesItself(const Profile& p) {
  for (const GCodeSpec& g : p.gcodes)
    if (g.action == GAction::DrillCycle || g.action == GAction::TurningCycle ||
        g.action == GAction::LevelDrillCycle)
      return true;
  return false;
}

// A target whose programs have calls and repeats but no variables: nothing in a call or a
// repeat is computed by the expansion, so the program as written means what its run does.
bool keepsCallsAsWritten(const Dialect& target) {
  const emit::Capabilities c = target.emits();
  return c.has(emit::Construct::Subprograms) && c.has(emit::Construct::Loops) &&
         !c.has(emit::Construct::Variables);
}

int expandToDialect(Session& s, const Dialect& target, const ExpandOptions& opt,
                    const machine::Setup& setup) {
  // no --expand: flatten what the target cannot keep
  const bool asWritten = opt.expand.empty() && keepsCallsAsWritten(target);
  if (!opt.expand.empty() && opt.expand != "macros,subprograms" &&
      opt.expand != "subprograms,macros") {
    reportUsage("--to " + target.name +
                " supports --expand macros,subprograms (cycles stay cycles); expanding "
                "cycles is not implemented yet");
    return UsageError;
  }
  if (!target.emits().has(emit::Construct::CannedCycles) && runsCyclesItself(target.profile())) {
    reportUsage("--to " + target.name +
                " has no canned cycles, and expanding cycles is not implemented yet");
    return UsageError;
  }
  AtomicOutput out(opt.output, s.dialect().textEncoding()); // the program's own encoding
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
  std::unique_ptr<emit::ProgramEmitter> emitter = target.emitter(out.stream());
  emitter->beginProgram({});
  expander.onFlatBlock([&](const ir::Block& b) {
    if (asWritten) return; // the run only proves the program; its text is written below
    ir::Block flat = b;    // comments and numbers do not survive, but those kept cycles refer to
    if (flat.sequence && !contours.keepsNumber(*flat.sequence)) {
      flat.sequence.reset();
      flat.sequenceText.clear();
    }
    flat.comments.clear();
    // a wordless block is dropped, but for the end of a cycle's contour (FMS `endcont`)
    if (flat.words.empty() && flat.kind != ir::BlockKind::ContourEnd) return;
    contours.written(flat);
    emitter->block(flat);
  });
  const bool ok = expander.run(*main) && (asWritten || contours.check(s.diags()));
  if (ok && asWritten) // every block as read, comments included: the calls stay calls
    for (const ir::Block& b : main->blocks)
      emitter->block(b);
  emitter->endProgram();
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

// "canonical and --to nct": the targets expand writes
std::string targetList() {
  std::string list = "canonical";
  const std::vector<std::string> names = dialectNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    list += (i + 1 == names.size() ? " and --to " : ", --to ") + names[i];
  return list;
}

// "--to nct": the targets that keep canned cycles
std::string cycleTargets() {
  std::string list;
  for (const Dialect& d : dialects())
    if (d.emits().has(emit::Construct::CannedCycles))
      list += (list.empty() ? "--to " : ", --to ") + d.name;
  return list;
}

} // namespace

int runExpand(const std::string& file, const ExpandOptions& opt) {
  const Dialect* target = opt.to == "canonical" ? nullptr : findDialect(opt.to);
  if (opt.to != "canonical" && !target) {
    reportUsage("--to " + opt.to + " is not implemented yet; --to " + targetList() + " are");
    return UsageError;
  }
  const bool keepsCycles = target && target->emits().has(emit::Construct::CannedCycles);
  // canonical motion is RS274/NGC: LinuxCNC compensates itself (G41.1/G42.1)
  const bool keepsComp = opt.keep == "comp" && !target;
  if (!opt.keep.empty() && !keepsComp && (opt.keep != "cycles" || !keepsCycles)) {
    reportUsage(opt.keep == "comp" ? "--keep comp needs --to canonical (a target that compensates "
                                     "itself; --to " +
                                         opt.to + " keeps G41/G42 as written)"
                : opt.keep != "cycles"
                    ? "--keep takes cycles or comp"
                    : fmt::format("--keep cycles needs a target with canned cycles ({}); {} has "
                                  "none",
                                  cycleTargets(), target ? target->name : "canonical motion"));
    return UsageError;
  }
  ExpandOptions kept = opt;
  kept.common.keepCompensation = keepsComp;
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  // The same code means other things in another dialect (FMS-3000 G04 E is tenths of a second,
  // NCT G4 P seconds): writing one dialect's blocks as another's is a translation, never a copy.
  if (target && target->name != s.dialect().name) {
    reportUsage(fmt::format("--to {} from a {} program is a translation between dialects: gcx "
                            "translate --to {} writes its motion with the codes' meaning",
                            target->name, s.dialect().name, target->name));
    return UsageError;
  }
  if (target) return expandToDialect(s, *target, opt, setup);
  AtomicOutput out(opt.output);
  PrintOutput print(opt.common, opt.output.empty());
  if (!out.ok() || !print.ok()) return UsageError;
  emit::CanonicalOptions copt;
  copt.provenance = opt.provenance;
  copt.fileName = [&](FileId id) { return s.sources().name(id); };
  emit::CanonicalEmitter emitter(out.stream(), copt);
  const bool ok = executeProgram(s, kept.common, setup, emitter, print.stream());
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return print.finish() && out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
