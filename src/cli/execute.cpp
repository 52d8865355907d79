#include "cli/execute.h"

#include <filesystem>
#include <fmt/format.h>
#include <iostream>
#include <unistd.h>

#include "machine/interpreter.h"
#include "passes/check/static_checks.h"

namespace gcx::cli {

namespace fs = std::filesystem;

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

bool executeProgram(Session& s, const machine::Setup& setup, motion::Sink& sink) {
  check::StaticChecker checker(s.dialect().profile(), s.diags());
  machine::Interpreter interp(s.dialect().profile(), setup, sink, s.diags());
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
