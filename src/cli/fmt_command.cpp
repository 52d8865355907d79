// gcx fmt: the IR printed back as normalised text of the same dialect. The output goes to a
// temporary file first, so an error never leaves a partial output behind.
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "cli/commands.h"
#include "cli/session.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

namespace fs = std::filesystem;

int runFmt(const std::string& file, const std::string& output, const CommonOptions& opt) {
  Session s(opt);
  if (!s.open(file)) return UsageError;
  const fs::path target = output.empty() ? fs::path() : fs::path(output);
  const fs::path tmp = output.empty()
                           ? fs::temp_directory_path() / fmt::format("gcx-fmt-{}.tmp", ::getpid())
                           : fs::path(output + ".gcx-tmp");
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) {
    reportUsage(fmt::format("{}: cannot write", tmp.string()));
    return UsageError;
  }
  check::StaticChecker checker(s.dialect().profile(), s.diags());
  ir::Block block;
  while (s.source().next(block)) {
    checker.block(block);
    out << s.dialect().print(block) << '\n';
  }
  checker.finish(s.file(), s.source().failedBlocks() > 0);
  out.close();
  const bool failed = s.diags().hasErrors() || !out;
  s.flushDiagnostics();
  std::error_code ec;
  if (failed) {
    fs::remove(tmp, ec);
    return ProgramErrors;
  }
  if (!output.empty()) {
    fs::rename(tmp, target, ec);
    if (ec) {
      reportUsage(fmt::format("{}: cannot write: {}", output, ec.message()));
      fs::remove(tmp, ec);
      return UsageError;
    }
    return Ok;
  }
  std::ifstream back(tmp, std::ios::binary);
  std::cout << back.rdbuf();
  back.close();
  fs::remove(tmp, ec);
  return Ok;
}

} // namespace gcx::cli
