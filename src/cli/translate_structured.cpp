#include "cli/translate_structured.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cli/execute.h"
#include "cli/setup_dialects.h"
#include "machine/settings.h"
#include "machine/setup.h"
#include "passes/macro/program_library.h"
#include "translate/lift.h"
#include "translate/structure_scan.h"
#include "translate/structured_writer.h"

namespace gcx::cli {

namespace {

namespace fs = std::filesystem;

std::string located(const xlate::Unkept& u, SourceManager& sources, const std::string& input) {
  const SourceLoc& at = u.where.begin;
  const std::string file = at.valid() ? fs::path(sources.name(at.file)).filename().string()
                                      : fs::path(input).filename().string();
  return at.valid() ? fmt::format("{}:{}: {}: {}", file, at.line, u.what, u.why)
                    : fmt::format("{}: {}: {}", file, u.what, u.why);
}

// "subprogram calls (A.nct:7, 9)", "loops (A.nct:3)"
std::vector<std::string> keptList(const std::vector<xlate::KeptStructure>& kept,
                                  SourceManager& sources) {
  std::vector<std::string> out;
  for (const xlate::KeptStructure& k : kept) {
    std::string at;
    FileId file = static_cast<FileId>(-1);
    for (std::size_t i = 0; i < k.at.size() && i < 6; ++i) {
      if (i > 0) at += ", ";
      if (k.at[i].file != file)
        at += fs::path(sources.name(k.at[i].file)).filename().string() + ":";
      file = k.at[i].file;
      at += std::to_string(k.at[i].line);
    }
    if (k.at.size() > 6) at += fmt::format(" and {} more", k.at.size() - 6);
    out.push_back(fmt::format("{} ({})", k.what, at));
  }
  return out;
}

// A block's place as both runs name it (each reads the files into its own SourceManager).
std::string placeKey(SourceManager& sources, const SourceLoc& at) {
  return fmt::format("{}:{}:{}", at.valid() ? sources.name(at.file) : std::string(), at.line,
                     at.col);
}

// The events of every run of every block of the lifted units, in the program's frame: a run of
// a block begins when the block runs, and takes what runs on its behalf (a cycle program it
// calls) until another block of the units runs.
class BlockRunRecorder : public motion::Sink {
public:
  BlockRunRecorder(SourceManager& sources, const std::set<std::string>& blocks)
      : sources_(sources), blocks_(blocks) {}

  void block(const motion::Provenance& from) {
    const std::string at = placeKey(sources_, from.at);
    if (blocks_.count(at)) {
      runs_[at].emplace_back();
      current_ = &runs_[at].back();
      return;
    }
    current_ = nullptr;
    for (auto f = from.chain.rbegin(); f != from.chain.rend(); ++f) {
      const std::string call = placeKey(sources_, f->call);
      if (!blocks_.count(call)) continue;
      auto& runs = runs_[call];
      if (runs.empty()) runs.emplace_back();
      current_ = &runs.back();
      return;
    }
  }
  void event(const motion::Event& e) override {
    if (current_) current_->push_back(e);
  }
  const xlate::BlockRuns* runsAt(const std::string& at) const {
    const auto it = runs_.find(at);
    return it == runs_.end() ? nullptr : &it->second;
  }

private:
  SourceManager& sources_;
  const std::set<std::string>& blocks_;
  std::map<std::string, xlate::BlockRuns> runs_;
  std::vector<motion::Event>* current_ = nullptr;
};

} // namespace

StructuredTarget structuredTarget(const Dialect& target) {
  StructuredTarget t;
  t.spelling = xlate::structuredSpellingFor(target.name);
  t.emitter = target.emitter;
  t.name = target.name;
  t.encoding = target.textEncoding();
  return t;
}

StructuredAttempt writeStructuredDialect(const Dialect& source, const StructuredTarget& target,
                                         const std::string& input, const fs::path& stage,
                                         const std::string& mainName, const TranslateOptions& opt) {
  StructuredAttempt a;
  const xlate::StructuredSpelling* spelling = target.spelling;
  if (!spelling) return a;
  SourceManager sources;
  diag::Engine diags(opt.common.maxErrors);
  macro::ProgramLibrary library(source, sources, diags, opt.common.libraryDirs);
  const macro::LoadedProgram* main = library.load(input);
  if (!main || diags.errorCount() > 0) return a; // the flat translation reports the errors
  for (const xlate::StructureAt& s : xlate::scanStructures(main->blocks, source.profile()))
    a.tried = a.tried || s.kind != xlate::Structure::Cycle || target.forCycles;
  if (!a.tried) return a;
  machine::Setup setup;
  if (!opt.setup.empty()) {
    std::optional<machine::Setup> loaded =
        machine::loadSetup(opt.setup, sources, diags, setupDialects(source.name));
    if (!loaded) return a;
    setup = std::move(*loaded);
  }
  const xlate::SettingLookup settings = [&](Setting which) {
    return machine::setting(source.profile(), setup, which);
  };
  // the main program and every program it calls, each read by meaning once; a call names the
  // unit by the first name that loaded its program
  xlate::StructuredInput in;
  in.source = &source.profile();
  in.mainStem = fs::path(input).stem().string();
  xlate::Unkept why;
  std::vector<const macro::LoadedProgram*> loaded = {main};
  std::vector<std::string> names = {in.mainStem};
  std::map<std::string, std::string> unitOf; // a call's unit -> the name of its program's unit
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    xlate::UnitSteps u;
    u.main = i == 0;
    u.name = names[i];
    if (!xlate::liftUnit(loaded[i]->blocks, source.profile(), settings, u, why)) {
      a.unkept = located(why, sources, input);
      return a;
    }
    for (xlate::Step& s : u.steps)
      for (xlate::Flow& f : s.after) {
        if (f.kind != xlate::FlowKind::Call) continue;
        if (!unitOf.count(f.unit)) {
          const macro::LoadedProgram* p = library.byUnit(f.unit, *loaded[i], f.range);
          if (!p || diags.errorCount() > 0) {
            a.unkept = fmt::format("{}: the program {} it calls is not found",
                                   fs::path(input).filename().string(), f.unit);
            return a;
          }
          const auto known = std::find(loaded.begin(), loaded.end(), p);
          if (known == loaded.end()) {
            loaded.push_back(p);
            names.push_back(f.unit);
          }
          unitOf[f.unit] = names[static_cast<std::size_t>(
              std::find(loaded.begin(), loaded.end(), p) - loaded.begin())];
        }
        f.unit = unitOf[f.unit];
      }
    in.units.push_back(std::move(u));
  }
  in.notes = {fmt::format("translated from {} ({}) by gcx", fs::path(input).filename().string(),
                          source.name)};
  // what each block drilled, run on the same setup in the program's frame (Step::cycle)
  std::set<std::string> blocks;
  bool drills = false;
  for (const xlate::UnitSteps& u : in.units)
    for (const xlate::Step& st : u.steps) {
      blocks.insert(placeKey(sources, st.range.begin));
      drills = drills || st.cycle;
    }
  Session run(opt.common);
  machine::Setup runSetup;
  BlockRunRecorder recorder(run.sources(), blocks);
  if (drills) {
    std::ostringstream discard;
    if (openWithSetup(run, input, opt.setup, runSetup) != Ok ||
        !executeProgram(run, opt.common, runSetup, recorder, discard, Frame::Program, nullptr,
                        [&](const motion::Provenance& from) { recorder.block(from); })) {
      a.unkept = fmt::format("{}: the program does not run", fs::path(input).filename().string());
      return a;
    }
    in.runs = [&](const SourceLoc& at) { return recorder.runsAt(placeKey(sources, at)); };
  }
  xlate::StructuredResult result;
  if (!xlate::writeStructured(std::move(in), *spelling, target.emitter, result, why)) {
    a.unkept = located(why, sources, input);
    return a;
  }
  a.kept = keptList(result.kept, sources);
  std::string list;
  for (const std::string& k : a.kept)
    list += (list.empty() ? "" : ", ") + k;
  a.note = fmt::format("kept as {} structure: {}; program frame: runs on the same setup as its "
                       "source",
                       target.name, list);
  std::error_code ec;
  fs::create_directories(stage, ec);
  for (const xlate::WrittenFile& f : result.files) {
    const std::string name = f.name.empty() ? mainName : f.name;
    if (!f.name.empty() && f.name == mainName) {
      a.unkept = fmt::format("{}: the subprogram file {} is the output's own name",
                             fs::path(input).filename().string(), f.name);
      return a;
    }
    const fs::path path = stage / name;
    std::string why;
    const std::optional<std::string> text = front::encodeText(f.text, target.encoding, why);
    if (!text) { // the line of a program that is not written would say nothing
      a.unkept = "its text " + why.substr(std::min(why.find("holds"), why.size()));
      return a;
    }
    std::ofstream out(path, std::ios::binary);
    out << *text;
    if (!out) {
      a.unkept = fmt::format("cannot write {}", path.string());
      return a;
    }
    a.staged.push_back(path);
    a.names.push_back(name);
  }
  a.written = true;
  return a;
}

} // namespace gcx::cli
