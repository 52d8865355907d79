// gcx fmt: the IR printed back as normalised text of the same dialect, in the encoding it was
// read in. The output goes to a temporary file first, so an error never leaves a partial output
// behind.
#include "cli/commands.h"
#include "cli/execute.h"
#include "cli/session.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

int runFmt(const std::string& file, const std::string& output, const CommonOptions& opt) {
  Session s(opt);
  if (!s.open(file)) return UsageError;
  AtomicOutput out(output, s.dialect().textEncoding()); // in the dialect's own encoding
  if (!out.ok()) return UsageError;
  check::StaticChecker checker(s.dialect().profile(), s.diags());
  std::unique_ptr<emit::ProgramEmitter> emitter = s.dialect().emitter(out.stream());
  emitter->beginProgram({});
  ir::Block block;
  while (s.source().next(block)) {
    checker.block(block);
    emitter->block(block);
  }
  emitter->endProgram();
  checker.finish(s.file(), s.source().failedBlocks() > 0);
  const bool failed = s.diags().hasErrors();
  s.flushDiagnostics();
  if (failed) return ProgramErrors;
  return out.commit() ? Ok : UsageError;
}

} // namespace gcx::cli
