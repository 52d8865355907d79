#include "support/wl4_support.h"

#include <sstream>

#include "dialect/dialect.h"
#include "dialects/wl4/printer.h"
#include "dialects/wl4/profile.h"
#include "dialects/wl4/reader.h"
#include "passes/check/static_checks.h"
#include "passes/macro/expander.h"

namespace gcx::test {

Parsed parseWl4(const std::string& text, front::Encoding encoding, bool fastPath) {
  Parsed p;
  const FileId f = p.sources.addBuffer("test.wl4", text);
  std::istringstream in(text);
  wl4::Reader reader(in, f, p.diags, encoding);
  reader.setFastPath(fastPath);
  check::StaticChecker checker(wl4::profile(), p.diags);
  ir::Block b;
  while (reader.next(b)) {
    checker.block(b);
    p.blocks.push_back(b);
  }
  checker.finish(f, reader.failedBlocks() > 0);
  return p;
}

std::vector<std::string> printedWl4(const Parsed& p) {
  std::vector<std::string> out;
  for (const ir::Block& b : p.blocks)
    out.push_back(wl4::printBlock(b));
  return out;
}

MacroRun runWl4(const std::map<std::string, std::string>& files, const std::string& main,
                const machine::Setup& setup, const std::vector<int>& watch) {
  macro::Limits limits;
  limits.maxJumps = 10000;
  return runMacroAs(*findDialect("wl4"), files, main, watch, setup, limits);
}

MacroRun runWl4(const std::string& text, const machine::Setup& setup) {
  return runWl4({{"main.wl4", text}}, "main.wl4", setup);
}

std::vector<std::string> errorsAt(const MacroRun& r) {
  std::vector<std::string> out;
  for (const std::string& e : r.errors)
    out.push_back(e.substr(e.find(':') + 1));
  return out;
}

machine::Setup wl4Lathe() {
  machine::Setup s;
  s.parameters["lathe"] = 1;
  return s;
}

} // namespace gcx::test
