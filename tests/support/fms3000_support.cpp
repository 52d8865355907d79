#include "support/fms3000_support.h"

#include <sstream>

#include "dialect/dialect.h"
#include "dialects/fms3000/printer.h"
#include "passes/check/static_checks.h"

namespace gcx::test {

std::string specBlocks(const std::string& spec) {
  std::string out, rest = spec;
  const std::string dot = " \u00b7 ";
  for (std::size_t at; (at = rest.find(dot)) != std::string::npos;) {
    out += rest.substr(0, at) + "\r\n";
    rest = rest.substr(at + dot.size());
  }
  return out + rest + "\r\n";
}

Parsed parseFms(const std::string& text) {
  Parsed p;
  const FileId f = p.sources.addBuffer("test.fms", text);
  std::istringstream in(text);
  const Dialect& d = *findDialect("fms3000");
  auto source = d.open(in, f, p.diags);
  check::StaticChecker checker(d.profile(), p.diags);
  ir::Block b;
  while (source->next(b)) {
    checker.block(b);
    p.blocks.push_back(b);
  }
  checker.finish(f, source->failedBlocks() > 0);
  return p;
}

std::vector<std::string> printedFms(const Parsed& p) {
  std::vector<std::string> out;
  for (const ir::Block& b : p.blocks)
    out.push_back(fms3000::printBlock(b));
  return out;
}

MacroRun runFms(const std::map<std::string, std::string>& files, const machine::Setup& setup) {
  return runMacroWith(*findDialect("fms3000"), files, "main.fms", setup);
}

MacroRun runFms(const std::string& main, const machine::Setup& setup) {
  return runFms({{"main.fms", main}}, setup);
}

} // namespace gcx::test
