// The gcx subcommands. Each returns the process exit code: 0 ok, 1 the program has errors,
// 2 usage or I/O error.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace gcx::cli {

enum Exit { Ok = 0, ProgramErrors = 1, UsageError = 2 };

struct CommonOptions {
  std::string dialect; // empty: from the file extension
  bool json = false;   // diagnostics as JSON
  std::size_t maxErrors = 50;
};

int runCheck(const std::vector<std::string>& files, const CommonOptions& opt);
int runFmt(const std::string& file, const std::string& output, const CommonOptions& opt);
int runDumpIr(const std::string& file, const CommonOptions& opt);

} // namespace gcx::cli
