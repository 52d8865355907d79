#include "dialects/fms3000/lexical_rules.h"

namespace gcx::fms3000 {

const front::LexicalRules& lexicalRules() {
  static const front::LexicalRules rules = [] {
    front::LexicalRules r;
    // no `( )` comments: a line whose first word is `rem` is a comment (001:3343)
    r.commentLineKeywords = {"rem"};
    // upper-case addresses; lower case only in `rem` and `endcont` (001:3272); any other
    // lower-case line is the undocumented macro language, which the front end rejects (§6.4)
    r.letterCase = front::LetterCase::Keep;
    r.lowerCaseKeywords = {"endcont", "rem"};
    r.encoding = front::Encoding::Utf8; // ISO code; `rem` text may hold Cyrillic
    // at most 254 characters including CR LF (001:223)
    r.maxBlockChars = 252;
    return r;
  }();
  return rules;
}

} // namespace gcx::fms3000
