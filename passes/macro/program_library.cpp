#include "passes/macro/program_library.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "diag/codes.h"
#include "dialect/control_flow.h"
#include "passes/check/static_checks.h"

namespace gcx::macro {

namespace fs = std::filesystem;

std::size_t LoadedProgram::find(std::int64_t n, std::size_t from) const {
  auto it = labels.find(n);
  if (it == labels.end()) return npos;
  for (std::size_t i : it->second)
    if (i >= from) return i;
  return it->second.front();
}

ProgramLibrary::ProgramLibrary(const Dialect& dialect, SourceManager& sources, diag::Engine& diags,
                               std::vector<std::string> libraryDirs)
    : dialect_(dialect), sources_(sources), diags_(diags), libraryDirs_(std::move(libraryDirs)) {}

namespace {

// Block numbers and the static loop pairs of a unit (the checker has already rejected
// unpaired loops).
void indexBlocks(LoadedProgram& prog) {
  prog.loopPartner.assign(prog.blocks.size(), LoadedProgram::npos);
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < prog.blocks.size(); ++i) {
    const ir::Block& blk = prog.blocks[i];
    if (blk.sequence && blk.kind == ir::BlockKind::Normal) prog.labels[*blk.sequence].push_back(i);
    if (blk.stmts.empty()) continue;
    const ir::StmtKind k = blk.stmts.front().kind;
    if (k == ir::StmtKind::While || k == ir::StmtKind::Do) open.push_back(i);
    if (k == ir::StmtKind::End) {
      for (auto it = open.rbegin(); it != open.rend(); ++it)
        if (prog.blocks[*it].stmts.front().loopId == blk.stmts.front().loopId) {
          prog.loopPartner[*it] = i;
          prog.loopPartner[i] = *it;
          open.erase(std::next(it).base());
          break;
        }
    }
  }
}

} // namespace

bool ProgramLibrary::namedUnits() const {
  const ControlFlow* flow = dialect_.profile().controlFlow;
  return flow && flow->namedUnits;
}

const LoadedProgram* ProgramLibrary::load(const std::string& path) {
  const Units* units = loadFile(path);
  return units ? units->front().get() : nullptr;
}

const ProgramLibrary::Units* ProgramLibrary::loadFile(const std::string& path) {
  std::error_code ec;
  const std::string key = fs::weakly_canonical(path, ec).string();
  if (auto it = loaded_.find(key); it != loaded_.end()) return &it->second;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags_.error(diag::code::CannotRead, {}, fmt::format("{}: cannot open", path));
    return nullptr;
  }
  if (loaded_.empty()) mainFolder_ = fs::path(key).parent_path().string();
  return loadUnits(key, path, sources_.addFile(path), in);
}

const ProgramLibrary::Units* ProgramLibrary::loadUnits(const std::string& key,
                                                       const std::string& path, FileId file,
                                                       std::istream& in) {
  auto prog = std::make_unique<LoadedProgram>();
  prog->path = path;
  prog->file = file;
  const std::size_t errorsBefore = diags_.errorCount();
  auto source = dialect_.open(in, prog->file, diags_);
  check::StaticChecker checker(dialect_.profile(), diags_);
  ir::Block b;
  while (source->next(b)) {
    checker.block(b);
    prog->blocks.push_back(b);
  }
  checker.finish(prog->file, source->failedBlocks() > 0);
  if (diags_.errorCount() != errorsBefore) return nullptr;
  Units units;
  if (!namedUnits()) {
    units.push_back(std::move(prog));
  } else if (!splitUnits(*prog, units)) {
    return nullptr;
  }
  for (auto& u : units) {
    u->key = key;
    indexBlocks(*u);
  }
  return &loaded_.emplace(key, std::move(units)).first->second;
}

bool ProgramLibrary::splitUnits(LoadedProgram& whole, Units& units) {
  // `%name` opens a unit, `%` closes it; text between units is not part of a program (§1.2)
  LoadedProgram* open = nullptr;
  for (ir::Block& b : whole.blocks) {
    if (b.kind == ir::BlockKind::ProgramStart) {
      auto u = std::make_unique<LoadedProgram>();
      u->file = whole.file;
      u->path = whole.path;
      u->name = b.programName;
      open = u.get();
      units.push_back(std::move(u));
    } else if (b.kind == ir::BlockKind::ProgramEnd) {
      open = nullptr;
    } else if (open) {
      open->blocks.push_back(std::move(b));
    }
  }
  if (!units.empty()) return true;
  diags_.error(diag::code::ProgramNotFound, SourceRange{SourceLoc{whole.file, 1, 1, 0}, 1},
               fmt::format("{} holds no program: a program starts with a line `%name`",
                           fs::path(whole.path).filename().string()));
  return false;
}

const LoadedProgram* ProgramLibrary::systemUnit(const std::string& unit) {
  const ControlFlow* flow = dialect_.profile().controlFlow;
  const auto text = flow && flow->systemProgram ? flow->systemProgram(unit) : std::nullopt;
  if (!text) return nullptr;
  const std::string key = "system program " + unit;
  const Units* units = nullptr;
  if (auto it = loaded_.find(key); it != loaded_.end()) {
    units = &it->second;
  } else {
    // named like a file of the caller's kind, so messages point into the shipped program
    const std::string name = label(unit) + " (system program)";
    std::istringstream in{std::string(*text)};
    units = loadUnits(key, name, sources_.addBuffer(name, std::string(*text)), in);
  }
  return units ? unitNamed(*units, unit) : nullptr;
}

const LoadedProgram* ProgramLibrary::unitNamed(const Units& units, const std::string& name) {
  for (const auto& u : units)
    if (u->name == name) return u.get();
  return nullptr;
}

std::vector<std::string> ProgramLibrary::searchFolders(const LoadedProgram& caller) const {
  // the caller's folder, then the library folders; system macros of configured calls live in
  // SystemMacros/Channel1 below them (nct-macro.md §5.1 S6)
  std::vector<std::string> dirs{fs::path(caller.path).parent_path().string()};
  for (const std::string& d : libraryDirs_)
    dirs.push_back(d);
  for (std::size_t i = 0, n = dirs.size(); i < n; ++i)
    dirs.push_back((fs::path(dirs[i]) / "SystemMacros" / "Channel1").string());
  return dirs;
}

std::string ProgramLibrary::locateFile(const std::vector<std::string>& candidates,
                                       const LoadedProgram& caller) const {
  for (const fs::path dir : searchFolders(caller)) {
    for (const std::string& name : candidates) {
      const fs::path direct = dir / name;
      std::error_code ec;
      if (fs::is_regular_file(direct, ec)) return direct.string();
      // the controls' file systems ignore case: O0011.NCT finds o0011.nct
      const fs::path folder = (dir / name).parent_path();
      const std::string leaf = fs::path(name).filename().string();
      if (!fs::is_directory(folder, ec)) continue;
      for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string f = entry.path().filename().string();
        if (entry.is_regular_file(ec) && f.size() == leaf.size() &&
            std::equal(f.begin(), f.end(), leaf.begin(), [](char a, char b) {
              return std::tolower(static_cast<unsigned char>(a)) ==
                     std::tolower(static_cast<unsigned char>(b));
            }))
          return entry.path().string();
      }
    }
  }
  return {};
}

const LoadedProgram* ProgramLibrary::findFile(const std::vector<std::string>& candidates,
                                              const LoadedProgram& caller, const SourceRange& where,
                                              const std::string& what) {
  if (std::string path = locateFile(candidates, caller); !path.empty()) {
    if (!insideRoots(path)) {
      diags_.error(diag::code::PathOutsideFolders, where,
                   fmt::format("program {} lies outside the program's folder and the --lib "
                               "folders; add its folder with --lib DIR",
                               what));
      return nullptr;
    }
    return load(path);
  }
  diags_.error(diag::code::ProgramNotFound, where,
               fmt::format("program {} not found next to {} or in the library folders", what,
                           fs::path(caller.path).filename().string()));
  return nullptr;
}

bool ProgramLibrary::insideRoots(const std::string& path) const {
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(path, ec);
  const auto within = [&](const std::string& root) {
    const fs::path r = fs::weakly_canonical(root.empty() ? "." : root, ec);
    const auto [rootEnd, fileIt] = std::mismatch(r.begin(), r.end(), file.begin(), file.end());
    return rootEnd == r.end() || (std::next(rootEnd) == r.end() && rootEnd->empty());
  };
  if (within(mainFolder_)) return true;
  return std::any_of(libraryDirs_.begin(), libraryDirs_.end(), within);
}

std::vector<std::string> ProgramLibrary::unitFiles(const std::string& unit,
                                                   const LoadedProgram& caller) const {
  const ControlFlow* flow = dialect_.profile().controlFlow;
  if (!flow || !flow->programFiles) return {};
  return flow->programFiles(unit, fs::path(caller.path).extension().string());
}

std::string ProgramLibrary::label(const std::string& unit) const {
  const ControlFlow* flow = dialect_.profile().controlFlow;
  return flow && flow->programLabel ? flow->programLabel(unit) : unit;
}

std::string ProgramLibrary::locate(const std::string& unit, const LoadedProgram& caller) const {
  return locateFile(unitFiles(unit, caller), caller);
}

const LoadedProgram* ProgramLibrary::byUnit(const std::string& unit, const LoadedProgram& caller,
                                            const SourceRange& where) {
  const std::string ext = fs::path(caller.path).extension().string();
  if (!namedUnits()) return findFile(unitFiles(unit, caller), caller, where, label(unit) + ext);
  // a unit of the caller's file, then a file of the unit's name beside it holding that unit
  if (auto own = loaded_.find(caller.key); own != loaded_.end())
    if (const LoadedProgram* p = unitNamed(own->second, unit)) return p;
  // a program the dialect ships, unless the user has one of that name
  if (locateFile(unitFiles(unit, caller), caller).empty())
    if (const LoadedProgram* p = systemUnit(unit)) return p;
  const LoadedProgram* first = findFile(unitFiles(unit, caller), caller, where, label(unit) + ext);
  if (!first) return nullptr;
  const Units* units = loadFile(first->path);
  if (const LoadedProgram* p = units ? unitNamed(*units, unit) : nullptr) return p;
  diags_.error(diag::code::ProgramNotFound, where,
               fmt::format("program {} not found: {} holds no unit {}", label(unit),
                           fs::path(first->path).filename().string(), label(unit)));
  return nullptr;
}

const LoadedProgram* ProgramLibrary::byName(const std::string& name, const LoadedProgram& caller,
                                            const SourceRange& where) {
  std::string path = name;
  std::replace(path.begin(), path.end(), '\\', '/'); // the manual's paths use backslashes
  return findFile({path}, caller, where, "<" + name + ">");
}

} // namespace gcx::macro
