#include "cli/execute.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <unistd.h>

#include "cli/block_pipeline.h"
#include "cli/setup_dialects.h"
#include "diag/codes.h"
#include "machine/interpreter.h"
#include "motion/program_units.h"
#include "motion/transform_frame.h"
#include "motion/work_frame.h"
#include "passes/check/static_checks.h"
#include "passes/macro/expander.h"

namespace gcx::cli {

namespace fs = std::filesystem;

PrintOutput::PrintOutput(const CommonOptions& opt, bool outputOnStdout)
    : path_(opt.printFile), console_(outputOnStdout ? &std::cerr : &std::cout) {}

bool PrintOutput::ok() {
  if (path_.empty() || file_.isOpen()) return true;
  if (file_.open(path_)) return true;
  reportUsage(fmt::format("{}: cannot write: {}", path_, file_.error()));
  return false;
}

bool PrintOutput::finish() {
  if (path_.empty()) return true;
  fileStream_.flush();
  if (file_.close()) return true;
  reportUsage(fmt::format("{}: cannot write: {}", path_, file_.error()));
  return false;
}

bool copyToStdout(const std::string& path) {
  std::cout.flush();
  std::fflush(stdout);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    reportUsage(fmt::format("{}: cannot read back: {}", path, std::strerror(errno)));
    return false;
  }
  std::vector<char> buf(1 << 16);
  std::string error;
  for (;;) {
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n < 0) error = std::strerror(errno);
      break;
    }
    for (ssize_t done = 0; done < n && error.empty();) {
      const ssize_t w =
          ::write(STDOUT_FILENO, buf.data() + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0)
        error = std::strerror(w < 0 ? errno : EIO);
      else
        done += w;
    }
    if (!error.empty()) break;
  }
  ::close(fd);
  if (error.empty()) return true;
  reportUsage(fmt::format("standard output: cannot write: {}", error));
  return false;
}

int openWithSetup(Session& s, const std::string& file, const std::string& setupPath,
                  machine::Setup& setup) {
  if (!s.open(file)) return UsageError;
  if (setupPath.empty()) return Ok;
  auto loaded =
      machine::loadSetup(setupPath, s.sources(), s.diags(), setupDialects(s.dialect().name));
  if (!loaded) {
    const diag::Diagnostic* last = s.diags().lastError();
    const bool unreadable = last && last->code == diag::code::SetupCannotRead;
    s.flushDiagnostics();
    return unreadable ? UsageError : ProgramErrors; // a file that cannot be read is I/O
  }
  setup = std::move(*loaded);
  return Ok;
}

namespace {
std::uint64_t programSize(Session& s) {
  std::error_code ec;
  const std::uintmax_t n = std::filesystem::file_size(s.path(), ec);
  return ec ? 0 : static_cast<std::uint64_t>(n);
}
} // namespace

macro::Limits expansionLimits(const CommonOptions& opt) {
  macro::Limits limits;
  limits.maxJumps = opt.maxJumps;
  limits.maxBlocks = opt.maxBlocks;
  limits.maxDepth = opt.maxDepth;
  return limits;
}

std::uint64_t outputBudgetFor(const CommonOptions& opt, std::uint64_t programBytes) {
  if (opt.maxOutput != 0) return opt.maxOutput;
  constexpr std::uint64_t floor = 256ULL << 20, perProgramByte = 32;
  return std::max(floor, programBytes * perProgramByte);
}

void limitMachine(machine::Interpreter& interp, const CommonOptions& opt,
                  std::uint64_t programBytes) {
  interp.setMaxMoves(opt.maxMoves);
  setOutputBudget(outputBudgetFor(opt, programBytes));
  interp.setStopCheck([]() -> std::optional<std::string> {
    if (!outputBudgetExceeded()) return std::nullopt;
    return fmt::format("the output exceeded --max-output {} bytes; raise it with --max-output N",
                       outputBudget());
  });
}

namespace {
// What the interpreter writes to: the output sink itself, or the chain of adapters in front of
// it that re-express each event in the work or the program frame, asking the interpreter for
// the work origin and the transformations in force at each event.
class FramedSink {
public:
  /// machineOut: a sink that gets the machine frame besides (statistics beside a framed trace).
  FramedSink(motion::Sink& out, Frame frame, motion::Sink* machineOut)
      : out_(out), frame_(frame), units_(out),
        transforms_(units_, [this] { return interp_->transforms().matrix(); }),
        work_(frame == Frame::Work ? out : static_cast<motion::Sink&>(transforms_),
              [this] { return interp_->workOrigin(); }) {
    if (!machineOut) return;
    both_.add(framed());
    both_.add(*machineOut);
  }
  motion::Sink& sink() { return both_.empty() ? framed() : both_; }
  void bind(const machine::Interpreter& interp) { interp_ = &interp; }

private:
  motion::Sink& out_;
  Frame frame_;
  motion::ProgramUnits units_;
  motion::TransformFrame transforms_;
  motion::WorkFrame work_;
  Tee both_;
  const machine::Interpreter* interp_ = nullptr;

  motion::Sink& framed() { return frame_ == Frame::Machine ? out_ : work_; }
};

} // namespace

Frame frameNamed(const std::string& name) {
  return name == "work" ? Frame::Work : name == "program" ? Frame::Program : Frame::Machine;
}

namespace {
// Programs with macro statements, variables or calls run through the expansion pass, which
// loads them whole; everything else streams block by block.
bool expandProgram(Session& s, const CommonOptions& opt, const machine::Setup& setup,
                   motion::Sink& out, std::ostream& printOut, Frame frame, motion::Sink* machineOut,
                   std::function<void(const motion::Provenance&)> onBlock) {
  macro::ProgramLibrary library(s.dialect(), s.sources(), s.diags(), opt.libraryDirs);
  const macro::LoadedProgram* main = library.load(s.path());
  if (!main) return false;
  FramedSink framed(out, frame, machineOut);
  motion::Sink& sink = framed.sink();
  machine::Interpreter interp(s.dialect().profile(), setup, sink, s.diags());
  framed.bind(interp);
  limitMachine(interp, opt, programSize(s));
  interp.setKeepCompensation(opt.keepCompensation);
  interp.setBlockObserver(std::move(onBlock));
  macro::Expander expander(library, interp, s.diags(), expansionLimits(opt));
  expander.setPrintOutput(&printOut);
  if (opt.fanucVacantOrder) expander.setVacantOrder(macro::VacantOrder::Fanuc);
  if (!expander.run(*main)) return false;
  sink.finish();
  return !s.diags().hasErrors();
}
} // namespace

bool executeProgram(Session& s, const CommonOptions& opt, const machine::Setup& setup,
                    motion::Sink& out, std::ostream& printOut, Frame frame,
                    motion::Sink* machineOut,
                    std::function<void(const motion::Provenance&)> onBlock) {
  // The scan for what needs the expansion pass reads the whole file before any block runs. With
  // two jobs each thread scans half of it; the streaming stages are built first, as they report
  // and write nothing, and dropped if the scan finds something.
  std::error_code noSize;
  const std::uint64_t size = std::filesystem::file_size(s.path(), noSize);
  const std::uint64_t half = noSize ? UINT64_MAX : size / 2;
  const StreamGate noExpansion{
      [&] { return !macro::mayNeedExpansion(s.path(), s.dialect().profile(), 0, half); },
      [&] { return !macro::mayNeedExpansion(s.path(), s.dialect().profile(), half); }};
  // With two jobs the reading thread checks every block: the checker, which it writes, must not
  // share a cache line with the interpreter and sinks this thread writes beside it.
  struct alignas(128) OwnLines {
    check::StaticChecker checker;
  } isolated{check::StaticChecker(s.dialect().profile(), s.diags())};
  check::StaticChecker& checker = isolated.checker;
  FramedSink framed(out, frame, machineOut);
  motion::Sink& sink = framed.sink();
  machine::Interpreter interp(s.dialect().profile(), setup, sink, s.diags());
  framed.bind(interp);
  limitMachine(interp, opt, programSize(s));
  interp.setKeepCompensation(opt.keepCompensation);
  interp.setBlockObserver(onBlock);
  const StreamStages stages{s.source(), checker, interp, s.diags()};
  if (!runBlocks(stages, opt.jobs, noExpansion))
    return expandProgram(s, opt, setup, out, printOut, frame, machineOut, std::move(onBlock));
  if (s.diags().hasErrors()) return false;
  if (!interp.ended()) {
    // drain the rest for static errors (GOTO targets, loops) only when the program ran out
    checker.finish(s.file(), s.source().failedBlocks() > 0);
    if (s.diags().hasErrors()) return false;
    interp.endOfFile();
  }
  sink.finish();
  return !s.diags().hasErrors();
}

motion::Vec3 initialWorkOrigin(Session& s, const machine::Setup& setup) {
  struct Discard : motion::Sink {
    void event(const motion::Event&) override {}
  } discard;
  return machine::Interpreter(s.dialect().profile(), setup, discard, s.diags()).workOrigin();
}

AtomicOutput::AtomicOutput(std::string path, front::Encoding encoding) : path_(std::move(path)) {
  if (encoding != front::Encoding::Utf8) {
    encoded_ = std::make_unique<front::EncodingOutput>(out_, encoding);
    encodedStream_ = std::make_unique<std::ostream>(encoded_.get());
  }
  std::error_code ec;
  // a device or pipe (/dev/null, /dev/full) is written directly: it cannot be replaced
  direct_ = !path_.empty() && fs::exists(path_, ec) && !fs::is_regular_file(path_, ec) &&
            !fs::is_directory(path_, ec);
  tmp_ = direct_ ? path_
         : path_.empty()
             ? (fs::temp_directory_path() / fmt::format("gcx-{}.tmp", ::getpid())).string()
             : path_ + ".gcx-tmp";
  file_.open(tmp_);
}

bool AtomicOutput::ok() {
  if (file_.isOpen()) return true;
  reportUsage(fmt::format("{}: cannot write: {}", path_.empty() ? tmp_ : path_, file_.error()));
  return false;
}

void AtomicOutput::discard() {
  std::error_code ec;
  if (!direct_) fs::remove(tmp_, ec);
}

AtomicOutput::~AtomicOutput() {
  if (!done_) {
    file_.close();
    discard();
  }
}

bool AtomicOutput::commit() {
  done_ = true;
  if (encoded_ && !encoded_->finish()) {
    reportUsage(fmt::format("{}: cannot write: {}", path_.empty() ? "standard output" : path_,
                            encoded_->error()));
    file_.close();
    discard();
    return false;
  }
  out_.flush();
  if (!file_.close()) {
    reportUsage(fmt::format("{}: cannot write: {}", path_.empty() ? "standard output" : path_,
                            file_.error()));
    discard();
    return false;
  }
  if (direct_) return true;
  if (path_.empty()) {
    const bool copied = copyToStdout(tmp_);
    discard();
    return copied;
  }
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) {
    reportUsage(fmt::format("{}: cannot write: {}", path_, ec.message()));
    discard();
    return false;
  }
  return true;
}

} // namespace gcx::cli
