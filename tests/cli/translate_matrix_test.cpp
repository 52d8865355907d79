// The translation matrix (docs/translation.md): every example and differential program of every
// dialect translated to every other dialect, to canonical and to ngc, each proven equivalent by
// translate itself (a batch per source folder and target). The outcome of every pair is pinned in
// translate_matrix.txt: a translation that starts or stops holding, or fails for another reason,
// is a difference to look at (the test prints the whole table to update it). A subprogram is
// translated with its caller and has no row of its own; one the batch took for a subprogram by
// mistake would lose its rows.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <vector>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

const char* const kFolders[] = {"examples/nct", "examples/wl4", "tests/differential/programs",
                                "tests/differential/fms3000", "tests/differential/wl4"};
const char* const kTargets[] = {"nct", "fms3000", "wl4", "canonical", "ngc"};

std::string dialectOf(const fs::path& p) {
  const std::string e = p.extension().string();
  return e == ".nct" ? "nct" : e == ".fms" ? "fms3000" : e == ".wl4" ? "wl4" : "";
}

// "program: status [code]" from report.csv: the error code in brackets, or what the proof found
std::string outcome(const std::string& status, const std::string& reason) {
  if (status == "verified") return status;
  static const std::regex code(R"(\[([A-Z0-9-]+)\])");
  std::smatch m;
  if (std::regex_search(reason, m, code)) return status + " " + m[1].str();
  if (reason.find("does not move the tool like") != std::string::npos) return status + " differs";
  return status;
}

// The cells of a report.csv line ("a,\"b, c\",d": a / b, c / d).
std::vector<std::string> csvCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
      cells.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.emplace_back();
    else
      cells.back() += c;
  }
  return cells;
}

// The kinds of structure a translation kept, without their lines: "drilling (A.nct:2, 3)" is
// "drilling".
std::string keptKinds(const std::string& kept) {
  static const std::regex places(R"( \([^)]*\))");
  return std::regex_replace(kept, places, "");
}

TEST(TranslateMatrix, EveryProgramToEveryTargetIsProvenOrRefusedAsPinned) {
  CliFolder folder("translate-matrix");
  const fs::path source(GCX_SOURCE_DIR);
  std::ostringstream table;
  for (const char* rel : kFolders) {
    const fs::path dir = source / rel;
    std::vector<fs::path> programs;
    for (const auto& e : fs::directory_iterator(dir))
      if (!dialectOf(e.path()).empty()) programs.push_back(e.path());
    std::sort(programs.begin(), programs.end());
    const fs::path in = folder.path() / rel;
    fs::create_directories(in);
    for (const fs::path& p : programs) {
      fs::create_symlink(p, in / p.filename());
      const fs::path setup = dir / (p.stem().string() + ".setup.json");
      if (fs::exists(setup)) fs::create_symlink(setup, in / setup.filename());
    }
    for (const char* to : kTargets) {
      const std::string out = std::string("out/") + rel + "/" + to;
      folder.gcx(
          fmt::format("translate {} --to {} -o {} --jobs 2 --lib {}", rel, to, out, dir.string()));
      std::map<std::string, std::string> rows; // program -> outcome
      std::ifstream csv(folder.path() / out / "report.csv");
      std::string line;
      std::getline(csv, line); // header
      while (std::getline(csv, line)) {
        // program,output,status,exit,seconds,peak_rss_kb,reason,kept,expanded
        const std::vector<std::string> cells = csvCells(line);
        if (cells.size() < 9) continue;
        rows[cells[0]] = outcome(cells[2], cells[6]) +
                         (cells[7].empty() ? "" : ", kept: " + keptKinds(cells[7]));
      }
      for (const fs::path& p : programs) {
        const std::string name = p.filename().string();
        // a subprogram runs with its caller, not alone (the batch tells them apart)
        const auto row = rows.find(name);
        if (dialectOf(p) == to || (row != rows.end() && row->second.starts_with("subprogram")))
          continue;
        table << rel << '/' << name << " -> " << to << ": "
              << (row != rows.end() ? row->second : "missing") << '\n';
      }
    }
  }
  const std::string expected = readFile(source / "tests" / "cli" / "translate_matrix.txt");
  if (table.str() == expected) return;
  // only the rows that differ, then the whole table to replace the pinned one with
  std::istringstream a(table.str()), b(expected);
  std::string x, y, rows;
  while (std::getline(a, x) && std::getline(b, y))
    if (x != y) rows += "  now: " + x + "\n  was: " + y + "\n";
  ADD_FAILURE() << "the matrix changed:\n" << rows << "the whole table:\n" << table.str();
}

} // namespace
} // namespace gcx::test
