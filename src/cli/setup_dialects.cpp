#include "cli/setup_dialects.h"

#include "dialect/dialect.h"

namespace gcx::cli {

machine::SetupDialects setupDialects(const std::string& own) {
  machine::SetupDialects out;
  for (const Dialect& d : dialects()) {
    out.all.push_back(machine::setupSyntax(d.name, d.profile()));
    if (d.name == own) out.own = out.all.back();
  }
  return out;
}

} // namespace gcx::cli
