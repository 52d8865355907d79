// NC words whose value is a variable or expression (`X#1`, `XI-#24`, `Y[#1+10]`, `G#102`): the
// vacant rule of nct-macro.md §2.5 rule 4, the rounding of §2.6 and the address range check.
#pragma once
#include <optional>
#include <string_view>

#include "dialect/word_value_rules.h"
#include "ir/block.h"
#include "passes/macro/evaluator.h"

namespace gcx::macro {

using gcx::AddressRule;
using gcx::Rounding;

struct WordOptions {
  /// The dialect's table (ControlFlow::wordValues); without one, values pass unrounded.
  const WordValueRules* rules = nullptr;
  /// Overrides the table's coordinate resolution when set.
  std::optional<double> resolution;
  /// P is a program or sequence number of a call or return (the remap row says so), S a
  /// configured call.
  bool callNumber = false;
};

enum class WordResult : unsigned char {
  Value,   // number holds the rounded, range-checked value
  Dropped, // a bare variable reference that is vacant: the word leaves the block (§2.5 rule 4)
  Error,   // reported
};

struct WordValue {
  WordResult result = WordResult::Error;
  double number = 0;
};

/// Resolves the value of w. A literal word is returned unchanged (the static checks own it).
/// `A#n`, `A-#n`, `AI#n`, `AI-#n`, `A#[e]`, `A#_NAME` drop the word when vacant; `A[e]`, `A-[e]`
/// are always a number (vacant = 0). w.incremental is left to the caller.
WordValue wordValue(const ir::Word& w, Evaluator& ev, const WordOptions& opt = {});

/// Rounds v for address per the table and checks its range: nullopt after reporting NCTX04 at
/// where. -0 comes back as 0.
std::optional<double> addressValue(double v, std::string_view address, const SourceRange& where,
                                   diag::Engine& diags, const WordOptions& opt = {});

} // namespace gcx::macro
