// The setup syntaxes of the registered dialects, for reading a setup file (--setup).
#pragma once
#include <string>

#include "machine/setup_syntax.h"

namespace gcx::cli {

/// Every registered dialect's setup syntax, with `own` (a dialect's name) as the program's;
/// an empty `own` reads only the machine (offsets, tools, positions).
machine::SetupDialects setupDialects(const std::string& own);

} // namespace gcx::cli
