// WL4's conversion of variable values to address values (wl4.md §6.1, 002:1799-1803).
#pragma once
#include "dialect/word_value_rules.h"

namespace gcx::wl4 {

WordValueRules wordValueRules();

} // namespace gcx::wl4
