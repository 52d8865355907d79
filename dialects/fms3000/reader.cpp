#include "dialects/fms3000/reader.h"

#include <fmt/format.h>

#include "diag/codes.h"
#include "dialects/fms3000/block_rules.h"
#include "dialects/fms3000/lexical_rules.h"

namespace gcx::fms3000 {

namespace {

constexpr const char* kEndcont = "endcont";

bool isLower(char c) {
  return c >= 'a' && c <= 'z';
}

} // namespace

Reader::Reader(std::istream& in, FileId file, diag::Engine& diags, front::ReaderLimits limits,
               std::optional<front::Encoding> encoding)
    : bytes_(in, file, diags, lexicalRules(), encoding.value_or(lexicalRules().encoding), limits),
      diags_(diags) {}

bool Reader::next(ir::Block& out) {
  while (bytes_.next(raw_)) {
    if (!raw_.failed && read(out)) return true;
    ++failed_;
  }
  return false;
}

void Reader::reset(ir::Block& out) const {
  out.kind = ir::BlockKind::Normal;
  out.skipLevel = 0;
  out.sequence.reset();
  out.sequenceText.clear();
  out.sequenceRange = {};
  out.programName.clear();
  out.words.clear();
  out.stmts.clear();
  out.comments.clear();
  out.range = SourceRange{raw_.begin, static_cast<std::uint32_t>(raw_.text.size())};
  out.lastLine = raw_.lastLine();
}

bool Reader::read(ir::Block& out) {
  reset(out);
  const std::string& t = raw_.lexText;
  const std::size_t first = t.find_first_not_of(" \t");
  // `rem ...`: a comment to the end of the line (001:3343)
  if (raw_.lineCommentAt == first) {
    out.kind = ir::BlockKind::CommentLine;
    ir::Comment& c = out.comments.emplace_back();
    c.kind = ir::CommentKind::ToLineEnd;
    const std::size_t textAt = raw_.text.find_first_not_of(" \t", first + 3);
    if (textAt != std::string::npos) c.text = raw_.text.substr(textAt);
    c.range = raw_.rangeAt(first, raw_.text.size() - first);
    c.order = static_cast<std::uint32_t>(first);
    return true;
  }
  if (t.compare(first, 7, kEndcont) == 0) {
    const std::size_t after = t.find_first_not_of(" \t", first + 7);
    if (after == std::string::npos) {
      out.kind = ir::BlockKind::ContourEnd; // the end of a G164/G165 profile (001:3272)
      return true;
    }
    diags_.error(diag::code::SyntaxError, raw_.rangeAt(after, 1),
                 "'endcont' stands alone on its line (fms3000.md §6.3)");
    return false;
  }
  if (isLower(t[first])) {
    std::size_t end = first;
    while (end < t.size() && (isLower(t[end]) || (t[end] >= '0' && t[end] <= '9')))
      ++end;
    diags_.error(diag::code::FmsMacroUnsupported, raw_.rangeAt(first, end - first),
                 fmt::format("'{}' starts a statement of the user-cycle language (СПЦП), which is "
                             "not documented in the FMS-3000 manual (fms3000.md §6.4)",
                             raw_.text.substr(first, end - first)));
    return false;
  }
  if (!rejectForeignCharacters()) return false;
  if (!grammar_.parse(raw_, out, diags_)) return false;
  return checkBlockRules(out, diags_);
}

// Characters of other dialects, explained before the grammar calls them unexpected: macro
// syntax (§6.4), block skip, comments in brackets and `%` (§1.1, §10 Q17).
bool Reader::rejectForeignCharacters() {
  const std::string& t = raw_.lexText;
  const std::size_t at = t.find_first_of("#=[]/(%;");
  if (at == std::string::npos) return true;
  const char c = t[at];
  if (c == '#' || c == '=' || c == '[' || c == ']') {
    diags_.error(diag::code::FmsMacroUnsupported, raw_.rangeAt(at, 1),
                 fmt::format("'{}' belongs to the user-cycle language (СПЦП), which is not "
                             "documented in the FMS-3000 manual (fms3000.md §6.4)",
                             c));
  } else if (c == '/') {
    diags_.error(diag::code::SyntaxError, raw_.rangeAt(at, 1),
                 "unknown character '/': FMS-3000 has no block skip (fms3000.md §1.1)");
  } else if (c == '(') {
    diags_.error(diag::code::SyntaxError, raw_.rangeAt(at, 1),
                 "unknown character '(': FMS-3000 has no bracket comments; write a 'rem' line "
                 "(fms3000.md §1.1)");
  } else {
    diags_.error(diag::code::SyntaxError, raw_.rangeAt(at, 1),
                 fmt::format("unknown character '{}' (fms3000.md §1.1)", c));
  }
  return false;
}

} // namespace gcx::fms3000
