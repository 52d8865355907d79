#include "fuzz/entry_points.h"

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "cli/execute.h"
#include "cli/setup_dialects.h"
#include "dialect/dialect.h"
#include "emit/canonical.h"
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
  std::string printed;
  for (const ir::Block& b : first.blocks)
    printed += printBlock(dialect, b);
  out.outputBytes = printed.size();
  diag::Engine again(Bounds::maxErrors);
  const Parsed second = parseText(dialect, printed, sm, again, "printed");
  if (second.failed) {
    out.violation =
        "the printed program does not parse: " + diag::renderText(again.all().front(), sm) +
        "--- printed:\n" + printed;
    return out;
  }
  if (first.blocks.size() != second.blocks.size()) {
    out.violation = fmt::format("{} blocks printed as {}:\n{}", first.blocks.size(),
                                second.blocks.size(), printed);
    return out;
  }
  for (std::size_t i = 0; i < first.blocks.size(); ++i) {
    // compared as JSON values, not text: numbers by value, so `X-0` printed as `X0` is the same
    const nlohmann::json a = ir::toJson(first.blocks[i], false);
    const nlohmann::json b = ir::toJson(second.blocks[i], false);
    if (a != b) {
      out.violation = fmt::format("block {} changes in the round trip:\n  {}\n  {}\nprinted: {}", i,
                                  a.dump(), b.dump(), printBlock(dialect, first.blocks[i]));
      return out;
    }
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
  Outcome (*run)(std::string_view);
};
const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"check_nct", [](std::string_view in) { return checkProgram("nct", in); }},
      {"expand_nct", [](std::string_view in) { return expandCanonical("nct", in); }},
      {"fmt_nct", [](std::string_view in) { return fmtRoundTrip("nct", in); }},
      {"setup_json", &readSetup},
  };
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

Outcome runTarget(std::string_view target, std::string_view input) {
  for (const Target& t : targets())
    if (t.name == target) return t.run(input);
  std::abort(); // a driver or test names a target that does not exist: a harness bug
}

} // namespace gcx::fuzz
