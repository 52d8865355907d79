// How FMS-3000 text is cut into blocks (fms3000.md §1.1): front::LexicalRules as data.
#pragma once
#include "front/lexical_rules.h"

namespace gcx::fms3000 {

const front::LexicalRules& lexicalRules();

} // namespace gcx::fms3000
