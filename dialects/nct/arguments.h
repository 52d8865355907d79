// NCT macro-call argument specification I and II (nct-macro.md §5.4): which local variable each
// word of a G65/G66/G66.1 block fills. One implementation for the static check and the macro pass.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "ir/block.h"

namespace gcx::nct {

struct ArgumentBinding {
  int variable = 0; // 1..33
  const ir::Word* word = nullptr;
};

struct ArgumentResult {
  std::vector<ArgumentBinding> bindings;
  const ir::Word* offending = nullptr; // the word that caused the error
  const char* code = nullptr;          // 2017 or 2064
  std::string message;
  bool ok() const { return offending == nullptr; }
};

/// Is this word's value unknown until run time (so the static check must stop)?
using UnknownValue = std::function<bool(const ir::Word&)>;
/// Is this word a bare variable reference that is vacant (then it is skipped, macro §2.5 rule 6)?
using VacantValue = std::function<bool(const ir::Word&)>;

/// Binds the argument words of a macro call block. Control words (the call G code, P, L and
/// a `<file>`) are skipped. Stops early, with ok() true, when unknown() says a value decides.
/// With controlPL false, P and L are ordinary arguments (#16, #12): calls by a configured G code
/// (nct-macro.md §5.4, last table).
ArgumentResult bindArguments(const ir::Block& block, const VacantValue& vacant,
                             const UnknownValue& unknown = {}, bool controlPL = true);

} // namespace gcx::nct
