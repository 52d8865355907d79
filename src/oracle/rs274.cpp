#include "oracle/rs274.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace gcx::oracle {

namespace fs = std::filesystem;

namespace {

constexpr double kMmPerInch = 25.4;

bool isExecutableFile(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
}

bool writeFile(const fs::path& p, std::string_view text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  return static_cast<bool>(out);
}

std::string readWhole(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    pos = nl + 1;
  }
  return lines;
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

/// Removes the owned temporary directory unless asked to keep it.
struct WorkDir {
  fs::path path;
  bool keep = false;
  ~WorkDir() {
    if (!path.empty() && !keep) {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  }
};

} // namespace

std::string Rs274Result::summary() const {
  std::string s;
  if (!error.empty())
    s = "could not run rs274: " + error;
  else if (timedOut)
    s = "rs274 timed out (killed)";
  else if (signal != 0)
    s = fmt::format("rs274 killed by signal {}", signal);
  else
    s = fmt::format("rs274 exit code {}", exitCode);
  std::string err = stderrText;
  // rs274 prints a bare "executing" banner on stderr for every run; it says nothing.
  for (std::size_t p; (p = err.find("executing")) != std::string::npos;)
    err.erase(p, 9);
  while (!err.empty() && (err.back() == '\n' || isSpace(err.back())))
    err.pop_back();
  while (!err.empty() && (err.front() == '\n' || isSpace(err.front())))
    err.erase(0, 1);
  if (!err.empty()) s += ": " + err;
  return s;
}

std::optional<std::string> findRs274(const std::string& executable) {
  if (executable.empty()) return std::nullopt;
  if (executable.find('/') != std::string::npos)
    return isExecutableFile(executable) ? std::optional<std::string>(executable) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t pos = 0;
  while (pos <= dirs.size()) {
    std::size_t colon = dirs.find(':', pos);
    if (colon == std::string::npos) colon = dirs.size();
    const fs::path dir = colon > pos ? fs::path(dirs.substr(pos, colon - pos)) : fs::path(".");
    const std::string candidate = (dir / executable).string();
    if (isExecutableFile(candidate)) return candidate;
    pos = colon + 1;
  }
  return std::nullopt;
}

bool rs274Available() {
  static const bool available = findRs274().has_value();
  return available;
}

std::string numberLines(std::string_view program) {
  std::string out;
  out.reserve(program.size() + program.size() / 4 + 16);
  std::size_t pos = 0;
  std::size_t lineno = 0;
  while (pos < program.size()) {
    std::size_t nl = program.find('\n', pos);
    if (nl == std::string_view::npos) nl = program.size();
    std::string_view line = program.substr(pos, nl - pos);
    pos = nl + 1;
    ++lineno;

    std::size_t p = 0;
    while (p < line.size() && isSpace(line[p]))
      ++p;
    if (p < line.size() && line[p] == '%') { // program demarcation: rs274 rejects "N1 %"
      out.append(line);
      out.push_back('\n');
      continue;
    }
    std::string head;
    if (p < line.size() && line[p] == '/') { // block delete stays first
      head = "/";
      ++p;
      if (p < line.size() && isDigit(line[p])) head.push_back(line[p++]);
      while (p < line.size() && isSpace(line[p]))
        ++p;
    }
    if (p < line.size() && (line[p] == 'N' || line[p] == 'n')) { // replace an existing N word
      std::size_t q = p + 1;
      while (q < line.size() && isSpace(line[q]))
        ++q;
      if (q < line.size() && isDigit(line[q])) {
        while (q < line.size() && (isDigit(line[q]) || isSpace(line[q])))
          ++q;
        p = q;
      }
    }
    out += head;
    out += fmt::format("N{} ", lineno);
    out.append(line.substr(p));
    out.push_back('\n');
  }
  return out;
}

std::string toolTableText(const std::vector<OracleTool>& tools) {
  std::string s;
  for (const OracleTool& t : tools)
    s += fmt::format("T{0} P{0} D{1:.10f} Z{2:.10f} ;gcx oracle tool: D {3} mm, Z {4} mm\n",
                     t.number, t.diameterMm / kMmPerInch, t.lengthMm / kMmPerInch, t.diameterMm,
                     t.lengthMm);
  return s;
}

std::string parameterFileText(const std::vector<OracleWorkOffset>& offsets) {
  std::map<int, double> params;
  params[5220] = 1.0; // G54 active at start
  for (const OracleWorkOffset& o : offsets) {
    if (o.index < 1 || o.index > 9) continue;
    const int base = 5201 + 20 * o.index; // G54: 5221..5229 (x y z a b c u v w), 5230 = R
    params[base + 0] = o.offsetMm.x() / kMmPerInch;
    params[base + 1] = o.offsetMm.y() / kMmPerInch;
    params[base + 2] = o.offsetMm.z() / kMmPerInch;
    params[base + 9] = o.rotationDeg;
  }
  std::string s;
  for (const auto& [num, value] : params)
    s += fmt::format("{}\t{:.12f}\n", num, value);
  return s;
}

Rs274Result Rs274::run(std::string_view program) const {
  Rs274Result r;
  const std::optional<std::string> exe = findRs274(options_.executable);
  if (!exe) {
    r.error = fmt::format("'{}' not found or not executable", options_.executable);
    return r;
  }

  // A private directory: program, parameter file, tool table, HOME, outputs.
  std::error_code ec;
  fs::path tmpBase = fs::temp_directory_path(ec);
  if (ec) tmpBase = "/tmp";
  std::string tmpl = (tmpBase / "gcx-rs274-XXXXXX").string();
  std::vector<char> buf(tmpl.begin(), tmpl.end());
  buf.push_back('\0');
  if (::mkdtemp(buf.data()) == nullptr) {
    r.error = fmt::format("mkdtemp({}): {}", tmpl, std::strerror(errno));
    return r;
  }
  WorkDir dir{fs::path(buf.data()), options_.keepWorkDir};
  if (options_.keepWorkDir) r.workDir = dir.path.string();

  const fs::path ngc = dir.path / "in.ngc", canon = dir.path / "out.canon",
                 var = dir.path / "p.var", tbl = dir.path / "tool.tbl",
                 outTxt = dir.path / "stdout.txt", errTxt = dir.path / "stderr.txt";
  std::string text = options_.numberLines ? numberLines(program) : std::string(program);
  if (!text.empty() && text.back() != '\n') text.push_back('\n');
  if (!writeFile(ngc, text) || !writeFile(var, parameterFileText(options_.workOffsets)) ||
      !writeFile(tbl, toolTableText(options_.tools))) {
    r.error = "cannot write into " + dir.path.string();
    return r;
  }

  // Everything the child needs is prepared before fork: after fork only async-signal-safe
  // calls are made (the test binary may be multi-threaded).
  std::vector<std::string> args = {*exe, "-g",         "-t",         tbl.string(),
                                   "-v", var.string(), ngc.string(), canon.string()};
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e) {
    std::string_view kv(*e);
    if (kv.starts_with("HOME=") || kv.starts_with("LC_ALL=") || kv.starts_with("LANG=") ||
        kv.starts_with("LC_NUMERIC="))
      continue;
    env.emplace_back(kv);
  }
  env.push_back("HOME=" + dir.path.string());
  env.push_back("LC_ALL=C"); // %.4f with a decimal point whatever the caller's locale
  std::vector<char*> argv, envp;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : env)
    envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string dirStr = dir.path.string(), outStr = outTxt.string(), errStr = errTxt.string();

  const pid_t pid = ::fork();
  if (pid < 0) {
    r.error = fmt::format("fork: {}", std::strerror(errno));
    return r;
  }
  if (pid == 0) {
    ::setpgid(0, 0); // own process group, so a timeout kill reaches anything it started
    if (::chdir(dirStr.c_str()) != 0) ::_exit(126);
    int in = ::open("/dev/null", O_RDONLY);
    int out = ::open(outStr.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    int err = ::open(errStr.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || out < 0 || err < 0) ::_exit(126);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid); // also in the parent: no race with an early kill

  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(options_.timeoutSeconds));
  int status = 0;
  auto sleep = std::chrono::microseconds(500);
  for (;;) {
    pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      r.error = fmt::format("waitpid: {}", std::strerror(errno));
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return r;
    }
    if (Clock::now() >= deadline) {
      r.timedOut = true;
      ::kill(-pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(sleep);
    sleep = std::min(sleep * 2, std::chrono::microseconds(20000));
  }
  if (WIFEXITED(status)) {
    r.exitCode = WEXITSTATUS(status);
    if (r.exitCode == 127 && !r.timedOut) r.error = "exec of " + *exe + " failed";
  } else if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  }
  r.stderrText = readWhole(errTxt);
  r.stdoutText = readWhole(outTxt);
  r.canonLines = splitLines(readWhole(canon));
  return r;
}

} // namespace gcx::oracle
