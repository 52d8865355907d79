#include "fuzz/entry_points.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "cli/commands.h"
#include "cli/execute.h"
#include "cli/setup_dialects.h"
#include "dialect/dialect.h"
#include "emit/canonical.h"
#include "front/encoding_output.h"
#include "ir/dump.h"
#include "machine/setup.h"
#include "passes/check/static_checks.h"

namespace gcx::fuzz {

namespace fs = std::filesystem;

namespace {

const Dialect& dialectNamed(const std::string& name) {
  const Dialect* d = findDialect(name);
  if (!d) std::abort(); // a driver names a dialect that does not exist: a harness bug
  return *d;
}

/// Renders every diagnostic (the renderer reads the source line back, so it is exercised too)
/// and names the first error without a location.
std::string renderAll(const diag::Engine& diags, const SourceManager& sm, Outcome& out) {
  out.errors = diags.errorCount();
  std::string unlocated;
  for (const diag::Diagnostic& d : diags.all()) {
    (void)diag::renderText(d, sm);
    if (d.severity == diag::Severity::Error && out.firstError.empty())
      out.firstError = fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code);
    if (d.severity == diag::Severity::Error && !d.range.begin.valid() && unlocated.empty())
      unlocated = fmt::format("error {} without a location: {}", d.code, d.message);
  }
  return unlocated;
}

std::string printBlock(const Dialect& dialect, const ir::Block& b) {
  std::ostringstream out;
  dialect.emitter(out)->block(b);
  return out.str();
}

struct Parsed {
  std::vector<ir::Block> blocks;
  bool failed = false;
};

Parsed parseText(const Dialect& dialect, const std::string& text, SourceManager& sm,
                 diag::Engine& diags, const std::string& name) {
  const FileId file = sm.addBuffer(name, text);
  std::istringstream in(text);
  std::unique_ptr<BlockSource> source = dialect.open(in, file, diags);
  check::StaticChecker checker(dialect.profile(), diags);
  Parsed p;
  ir::Block block;
  while (source->next(block)) {
    checker.block(block);
    p.blocks.push_back(block);
  }
  checker.finish(file, source->failedBlocks() > 0);
  p.failed = diags.hasErrors();
  return p;
}

/// Thrown by the capped sink to stop a program whose motion outgrows the harness's bounds.
struct Capped {};

/// Counts the bytes written and keeps none of them.
class CountingBuffer : public std::streambuf {
public:
  std::size_t bytes = 0;

protected:
  int_type overflow(int_type c) override {
    ++bytes;
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += static_cast<std::size_t>(n);
    return n;
  }
};

/// Passes events on to the emitter until the event or output-size cap is reached.
class CappedSink : public motion::Sink {
public:
  CappedSink(motion::Sink& inner, const CountingBuffer& output) : inner_(inner), output_(output) {}
  void event(const motion::Event& e) override {
    if (++events_ > Bounds::maxEvents || output_.bytes > Bounds::maxOutputBytes) throw Capped{};
    inner_.event(e);
  }
  void finish() override { inner_.finish(); }

private:
  motion::Sink& inner_;
  const CountingBuffer& output_;
  std::size_t events_ = 0;
};

/// The private folder of this process's expansion runs, removed at exit.
const fs::path& workFolder() {
  static const fs::path dir = [] {
    std::string tmpl = (fs::temp_directory_path() / "gcx-fuzz-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) std::abort();
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(workFolder(), ec);
    });
    return fs::path(tmpl);
  }();
  return dir;
}

/// Empties the work folder and writes the input's files into it; returns the main program.
fs::path writeProgramFiles(const Dialect& dialect, std::string_view input) {
  const fs::path& dir = workFolder();
  for (const auto& entry : fs::directory_iterator(dir))
    fs::remove_all(entry.path());
  const std::string ext = dialect.extensions.front();
  constexpr std::string_view separator = "\n@@\n";
  constexpr int maxFiles = 4;
  for (int i = 0; i < maxFiles; ++i) {
    const std::size_t cut = i + 1 < maxFiles ? input.find(separator) : std::string_view::npos;
    const std::string name = i == 0 ? "O0001" : fmt::format("O{}", 9000 + i);
    std::ofstream(dir / (name + ext), std::ios::binary) << input.substr(0, cut);
    if (cut == std::string_view::npos) break;
    input.remove_prefix(cut + separator.size());
  }
  return dir / ("O0001" + ext);
}

} // namespace

Outcome checkProgram(const std::string& dialect, std::string_view input) {
  SourceManager sm;
  diag::Engine diags(Bounds::maxErrors);
  Outcome out;
  parseText(dialectNamed(dialect), std::string(input), sm, diags, "O0001");
  out.violation = renderAll(diags, sm, out);
  return out;
}

Outcome expandCanonical(const std::string& dialect, std::string_view input) {
  const fs::path program = writeProgramFiles(dialectNamed(dialect), input);
  cli::CommonOptions opt;
  opt.dialect = dialect;
  opt.maxErrors = Bounds::maxErrors;
  opt.maxJumps = Bounds::maxJumps;
  opt.maxBlocks = Bounds::maxBlocks;
  opt.maxMoves = Bounds::maxMoves;
  cli::Session session(opt);
  Outcome out;
  if (!session.open(program.string())) {
    out.violation = "the harness could not open its own program file";
    return out;
  }
  CountingBuffer output, printed;
  std::ostream outputStream(&output), printStream(&printed);
  emit::CanonicalEmitter emitter(outputStream);
  CappedSink sink(emitter, output);
  try {
    cli::executeProgram(session, opt, machine::Setup{}, sink, printStream);
  } catch (const Capped&) {
    out.capped = true;
  }
  out.outputBytes = output.bytes;
  const std::string unlocated = renderAll(session.diags(), session.sources(), out);
  if (!out.capped) out.violation = unlocated; // a capped run may stop mid-way; no verdict then
  return out;
}

Outcome fmtRoundTrip(const std::string& dialectName, std::string_view input) {
  const Dialect& dialect = dialectNamed(dialectName);
  Outcome out;
  SourceManager sm;
  diag::Engine diags(Bounds::maxErrors);
  const Parsed first = parseText(dialect, std::string(input), sm, diags, "O0001");
  out.violation = renderAll(diags, sm, out);
  if (first.failed || !out.violation.empty()) return out;
  // printed as `gcx fmt` prints: one emitter for the whole program, in the dialect's encoding
  std::ostringstream text;
  front::EncodingOutput encoded(text, dialect.textEncoding());
  std::ostream utf8(&encoded);
  const std::unique_ptr<emit::ProgramEmitter> emitter = dialect.emitter(utf8);
  emitter->beginProgram({});
  for (const ir::Block& b : first.blocks)
    emitter->block(b);
  emitter->endProgram();
  if (!encoded.finish()) return out; // a character the encoding lacks: gcx fmt refuses it
  const std::string printed = text.str();
  out.outputBytes = printed.size();
  diag::Engine again(Bounds::maxErrors);
  Parsed second = parseText(dialect, printed, sm, again, "printed");
  // a dialect whose files are units (WL4 `%name ... %`) prints the unit lines a program
  // without them is read as having (`%MAIN` before a file's first block, `%` after its last)
  for (const ir::BlockKind unitLine : {ir::BlockKind::ProgramStart, ir::BlockKind::ProgramEnd}) {
    const auto is = [unitLine](const ir::Block& b) { return b.kind == unitLine; };
    if (std::none_of(first.blocks.begin(), first.blocks.end(), is))
      std::erase_if(second.blocks, is);
  }
  // a block of nothing (FMS-3000's tolerated bare `N`, fms3000.md §6.3) prints as a blank line
  const auto nothing = [](const ir::Block& b) {
    return b.kind == ir::BlockKind::Normal && b.empty() && b.comments.empty() && !b.skipLevel;
  };
  std::vector<ir::Block> kept = first.blocks;
  std::erase_if(kept, nothing);
  std::erase_if(second.blocks, nothing);
  if (second.failed) {
    out.violation =
        "the printed program does not parse: " + diag::renderText(again.all().front(), sm) +
        "--- printed:\n" + printed;
    return out;
  }
  if (kept.size() != second.blocks.size()) {
    out.violation =
        fmt::format("{} blocks printed as {}:\n{}", kept.size(), second.blocks.size(), printed);
    return out;
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    // compared as JSON values, not text: numbers by value, so `X-0` printed as `X0` is the same
    const nlohmann::json a = ir::toJson(kept[i], false);
    const nlohmann::json b = ir::toJson(second.blocks[i], false);
    if (a != b) {
      out.violation = fmt::format("block {} changes in the round trip:\n  {}\n  {}\nprinted: {}", i,
                                  a.dump(), b.dump(), printBlock(dialect, kept[i]));
      return out;
    }
  }
  return out;
}

Outcome translateToEveryTarget(const std::string& dialect, std::string_view input) {
  const fs::path program = writeProgramFiles(dialectNamed(dialect), input);
  Outcome out;
  for (const std::string to : {"nct", "fms3000", "wl4", "canonical", "ngc"}) {
    if (to == dialect) continue;
    cli::TranslateOptions opt;
    opt.common.dialect = dialect;
    opt.common.maxErrors = Bounds::maxErrors;
    opt.common.maxJumps = Bounds::maxJumps;
    opt.common.maxBlocks = Bounds::maxBlocks;
    opt.common.maxMoves = Bounds::maxMoves;
    opt.common.maxOutput = Bounds::maxOutputBytes;
    opt.common.jobs = 1;
    opt.to = to;
    const Dialect* target = findDialect(to);
    opt.output =
        (workFolder() / ("out-" + to + (target ? target->extensions.front() : ".ngc"))).string();
    // no LinuxCNC: gcx reads the canonical output itself, so every run is the same everywhere
    opt.rs274 = (workFolder() / "no-rs274").string();
    // what translate says goes to a buffer: the verdict is in its text
    std::ostringstream said;
    std::streambuf* const err = std::cerr.rdbuf(said.rdbuf());
    std::streambuf* const log = std::clog.rdbuf(said.rdbuf());
    const int rc = cli::runTranslate(program.string(), opt);
    std::cerr.rdbuf(err);
    std::clog.rdbuf(log);
    out.errors += rc != 0;
    out.outputBytes += said.str().size();
    // what shops rely on: a translation is written only when it is proven; one that fails
    // (the source does not read, the target cannot say it, or the proof finds a difference)
    // leaves no file
    const bool written = fs::exists(opt.output);
    if (written != (rc == 0)) {
      out.violation = fmt::format("the translation to {} exited {} and {} a file:\n{}", to, rc,
                                  written ? "wrote" : "did not write", said.str());
      return out;
    }
    if (rc != 0 && out.firstError.empty())
      out.firstError = said.str().find("does not move the tool like") != std::string::npos
                           ? "differs: " + to
                           : "refused: " + to;
  }
  return out;
}

Outcome readSetup(std::string_view input) {
  SourceManager sm;
  diag::Engine diags(Bounds::maxErrors);
  const std::string text(input);
  const FileId file = sm.addBuffer("setup.json", text);
  Outcome out;
  (void)machine::parseSetup(text, file, diags, cli::setupDialects("nct"));
  out.violation = renderAll(diags, sm, out);
  return out;
}

namespace {
struct Target {
  std::string name;
  std::string seedExtension; // the files that seed it
  std::function<Outcome(std::string_view)> run;
};
// Three targets per dialect of the registry (a dialect added later is fuzzed without an edit
// here), the translation of NCT programs to every target, and the setup reader.
const std::vector<Target>& targets() {
  static const std::vector<Target> all = [] {
    std::vector<Target> v;
    for (const Dialect& d : dialects()) {
      const std::string name = d.name, ext = d.extensions.front();
      v.push_back({"check_" + name, ext, [name](auto in) { return checkProgram(name, in); }});
      v.push_back({"expand_" + name, ext, [name](auto in) { return expandCanonical(name, in); }});
      v.push_back({"fmt_" + name, ext, [name](auto in) { return fmtRoundTrip(name, in); }});
    }
    v.push_back(
        {"translate_nct", ".nct", [](auto in) { return translateToEveryTarget("nct", in); }});
    v.push_back({"setup_json", ".json", &readSetup});
    return v;
  }();
  return all;
}
} // namespace

const std::vector<std::string>& targetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Target& t : targets())
      v.push_back(t.name);
    return v;
  }();
  return names;
}

const std::string& seedExtension(std::string_view target) {
  for (const Target& t : targets())
    if (t.name == target) return t.seedExtension;
  std::abort();
}

Outcome runTarget(std::string_view target, std::string_view input) {
  for (const Target& t : targets())
    if (t.name == target) return t.run(input);
  std::abort(); // a driver or test names a target that does not exist: a harness bug
}

} // namespace gcx::fuzz
