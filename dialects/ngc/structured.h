// `gcx translate --to ngc` with structure: a source program written as LinuxCNC RS274/NGC that
// keeps its canned cycles, subprograms, loops and variables where LinuxCNC gives them the same
// meaning (docs/translation.md, "ngc: what is kept"). A program with one construct that cannot be
// kept is not written here: the caller writes its flat motion and says why.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "dialect/dialect.h"
#include "ir/block.h"

namespace gcx::ngc {

/// Why a program could not be kept structured: the construct, where, and why.
struct Unkept {
  SourceRange where;
  std::string what; // "GOTO", "G84 tapping cycle"
  std::string why;
};

/// The blocks of program `unit` (NCT "2001" from P2001) called at `where`, or null.
using FindProgram =
    std::function<const std::vector<ir::Block>*(const std::string& unit, const SourceRange&)>;

struct Structured {
  std::string text;              // the whole .ngc file
  std::vector<std::string> kept; // "canned cycles (G81)", "subprogram O2001 as o2001"
};

using StructuredWriter = bool (*)(const std::vector<ir::Block>& main, const FindProgram& find,
                                  Structured& out, Unkept& unkept);

/// The writer for programs of `source`, or null when gcx keeps none of its structure in ngc.
StructuredWriter structuredWriter(const Dialect& source);

} // namespace gcx::ngc
