// The fast path: plain word-address blocks (letters with literal numbers, `/n`, comments), the
// bulk of CAM output. It yields exactly the IR the ANTLR path yields (tests/front/
// fast_path_equivalence_test.cpp proves it on the corpus and on generated blocks) and declines
// anything else, including every block with a diagnostic, so that diagnostics always come from
// the grammar path.
#pragma once
#include "dialects/nct/block_builder.h"

namespace gcx::nct {

enum class FastResult { Parsed, Declined };

/// Parses raw into out if raw is a well-formed plain block that needs no diagnostic. Declined
/// (nothing reported, out left half-built) for anything else: a block with a bad value, a
/// number of more than 15 digits or a warned-of skip level is the grammar path's to report.
FastResult parseFast(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags);

} // namespace gcx::nct
