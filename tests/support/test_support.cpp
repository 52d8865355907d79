#include "support/test_support.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "dialects/nct/profile.h"
#include "dialects/nct/reader.h"
#include "passes/check/static_checks.h"

namespace gcx::test {

namespace {
std::vector<std::string> collect(const diag::Engine& e, diag::Severity sev) {
  std::vector<std::string> out;
  for (const diag::Diagnostic& d : e.all())
    if (d.severity == sev)
      out.push_back(fmt::format("{}:{} {}", d.range.begin.line, d.range.begin.col, d.code));
  return out;
}

void run(Parsed& p, std::istream& in, FileId file, const ParseOptions& opt) {
  nct::Reader reader(in, file, p.diags, {}, opt.encoding);
  reader.setFastPath(opt.fastPath);
  check::StaticChecker checker(nct::profile(), p.diags);
  ir::Block b;
  while (reader.next(b)) {
    if (opt.staticChecks) checker.block(b);
    p.blocks.push_back(b);
  }
  if (opt.staticChecks) checker.finish(file, reader.stats().failed > 0);
  p.fastPathBlocks = reader.stats().fastPath;
}
} // namespace

std::vector<std::string> Parsed::errors() const {
  return collect(diags, diag::Severity::Error);
}
std::vector<std::string> Parsed::warnings() const {
  return collect(diags, diag::Severity::Warning);
}

std::string Parsed::rendered() const {
  std::string s;
  for (const diag::Diagnostic& d : diags.all())
    s += diag::renderText(d, sources);
  return s;
}

Parsed parseNct(const std::string& text, const ParseOptions& opt) {
  Parsed p;
  FileId f = p.sources.addBuffer(opt.name, text);
  std::istringstream in(text);
  run(p, in, f, opt);
  return p;
}

Parsed parseNctFile(const fs::path& path, const ParseOptions& opt) {
  Parsed p;
  FileId f = p.sources.addFile(path.string());
  std::ifstream in(path, std::ios::binary);
  run(p, in, f, opt);
  return p;
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path sourceDir() {
  return fs::path(GCX_SOURCE_DIR);
}

std::vector<fs::path> filesUnder(const fs::path& dir, const std::vector<std::string>& exts) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = e.path().extension().string();
    if (std::find(exts.begin(), exts.end(), ext) != exts.end()) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace gcx::test
