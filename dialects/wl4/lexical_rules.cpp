#include "dialects/wl4/lexical_rules.h"

namespace gcx::wl4 {

const front::LexicalRules& lexicalRules() {
  static const front::LexicalRules rules = [] {
    front::LexicalRules r;
    // `(` is a bracket, never a comment; `$` ends the commands of a block (§1.6)
    r.lineCommentMarkers = "$";
    r.dotStartsMessage = true; // block_parser.cpp acts on it where a word would start
    // only upper-case letters outside comments (Table 1, §1.1)
    r.letterCase = front::LetterCase::ErrorOutsideComments;
    // editors write minus as U+2212 or en dash (§0.1)
    r.signAliases = {{U'\u2212', '-', " (wl4.md §0.1)"}, {U'\u2013', '-', " (wl4.md §0.1)"}};
    r.encoding = front::Encoding::Koi8R; // the media code (§1.1)
    // 80 characters a block (§1.3); the manual's own %1 exceeds it: a warning
    r.warnBlockChars = 80;
    return r;
  }();
  return rules;
}

} // namespace gcx::wl4
