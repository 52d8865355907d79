// NCT macro-call argument specification I and II (nct-macro.md §5.4): which local variable each
// word of a G65/G66/G66.1 block fills. One implementation for the static check and the macro pass.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "dialect/control_flow.h"
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

/// The control-flow engine's binding hook: the words of a call as bindArguments takes them,
/// then the control values (§5.3 C3) where no word took their variable: #10 the call code,
/// #16 P and #12 L; under G66.1 (a call by every block, §5.6 E2) #10 the block's G code or
/// vacant, #12 its L and #16 its P, and a second G code in the block is an error.
CallArguments bindCall(const CallSite& site);

} // namespace gcx::nct
