// gcx translate DIR --to T -o OUTDIR: every program of a tree, each translated and verified by
// its own gcx process (a program that fails, or crashes, does not stop the rest), N at a time;
// a summary on standard output and report.csv / report.html in OUTDIR.
#pragma once
#include <string>

#include "cli/commands.h"

namespace gcx::cli {

int runTranslateBatch(const std::string& folder, const TranslateOptions& opt);

} // namespace gcx::cli
