// gcx check: syntax plus static checks; a one-line summary per file.
#include <fmt/format.h>
#include <iostream>

#include "cli/check_in_parts.h"
#include "cli/commands.h"
#include "cli/session.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

int runCheck(const std::vector<std::string>& files, const CommonOptions& opt) {
  int exit = Ok;
  for (const std::string& path : files) {
    Session s(opt);
    if (!s.open(path)) {
      exit = UsageError;
      continue;
    }
    check::StaticChecker checker(s.dialect().profile(), s.diags());
    const CheckedBlocks read = checkBlocks(s, checker, opt.jobs);
    const std::size_t blocks = read.blocks;
    checker.finish(s.file(), read.failed > 0);
    const std::size_t errors = s.diags().errorCount(), warnings = s.diags().warningCount();
    s.flushDiagnostics();
    if (!opt.json)
      std::cout << fmt::format("{}: {} blocks, {} error{}, {} warning{}\n", path, blocks, errors,
                               errors == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s");
    if (errors && exit == Ok) exit = ProgramErrors;
  }
  return exit;
}

} // namespace gcx::cli
