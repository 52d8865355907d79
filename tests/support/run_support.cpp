#include "support/run_support.h"

#include <cmath>
#include <fmt/format.h>
#include <sstream>

#include "dialects/nct/profile.h"
#include "dialects/nct/reader.h"
#include "machine/interpreter.h"
#include "motion/geometry.h"
#include "passes/check/static_checks.h"

namespace gcx::test {

namespace {
class Collect : public motion::Sink {
public:
  std::vector<motion::Event>& out;
  motion::Sink* also;
  Collect(std::vector<motion::Event>& o, motion::Sink* a) : out(o), also(a) {}
  void event(const motion::Event& e) override {
    out.push_back(e);
    if (also) also->event(e);
  }
  void finish() override {
    if (also) also->finish();
  }
};
} // namespace

std::string n4(double v) {
  double r = std::round(v * 1e4) / 1e4;
  if (r == 0) r = 0;
  std::string s = fmt::format("{:.4f}", r);
  while (s.back() == '0')
    s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string describe(const motion::Event& e) {
  auto p = [&](const motion::Vec3& v) {
    std::string s = n4(v.x()) + "," + n4(v.y()) + "," + n4(v.z());
    for (int i = 0; i < 6; ++i) // extra axes that are not zero or that moved
      if (e.extraEnd[i] != 0 || e.extraStart[i] != e.extraEnd[i])
        s += std::string(" ") + motion::kExtraAxisNames[i] + n4(e.extraEnd[i]);
    return s;
  };
  switch (e.kind) {
  case motion::Kind::Rapid:
    return "R " + p(e.end);
  case motion::Kind::Feed:
    return "L " + p(e.end) + " F" + n4(e.feed);
  case motion::Kind::Arc: {
    const motion::ArcGeometry g(e);
    const motion::PlaneAxes ax = motion::axesOf(e.plane);
    std::string r = n4(g.startRadius());
    if (n4(g.endRadius()) != r) r += "->" + n4(g.endRadius());
    return fmt::format("{} {} C{},{} r{} θ{}", e.clockwise ? "CW" : "CCW", p(e.end),
                       n4(e.center[ax.first]), n4(e.center[ax.second]), r,
                       n4(g.sweep() * 180 / M_PI));
  }
  case motion::Kind::Dwell:
    return "DW " + n4(e.value) + (e.perRevolution ? "rev" : "s");
  case motion::Kind::Spindle:
    return "EV S" + n4(e.value) + (e.direction > 0 ? " M3" : e.direction < 0 ? " M4" : " M5");
  case motion::Kind::SpindleOrient:
    return "EV M19";
  case motion::Kind::OverrideLock:
    return e.value != 0 ? "EV G63" : "EV G64";
  case motion::Kind::RadiusComp:
    if (e.value == 0) return "EV G40";
    return std::string(e.value > 0 ? "EV G41 r" : "EV G42 r").append(n4(e.startRadius));
  case motion::Kind::ToolChange:
    return "EV T" + n4(e.value) + " M6";
  case motion::Kind::Coolant:
    return "EV M" + n4(e.value);
  case motion::Kind::Stop:
    return e.optional ? "EV M1" : "EV M0";
  case motion::Kind::End:
    return "END";
  case motion::Kind::Message:
    return "MSG " + e.text;
  case motion::Kind::PlaneChange: {
    static const char* const names[] = {"XY", "ZX", "YZ"};
    return "PLANE " + (e.text.empty() ? std::string(names[static_cast<int>(e.plane)]) : e.text);
  }
  case motion::Kind::UnitsChange:
    return "UNITS G" + n4(e.value);
  case motion::Kind::FeedModeChange:
    return "FEEDMODE G" + n4(e.value);
  }
  return "?";
}

namespace {
bool isModalChange(const motion::Event& e) {
  return e.kind == motion::Kind::PlaneChange || e.kind == motion::Kind::UnitsChange ||
         e.kind == motion::Kind::FeedModeChange;
}
} // namespace

std::vector<std::string> ProgramRun::motion() const {
  std::vector<std::string> out;
  for (const motion::Event& e : events)
    if (!isModalChange(e)) out.push_back(describe(e));
  return out;
}

std::vector<std::string> ProgramRun::all() const {
  std::vector<std::string> out;
  for (const motion::Event& e : events)
    out.push_back(describe(e));
  return out;
}

ProgramRun runNct(const std::string& text, const machine::Setup& setup, motion::Sink* also) {
  ProgramRun run;
  SourceManager sm;
  diag::Engine diags(100);
  const FileId f = sm.addBuffer("test.nct", text);
  std::istringstream in(text);
  nct::Reader reader(in, f, diags);
  check::StaticChecker checker(nct::profile(), diags);
  Collect sink(run.events, also);
  machine::Interpreter interp(nct::profile(), setup, sink, diags);
  ir::Block b;
  while (reader.next(b)) {
    const std::size_t before = diags.errorCount();
    checker.block(b);
    if (diags.errorCount() != before) break;
    motion::Provenance from;
    from.at = b.range.begin;
    if (!interp.execute(b, from)) break;
  }
  run.program = interp.programPosition();
  if (!diags.hasErrors()) {
    interp.finish();
    sink.finish();
  }
  for (const diag::Diagnostic& d : diags.all()) {
    if (d.severity == diag::Severity::Error)
      run.errors.push_back(fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code));
    run.rendered += diag::renderText(d, sm);
  }
  return run;
}

} // namespace gcx::test

#include <fstream>

#include "dialect/dialect.h"
#include "passes/macro/expander.h"

namespace gcx::test {

namespace {
MacroRun runMacroUnder(const Dialect& dialect, const std::map<std::string, std::string>& files,
                       const std::string& main, const std::vector<int>& watch,
                       const machine::Setup& setup, const macro::Limits& limits,
                       const std::vector<std::string>& libraryDirs) {
  static int counter = 0;
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("gcx-macro-{}-{}", ::getpid(), ++counter);
  fs::create_directories(dir);
  for (const auto& [name, text] : files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << text;
  }
  MacroRun run;
  SourceManager sm;
  diag::Engine diags(100);
  std::vector<std::string> libs;
  for (const std::string& d : libraryDirs)
    libs.push_back((dir / d).string());
  macro::ProgramLibrary library(dialect, sm, diags, libs);
  std::vector<motion::Event>& events = run.events;
  Collect sink(events, nullptr);
  std::ostringstream printed;
  if (const macro::LoadedProgram* prog = library.load((dir / main).string())) {
    machine::Interpreter interp(dialect.profile(), setup, sink, diags);
    macro::Expander expander(library, interp, diags, limits);
    expander.setPrintOutput(&printed);
    expander.run(*prog);
    for (int n : watch)
      if (auto v = expander.read(n, {})) run.vars[n] = *v;
    run.program = interp.programPosition();
  }
  run.printed = printed.str();
  for (const diag::Diagnostic& d : diags.all()) {
    if (d.severity == diag::Severity::Error || d.severity == diag::Severity::Warning)
      (d.severity == diag::Severity::Error ? run.errors : run.warnings)
          .push_back(fmt::format("{}:{}:{} {}",
                                 fs::path(sm.name(d.range.begin.file)).filename().string(),
                                 d.range.begin.line, d.range.begin.col, d.code));
    run.rendered += diag::renderText(d, sm);
  }
  fs::remove_all(dir);
  return run;
}
} // namespace

MacroRun runMacro(const std::map<std::string, std::string>& files, const std::string& main,
                  const std::vector<int>& watch, const machine::Setup& setup,
                  std::uint64_t maxJumps, const std::vector<std::string>& libraryDirs) {
  macro::Limits limits;
  limits.maxJumps = maxJumps;
  return runMacroUnder(*findDialect("nct"), files, main, watch, setup, limits, libraryDirs);
}

MacroRun runMacroLimited(const std::map<std::string, std::string>& files, const std::string& main,
                         const macro::Limits& limits) {
  return runMacroUnder(*findDialect("nct"), files, main, {}, {}, limits, {});
}

MacroRun runMacroAs(const Dialect& dialect, const std::map<std::string, std::string>& files,
                    const std::string& main, const std::vector<int>& watch) {
  return runMacroUnder(dialect, files, main, watch, {}, macro::Limits{}, {});
}

MacroRun runMacroWith(const Dialect& dialect, const std::map<std::string, std::string>& files,
                      const std::string& main, const machine::Setup& setup) {
  return runMacroUnder(dialect, files, main, {}, setup, macro::Limits{}, {});
}

MacroRun runMacroAs(const Dialect& dialect, const std::map<std::string, std::string>& files,
                    const std::string& main, const std::vector<int>& watch,
                    const machine::Setup& setup, const macro::Limits& limits) {
  return runMacroUnder(dialect, files, main, watch, setup, limits, {});
}

} // namespace gcx::test
