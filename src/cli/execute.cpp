#include "cli/execute.h"

#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <unistd.h>

#include "machine/interpreter.h"
#include "motion/work_frame.h"
#include "passes/check/static_checks.h"
#include "passes/macro/expander.h"

namespace gcx::cli {

namespace fs = std::filesystem;

std::ostream& printStream(const CommonOptions& opt, bool outputOnStdout) {
  static std::ofstream file;
  if (!opt.printFile.empty()) {
    if (!file.is_open()) file.open(opt.printFile, std::ios::binary | std::ios::trunc);
    return file;
  }
  return outputOnStdout ? std::cerr : std::cout;
}

int openWithSetup(Session& s, const std::string& file, const std::string& setupPath,
                  machine::Setup& setup) {
  if (!s.open(file)) return UsageError;
  if (setupPath.empty()) return Ok;
  auto loaded = machine::loadSetup(setupPath, s.sources(), s.diags());
  if (!loaded) {
    s.flushDiagnostics();
    return ProgramErrors;
  }
  setup = std::move(*loaded);
  return Ok;
}

namespace {
// What the interpreter writes to: the output sink itself, or its work-frame view, which asks the
// interpreter for the work origin of each event.
class FramedSink {
public:
  FramedSink(motion::Sink& out, Frame frame)
      : out_(out), frame_(frame), work_(out, [this] { return interp_->workOrigin(); }) {}
  motion::Sink& sink() { return frame_ == Frame::Work ? static_cast<motion::Sink&>(work_) : out_; }
  void bind(const machine::Interpreter& interp) { interp_ = &interp; }

private:
  motion::Sink& out_;
  Frame frame_;
  motion::WorkFrame work_;
  const machine::Interpreter* interp_ = nullptr;
};

// Programs with macro statements, variables or calls run through the expansion pass, which
// loads them whole; everything else streams block by block.
bool expandProgram(Session& s, const CommonOptions& opt, const machine::Setup& setup,
                   motion::Sink& out, std::ostream& printOut, Frame frame) {
  macro::ProgramLibrary library(s.dialect(), s.sources(), s.diags(), opt.libraryDirs);
  const macro::LoadedProgram* main = library.load(s.path());
  if (!main) return false;
  FramedSink framed(out, frame);
  motion::Sink& sink = framed.sink();
  machine::Interpreter interp(s.dialect().profile(), setup, sink, s.diags());
  framed.bind(interp);
  macro::SystemVariables system(interp, s.diags());
  macro::Limits limits;
  limits.maxJumps = opt.maxJumps;
  limits.maxBlocks = opt.maxBlocks;
  limits.maxDepth = opt.maxDepth;
  macro::Expander expander(library, interp, system, s.diags(), limits);
  expander.setPrintOutput(&printOut);
  if (opt.fanucVacantOrder) expander.setVacantOrder(macro::VacantOrder::Fanuc);
  if (!expander.run(*main)) return false;
  sink.finish();
  return !s.diags().hasErrors();
}
} // namespace

bool executeProgram(Session& s, const CommonOptions& opt, const machine::Setup& setup,
                    motion::Sink& out, std::ostream& printOut, Frame frame) {
  if (macro::mayNeedExpansion(s.path())) return expandProgram(s, opt, setup, out, printOut, frame);
  check::StaticChecker checker(s.dialect().profile(), s.diags());
  FramedSink framed(out, frame);
  motion::Sink& sink = framed.sink();
  machine::Interpreter interp(s.dialect().profile(), setup, sink, s.diags());
  framed.bind(interp);
  ir::Block block;
  bool ok = true;
  while (ok && s.source().next(block)) {
    const std::size_t before = s.diags().errorCount();
    checker.block(block);
    if (s.diags().errorCount() != before) break;
    motion::Provenance from;
    from.at = block.range.begin;
    if (!interp.execute(block, from)) break;
  }
  if (s.diags().hasErrors()) return false;
  if (!interp.ended()) {
    // drain the rest for static errors (GOTO targets, loops) only when the program ran out
    checker.finish(s.file(), s.source().failedBlocks() > 0);
    if (s.diags().hasErrors()) return false;
    interp.finish();
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

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  tmp_ = path_.empty()
             ? (fs::temp_directory_path() / fmt::format("gcx-{}.tmp", ::getpid())).string()
             : path_ + ".gcx-tmp";
  out_.open(tmp_, std::ios::binary | std::ios::trunc);
}

AtomicOutput::~AtomicOutput() {
  if (!done_) {
    out_.close();
    std::error_code ec;
    fs::remove(tmp_, ec);
  }
}

bool AtomicOutput::commit() {
  out_.close();
  done_ = true;
  std::error_code ec;
  if (!out_) {
    reportUsage(fmt::format("{}: cannot write", tmp_));
    fs::remove(tmp_, ec);
    return false;
  }
  if (path_.empty()) {
    std::ifstream back(tmp_, std::ios::binary);
    std::cout << back.rdbuf();
    std::cout.flush();
    fs::remove(tmp_, ec);
    return true;
  }
  fs::rename(tmp_, path_, ec);
  if (ec) {
    reportUsage(fmt::format("{}: cannot write: {}", path_, ec.message()));
    fs::remove(tmp_, ec);
    return false;
  }
  return true;
}

} // namespace gcx::cli
