#include "dialects/nct/lexical_rules.h"

namespace gcx::nct {

const front::LexicalRules& lexicalRules() {
  static const front::LexicalRules rules = [] {
    front::LexicalRules r;
    // `( )` may span lines and stand between words (nct.md §1.5); `;` is no comment
    r.bracketComment = front::BracketComment{'(', ')', true};
    // "addresses may be written in lower or upper case" (nct.md §1.1)
    r.letterCase = front::LetterCase::Fold;
    // the seed's symbol font shows minus as `!`; editors write en dash or minus sign (§0.1)
    r.signAliases = {{U'!', '-', " (a symbol-font artefact, nct.md §0.1)"},
                     {U'\u2013', '-', ""},
                     {U'\u2212', '-', ""}};
    // ASCII per the manual; comments in its examples hold Cyrillic, so UTF-8 (§1.1)
    r.encoding = front::Encoding::Utf8;
    return r;
  }();
  return rules;
}

} // namespace gcx::nct
