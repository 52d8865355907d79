// gcx expand FILE --to canonical: the flat RS274/NGC program of the program's motion.
#include "cli/commands.h"
#include "cli/execute.h"
#include "emit/canonical.h"

namespace gcx::cli {

int runExpand(const std::string& file, const ExpandOptions& opt) {
  if (opt.to != "canonical") {
    reportUsage("--to " + opt.to + " is not implemented yet; only --to canonical is");
    return UsageError;
  }
  Session s(opt.common);
  machine::Setup setup;
  if (int rc = openWithSetup(s, file, opt.setup, setup)) return rc;
  AtomicOutput out(opt.output);
  if (!out.ok()) {
    reportUsage("cannot write " + opt.output);
    return UsageError;
  }
  emit::CanonicalOptions copt;
  copt.provenance = opt.provenance;
  copt.fileName = [&](FileId id) { return s.sources().name(id); };
  emit::CanonicalEmitter emitter(out.stream(), copt);
  const bool ok = executeProgram(s, setup, emitter);
  s.flushDiagnostics();
  if (!ok) return ProgramErrors;
  return out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
