// The program files a run needs, loaded whole (jumps and calls need random access): the main
// program, and the programs it calls, found by their unit name through the dialect's
// ControlFlow::programFiles or by file name, each parsed and statically checked once.
#pragma once
#include <istream>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "diag/diagnostic.h"
#include "dialect/dialect.h"
#include "ir/block.h"

namespace gcx::macro {

/// One program unit: a whole file, or one `%name ... %` unit of a file (ControlFlow::namedUnits).
struct LoadedProgram {
  FileId file = 0;
  std::string path;
  std::string name; // the unit's name (namedUnits), else empty
  std::string key;  // the source it was read from, as the library keys it
  std::vector<ir::Block> blocks;
  /// Block number -> indices of the blocks carrying it as their first N, in file order.
  std::unordered_map<std::int64_t, std::vector<std::size_t>> labels;
  /// For each DO/WHILE block its END block and the reverse (nct-macro.md §4.5); npos: none.
  std::vector<std::size_t> loopPartner;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  /// The block labelled n, searched from `from` to the end, then from the start (§4.1 G5).
  std::size_t find(std::int64_t n, std::size_t from) const;
};

class ProgramLibrary {
public:
  ProgramLibrary(const Dialect& dialect, SourceManager& sources, diag::Engine& diags,
                 std::vector<std::string> libraryDirs = {});

  /// Loads a program file; null after reporting errors (I/O, syntax, static checks). With
  /// named units, the file's first unit (the main program, wl4.md §1.2).
  const LoadedProgram* load(const std::string& path);
  /// Program `unit` (NCT "12" from a P12 call word): with named units, a unit of that name in
  /// the caller's file first; then the dialect's file names for it with the caller's
  /// extension, in the caller's folder, then in the library folders. Null after reporting
  /// NCTX07 at `where`.
  const LoadedProgram* byUnit(const std::string& unit, const LoadedProgram& caller,
                              const SourceRange& where);
  /// The file `byUnit` would load, or empty; nothing is reported.
  std::string locate(const std::string& unit, const LoadedProgram& caller) const;
  /// How messages name program `unit` (NCT "O0012").
  std::string label(const std::string& unit) const;
  /// The folders a call from `caller` searches, in order.
  std::vector<std::string> searchFolders(const LoadedProgram& caller) const;
  /// A `<name>` call word: relative to the caller's folder (`\` separators, `..\`), then the
  /// library.
  const LoadedProgram* byName(const std::string& name, const LoadedProgram& caller,
                              const SourceRange& where);

private:
  /// A file's program units: one for a plain file, each `%name ... %` with named units.
  using Units = std::vector<std::unique_ptr<LoadedProgram>>;
  const Units* loadFile(const std::string& path);
  /// Reads the units of one source (a file, or a system program's text) under `key`.
  const Units* loadUnits(const std::string& key, const std::string& path, FileId file,
                         std::istream& in);
  /// A system program of the dialect named `unit`, or null.
  const LoadedProgram* systemUnit(const std::string& unit);
  /// Splits a file's blocks into its units; false after reporting a file without one.
  bool splitUnits(LoadedProgram& whole, Units& units);
  static const LoadedProgram* unitNamed(const Units& units, const std::string& name);
  bool namedUnits() const;
  std::vector<std::string> unitFiles(const std::string& unit, const LoadedProgram& caller) const;
  std::string locateFile(const std::vector<std::string>& candidates,
                         const LoadedProgram& caller) const;
  const LoadedProgram* findFile(const std::vector<std::string>& candidates,
                                const LoadedProgram& caller, const SourceRange& where,
                                const std::string& what);

  const Dialect& dialect_;
  SourceManager& sources_;
  diag::Engine& diags_;
  std::vector<std::string> libraryDirs_;
  std::string mainFolder_; // the first program's folder: with --lib, where calls may look
  /// Whether a located file lies inside the main program's folder or a --lib folder.
  bool insideRoots(const std::string& path) const;
  std::unordered_map<std::string, Units> loaded_; // by canonical path
};

} // namespace gcx::macro
