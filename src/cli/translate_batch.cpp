#include "cli/translate_batch.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <map>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "cli/translate_target.h"
#include "diag/diagnostic.h"
#include "dialect/control_flow.h"
#include "dialect/dialect.h"
#include "motion/xml_text.h"
#include "translate/program_calls.h"

extern char** environ;

namespace gcx::cli {

namespace fs = std::filesystem;

namespace {

struct Job {
  fs::path input;
  const Dialect* dialect = nullptr;
  std::string relative; // as the report names it
  fs::path output;
  std::string setup;
  // result
  int exitCode = -1;
  double seconds = 0;
  long peakKb = 0;
  std::string reason;
  std::string status;         // verified, written, failed, subprogram
  std::string kept, expanded; // the structures, from the child's note
};

// The programs of the tree in a stable order, each with the dialect its name (or --from) gives.
std::vector<Job> collect(const fs::path& root, const fs::path& outRoot, const TranslateOptions& opt,
                         std::size_t& skipped) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<Job> jobs;
  for (const fs::path& f : files) {
    // --from names the dialect of files whose extension names none (not setups, nor the
    // output folder's own files)
    const Dialect* d = dialectForPath(f.string());
    if (!d && !opt.common.dialect.empty() && f.extension() != ".json")
      d = findDialect(opt.common.dialect);
    const bool inOutput =
        fs::weakly_canonical(f).string().starts_with(fs::weakly_canonical(outRoot).string() + "/");
    if (!d || inOutput) {
      ++skipped; // setups, notes, LinuxCNC twins: not programs of a dialect gcx reads
      continue;
    }
    std::string why;
    const std::optional<ExpandSet> expand = parseExpand(opt.expand, why);
    const auto target = expand ? translateTarget(*d, opt.to, *expand, why) : std::nullopt;
    Job j;
    j.input = f;
    j.dialect = d;
    // by the path under root, not where a symlink points: the output stays under OUTDIR
    j.relative = f.lexically_relative(root).string();
    fs::path out = outRoot / j.relative;
    out.replace_extension(target ? target->extension : ".out");
    j.output = out;
    // a program's own setup beside it wins over --setup
    fs::path sidecar = f;
    sidecar.replace_extension(".setup.json");
    j.setup = fs::exists(sidecar) ? sidecar.string() : opt.setup;
    if (!target) j.status = "failed", j.reason = why, j.exitCode = UsageError;
    jobs.push_back(std::move(j));
  }
  return jobs;
}

// What a program calls and how it ends, read block by block with its dialect's reader; a file
// that does not read gives nothing here (its own translation reports why).
xlate::ProgramCalls callsOf(const Job& j) {
  std::ifstream in(j.input, std::ios::binary);
  SourceManager sources;
  diag::Engine diags;
  const FileId file = sources.addFile(j.input.string());
  const std::unique_ptr<BlockSource> source = j.dialect->open(in, file, diags);
  xlate::CallScanner scanner(j.dialect->profile());
  ir::Block block;
  while (source->next(block))
    scanner.block(block);
  return scanner.result();
}

// A program that only runs as a subprogram is not run alone (where it would restart or fail
// at its return until a limit stops it): one that another program of the batch calls is
// translated with that caller; one that ends in a return with no caller in the batch is
// reported as a subprogram. A dialect whose return ends a main program (FMS-3000 M99) runs
// such a file as a main program.
void markSubprograms(std::vector<Job>& jobs) {
  std::map<std::string, std::size_t> byPath; // canonical path -> job
  for (std::size_t i = 0; i < jobs.size(); ++i)
    byPath[fs::weakly_canonical(jobs[i].input).string()] = i;
  std::vector<xlate::ProgramCalls> calls(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i)
    if (jobs[i].status.empty()) calls[i] = callsOf(jobs[i]);
  std::vector<std::string> callers(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const Job& caller = jobs[i];
    const ControlFlow* flow = caller.dialect->profile().controlFlow;
    std::vector<std::string> names = calls[i].files;
    if (flow && flow->programFiles)
      for (const std::string& unit : calls[i].units)
        for (const std::string& name : flow->programFiles(unit, caller.input.extension().string()))
          names.push_back(name);
    for (const std::string& name : names) {
      const auto it = byPath.find(fs::weakly_canonical(caller.input.parent_path() / name).string());
      if (it == byPath.end() || it->second == i) continue;
      std::string& by = callers[it->second];
      if (by.find(caller.relative) == std::string::npos)
        by += (by.empty() ? "" : ", ") + caller.relative;
    }
  }
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    Job& j = jobs[i];
    if (!j.status.empty()) continue;
    const ControlFlow* flow = j.dialect->profile().controlFlow;
    if (!callers[i].empty()) {
      j.status = "subprogram", j.exitCode = Ok;
      j.reason = fmt::format("called by {}: translated with its caller", callers[i]);
    } else if (calls[i].endsByReturn && !(flow && flow->returnInMainEnds)) {
      j.status = "subprogram", j.exitCode = Ok;
      j.reason = fmt::format("ends in {}, a return to its caller, and no program of the folder "
                             "calls it: a subprogram runs only when called",
                             calls[i].endCode);
    }
    if (j.status == "subprogram") j.output.clear(); // no file of its own
  }
}

std::vector<std::string> childArguments(const Job& j, const TranslateOptions& opt) {
  std::vector<std::string> a{"gcx",  "translate", j.input.string(), "--to",
                             opt.to, "-o",        j.output.string()};
  if (!j.setup.empty()) a.insert(a.end(), {"--setup", j.setup});
  if (!opt.common.dialect.empty()) a.insert(a.end(), {"--from", opt.common.dialect});
  if (!opt.verify) a.push_back("--no-verify");
  if (opt.writeOffsets) a.push_back("--write-offsets");
  if (!opt.expand.empty()) a.insert(a.end(), {"--expand", opt.expand});
  a.insert(a.end(), {"--tol", fmt::format("{}", opt.tolerance), "--rs274", opt.rs274});
  for (const std::string& lib : opt.common.libraryDirs)
    a.insert(a.end(), {"--lib", lib});
  return a;
}

// The child's note ("gcx: note: IN: ...") as its kept and expanded structures.
void readNote(const fs::path& log, const fs::path& input, Job& j) {
  std::ifstream in(log);
  const std::string head = "gcx: note: " + input.string() + ": ";
  for (std::string line; std::getline(in, line);)
    if (line.starts_with(head)) {
      const NoteParts parts = splitNote(line.substr(head.size()));
      j.kept = parts.kept;
      j.expanded = parts.expanded;
    }
}

// The first error line of a child's standard error (without the "file:line:col: error: "
// prefix's program name), or its last line.
std::string reasonFrom(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.find("error") != std::string::npos) return line;
    last = line;
  }
  return last;
}

struct Running {
  pid_t pid;
  std::size_t job;
  std::chrono::steady_clock::time_point start;
  fs::path log;
};

bool spawn(Job& j, std::size_t index, const TranslateOptions& opt, const fs::path& self,
           const fs::path& logs, std::vector<Running>& running) {
  fs::create_directories(j.output.parent_path());
  const fs::path log = logs / fmt::format("{}.log", index);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = childArguments(j, opt);
  std::vector<char*> argv;
  for (std::string& s : args)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    j.status = "failed", j.exitCode = UsageError;
    j.reason = fmt::format("cannot start gcx: {}", std::strerror(rc));
    return false;
  }
  running.push_back({pid, index, std::chrono::steady_clock::now(), log});
  return true;
}

void finish(Job& j, int status, const rusage& usage, const Running& r) {
  j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
  j.peakKb = usage.ru_maxrss;
  if (WIFSIGNALED(status)) {
    j.exitCode = 128 + WTERMSIG(status);
    j.status = "failed";
    j.reason = fmt::format("gcx stopped by signal {}", WTERMSIG(status));
  } else {
    j.exitCode = WEXITSTATUS(status);
    j.status = j.exitCode == 0 ? "ok" : "failed";
    if (j.exitCode != 0) j.reason = reasonFrom(r.log);
    if (j.exitCode == 0) readNote(r.log, j.input, j);
  }
  std::error_code ec;
  fs::remove(r.log, ec);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void writeReports(const fs::path& outRoot, const std::vector<Job>& jobs, const std::string& status,
                  const std::string& summary) {
  std::ofstream csv(outRoot / "report.csv");
  csv << "program,output,status,exit,seconds,peak_rss_kb,reason,kept,expanded\n";
  for (const Job& j : jobs)
    csv << fmt::format("{},{},{},{},{:.3f},{},{},{},{}\n", csvField(j.relative),
                       csvField(j.output.string()), j.status == "ok" ? status : j.status,
                       j.exitCode, j.seconds, j.peakKb, csvField(j.reason), csvField(j.kept),
                       csvField(j.expanded));
  std::ofstream html(outRoot / "report.html");
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>gcx translate</title>"
          "<style>body{font-family:sans-serif}td,th{padding:2px 8px;text-align:left}"
          ".failed{color:#b00}</style></head><body>\n<h1>gcx translate</h1>\n<p>"
       << motion::xmlEscape(summary)
       << "</p>\n<table>\n<tr><th>program</th><th>status</th><th>seconds</th><th>peak RSS "
          "(kB)</th><th>reason</th><th>kept</th><th>expanded</th></tr>\n";
  for (const Job& j : jobs)
    html << fmt::format("<tr class=\"{}\"><td>{}</td><td>{}</td><td>{:.3f}</td><td>{}</td>"
                        "<td>{}</td><td>{}</td><td>{}</td></tr>\n",
                        j.status, motion::xmlEscape(j.relative),
                        j.status == "ok" ? status : j.status, j.seconds, j.peakKb,
                        motion::xmlEscape(j.reason), motion::xmlEscape(j.kept),
                        motion::xmlEscape(j.expanded));
  html << "</table>\n</body></html>\n";
}

} // namespace

int runTranslateBatch(const std::string& folder, const TranslateOptions& opt) {
  if (opt.output.empty()) {
    diag::reportUsage("translating a folder needs -o OUTDIR, the folder the translations go to");
    return UsageError;
  }
  const fs::path outRoot(opt.output);
  std::error_code ec;
  fs::create_directories(outRoot, ec);
  if (ec || !fs::is_directory(outRoot)) {
    diag::reportUsage(fmt::format("cannot create the folder {}", opt.output));
    return UsageError;
  }
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) {
    diag::reportUsage("cannot find the gcx executable to run the translations");
    return UsageError;
  }
  std::size_t skipped = 0;
  std::vector<Job> jobs = collect(fs::path(folder), outRoot, opt, skipped);
  markSubprograms(jobs);
  const fs::path logs = outRoot / fmt::format(".gcx-logs-{}", getpid());
  fs::create_directories(logs);

  const auto start = std::chrono::steady_clock::now();
  const bool progress = isatty(STDERR_FILENO);
  std::vector<Running> running;
  std::size_t next = 0, done = 0;
  const std::size_t jobsAtOnce = std::max<std::size_t>(1, opt.batchJobs);
  while (next < jobs.size() || !running.empty()) {
    while (running.size() < jobsAtOnce && next < jobs.size()) {
      const std::size_t i = next++;
      if (!jobs[i].status.empty() || !spawn(jobs[i], i, opt, self, logs, running)) ++done;
    }
    if (running.empty()) continue;
    int status = 0;
    rusage usage{};
    const pid_t pid = wait4(-1, &status, 0, &usage);
    if (pid < 0) break;
    const auto it = std::find_if(running.begin(), running.end(),
                                 [pid](const Running& r) { return r.pid == pid; });
    if (it == running.end()) continue;
    finish(jobs[it->job], status, usage, *it);
    running.erase(it);
    ++done;
    if (progress)
      std::cerr << fmt::format("\r[{}/{}] {}\x1b[K", done, jobs.size(),
                               jobs[std::min(next, jobs.size()) - 1].relative);
  }
  if (progress) std::cerr << "\r\x1b[K";
  fs::remove_all(logs, ec);

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string okStatus = opt.verify ? "verified" : "written";
  std::size_t failed = 0, subprograms = 0;
  long peak = 0;
  for (const Job& j : jobs) {
    failed += j.status == "failed";
    subprograms += j.status == "subprogram";
    peak = std::max(peak, j.peakKb);
  }
  const std::string summary = fmt::format(
      "{} programs to {} with {} jobs in {:.1f} s: {} {}, {} failed{}; {} other files skipped; "
      "peak RSS of one translation {} kB",
      jobs.size(), opt.to, jobsAtOnce, seconds, jobs.size() - failed - subprograms, okStatus,
      failed, subprograms ? fmt::format(", {} subprograms not run on their own", subprograms) : "",
      skipped, peak);
  std::cout << summary << '\n';
  for (const Job& j : jobs)
    if (j.status == "failed") std::cout << fmt::format("failed: {}: {}\n", j.relative, j.reason);
  writeReports(outRoot, jobs, okStatus, summary);
  return failed == 0 ? Ok : ProgramErrors;
}

} // namespace gcx::cli
