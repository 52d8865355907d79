// The fast path: plain word-address blocks (letters with literal numbers, `/n`, comments), the
// bulk of CAM output. It yields exactly the IR the ANTLR path yields (tests/unit/
// fast_path_equivalence_test.cpp proves it on the corpus and on generated blocks) and declines
// anything else, including every malformed block, so that errors always come from the grammar.
#pragma once
#include "dialects/nct/block_builder.h"

namespace gcx::nct {

enum class FastResult { Parsed, Failed, Declined };

/// Parses raw into out if raw is a well-formed plain block. Declined (nothing reported) for
/// anything else; Failed when the block has the plain shape but a bad value (reported).
FastResult parseFast(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

} // namespace gcx::nct
