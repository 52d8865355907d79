// How NCT text is cut into blocks (nct.md §1.1, §1.5, §0.1).
#pragma once
#include "front/lexical_rules.h"

namespace gcx::nct {

const front::LexicalRules& lexicalRules();

} // namespace gcx::nct
