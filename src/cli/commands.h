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

struct ExpandOptions {
  CommonOptions common;
  std::string to;
  std::string output; // empty: standard output
  std::string setup;
  bool provenance = false;
};
struct RunOptions {
  CommonOptions common;
  std::string setup;
  std::string trace;
  bool stats = false;
};
struct PlotOptions {
  CommonOptions common;
  std::string setup;
  std::string output;
  std::string view = "xy";
};

int runCheck(const std::vector<std::string>& files, const CommonOptions& opt);
int runFmt(const std::string& file, const std::string& output, const CommonOptions& opt);
int runDumpIr(const std::string& file, const CommonOptions& opt);
int runExpand(const std::string& file, const ExpandOptions& opt);
int runRun(const std::string& file, const RunOptions& opt);
int runPlot(const std::string& file, const PlotOptions& opt);

} // namespace gcx::cli
