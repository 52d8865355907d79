// NCT's address table for values computed by expressions (nct-macro.md §2.6, §1.2).
#pragma once
#include "dialect/word_value_rules.h"

namespace gcx::nct {

WordValueRules wordValueRules();

} // namespace gcx::nct
