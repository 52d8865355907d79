// How a dialect's text is cut into blocks and prepared for its parser, as data: comment forms,
// letter case, sign aliases, the file encoding and block-length limits. Each dialect
// fills one in dialects/<d>/lexical_rules.cpp; the one BlockReader (front/block_reader.h) reads
// it and never asks which dialect it is reading.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "front/encoding.h"

namespace gcx::front {

/// A comment between two characters: NCT `( ... )`.
struct BracketComment {
  char open = '(';
  char close = ')';
  bool spansLines = false; // a LF inside the brackets does not end the block (nct.md §1.5)
};

enum class LetterCase : unsigned char {
  Fold,                // lower case is read as upper case (NCT: "lower or upper case")
  Keep,                // letters reach the parser as written (the parser decides)
  ErrorOutsideComments // lower case outside a comment is an error (WL4 §1.1)
};

/// A character read as a sign, with a warning: NCT's `!` (a symbol-font artefact), U+2212.
struct SignAlias {
  char32_t codePoint = 0;
  char sign = '-';
  std::string_view why; // appended to the warning, e.g. " (a symbol-font artefact, nct.md §0.1)"
};

struct LexicalRules {
  /// Comments between brackets; none in FMS-3000 and WL4 (there `(` is an error or a bracket).
  std::optional<BracketComment> bracketComment;
  /// Characters after which the rest of the line is comment (WL4 `$`).
  std::string lineCommentMarkers;
  /// Words that, written first on a line, make the whole line a comment (FMS-3000 `rem`).
  /// Matched as written (after case folding, so a folding dialect lists them in upper case).
  std::vector<std::string> commentLineKeywords;
  /// WL4: a `.` where a new word would start begins a message to the end of the line (wl4.md
  /// §1.6). Only the dialect's word lexer knows where a word starts, so the block reader does not
  /// act on this flag; it records the rule for that lexer.
  bool dotStartsMessage = false;

  LetterCase letterCase = LetterCase::Fold;
  /// Lower-case words kept as written whatever letterCase says (FMS-3000 `endcont`, `rem`).
  std::vector<std::string> lowerCaseKeywords;

  std::vector<SignAlias> signAliases;

  /// The file encoding when the command line names none (--encoding).
  Encoding encoding = Encoding::Utf8;

  // Block ends are no rule of their own: NCT, FMS-3000 and WL4 all end a block at LF, with or
  // without a CR before it (nct.md §1.1, fms3000.md §1.1, wl4.md §1.3); LF inside a comment
  // that spans lines does not end it.
  /// Warn about a CR inside a block: the file probably has CR-only line ends.
  bool warnLoneCarriageReturn = true;

  /// The dialect's own block-length rules, in characters of a line as written, CR LF not
  /// counted (0: none). Longer than maxBlockChars is an error, longer than warnBlockChars a
  /// warning. The reader's resource limit (ReaderLimits) applies besides.
  std::size_t maxBlockChars = 0;
  std::size_t warnBlockChars = 0;
};

} // namespace gcx::front
