// How WL4 text is cut into blocks (wl4.md §1.1-§1.6): `$` comments to the end of the line, `.`
// messages, upper case outside comments, KOI8-R files, 80-character blocks.
#pragma once
#include "front/lexical_rules.h"

namespace gcx::wl4 {

const front::LexicalRules& lexicalRules();

} // namespace gcx::wl4
