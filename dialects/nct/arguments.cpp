#include "dialects/nct/arguments.h"

#include <fmt/format.h>

#include "diag/codes.h"

namespace gcx::nct {

namespace {
// Specification I: letter -> local variable (000:14580-14611); I, J, K are handled apart.
int specOneVariable(char letter) {
  static const int table[26] = {
      1,  2,  3,  7,  8,  9,  10, 11, 4,  5,  6,  12, 13, // A..M (I,J,K = first group)
      14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, // N..Z
  };
  return table[letter - 'A'];
}
} // namespace

ArgumentResult bindArguments(const ir::Block& block, const VacantValue& vacant,
                             const UnknownValue& unknown, bool controlPL) {
  ArgumentResult r;
  bool taken[34] = {};
  auto fail = [&](const ir::Word& w, const char* code, std::string msg) {
    r.offending = &w;
    r.code = code;
    r.message = std::move(msg);
    return r;
  };
  for (const ir::Word& w : block.words) {
    if (w.is('G') || (controlPL && (w.is('P') || w.is('L'))) || w.kind == ir::ValueKind::Path)
      continue;
    if (w.address.size() != 1)
      return fail(w, diag::code::ForbiddenAddress,
                  fmt::format("forbidden address {} in a macro call", w.address));
    if (w.incremental)
      return fail(w, diag::code::SyntaxError, "the incremental operator I in a macro argument");
    if (unknown && unknown(w)) return r;
    if (vacant(w)) continue;
    const char letter = w.address[0];
    int v = 0;
    if (letter == 'I' || letter == 'J' || letter == 'K') {
      const int offset = letter - 'I' + 1; // I -> 3g+1, J -> 3g+2, K -> 3g+3
      for (int g = 1; g <= 10 && !v; ++g)
        if (!taken[3 * g + offset]) v = 3 * g + offset;
      if (!v)
        return fail(
            w, diag::code::ForbiddenAddress,
            fmt::format("forbidden address {}: all ten {} groups are used", letter, letter));
    } else {
      v = specOneVariable(letter);
      if (taken[v])
        return fail(
            w, diag::code::ForbiddenAddress,
            fmt::format("forbidden address {}: variable #{} already holds an argument", letter, v));
    }
    taken[v] = true;
    r.bindings.push_back({v, &w});
  }
  return r;
}

} // namespace gcx::nct

namespace gcx::nct {

CallArguments bindCall(const CallSite& site) {
  const ir::Block& b = *site.block;
  const bool controlPL = site.kind != CallKind::ConfiguredG;
  CallArguments out;
  if (site.kind == CallKind::EveryBlock) {
    int gCount = 0;
    for (const ir::Word& w : b.words)
      if (w.is('G') && ++gCount == 2) {
        out.offending = &w;
        out.code = diag::code::ForbiddenAddress;
        out.message = "a second G code in a block under G66.1 (000:14939-14943)";
        return out;
      }
  }
  ArgumentResult bound = bindArguments(b, site.vacant, {}, controlPL);
  if (!bound.ok()) {
    out.offending = bound.offending;
    out.code = bound.code;
    out.message = std::move(bound.message);
    return out;
  }
  bool taken[34] = {};
  for (const ArgumentBinding& a : bound.bindings) {
    out.bindings.push_back({a.variable, a.word, {}, false});
    taken[a.variable] = true;
  }
  if (site.kind == CallKind::EveryBlock) { // G -> #10, L -> #12, P -> #16 (§5.6 E2)
    out.bindings.push_back({10, nullptr, {}, true});
    for (const ir::Word& w : b.words) {
      if (w.is('G')) out.bindings.push_back({10, &w, {}, false});
      if (w.is('L')) out.bindings.push_back({12, &w, {}, false});
      if (w.is('P')) out.bindings.push_back({16, &w, {}, false});
    }
    return out;
  }
  if (!taken[10]) out.bindings.push_back({10, nullptr, site.callCode, false});
  if (!controlPL) return out;
  if (!taken[16] && site.programWord) out.bindings.push_back({16, site.programWord, {}, false});
  for (const ir::Word& w : b.words)
    if (w.is('L') && !taken[12]) out.bindings.push_back({12, &w, {}, false});
  return out;
}

} // namespace gcx::nct
