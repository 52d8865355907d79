// gcx dump --ir: the IR of every block as one JSON object per line, with source locations.
#include <iostream>

#include "cli/commands.h"
#include "cli/session.h"
#include "ir/dump.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

int runDumpIr(const std::string& file, const CommonOptions& opt) {
  Session s(opt);
  if (!s.open(file)) return UsageError;
  check::StaticChecker checker(s.dialect().profile(), s.diags());
  ir::Block block;
  while (s.source().next(block)) {
    checker.block(block);
    std::cout << ir::toJson(block, true).dump() << '\n';
  }
  checker.finish(s.file(), s.source().failedBlocks() > 0);
  const bool failed = s.diags().hasErrors();
  CommonOptions quiet = opt;
  s.flushDiagnostics();
  return failed ? ProgramErrors : Ok;
}

} // namespace gcx::cli
