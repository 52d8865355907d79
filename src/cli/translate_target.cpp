#include "cli/translate_target.h"

#include <fmt/format.h>
#include <vector>

namespace gcx::cli {

namespace {

// "subprograms, loops and variables": the constructs the expansion flattens (it keeps only
// canned cycles, where the target has them)
std::string flattened(const emit::Capabilities& target) {
  std::vector<std::string> names;
  for (emit::Construct c : emit::kAllConstructs)
    if (c != emit::Construct::CannedCycles || !target.has(c))
      names.emplace_back(emit::constructName(c));
  if (names.empty()) return {};
  std::string out = names.front();
  for (std::size_t i = 1; i < names.size(); ++i)
    out += (i + 1 == names.size() ? " and " : ", ") + names[i];
  return out;
}

} // namespace

std::string translateTargetNames() {
  std::string names = "canonical, ngc";
  for (const std::string& d : dialectNames())
    names += ", " + d;
  return names;
}

std::optional<TranslateTarget> translateTarget(const Dialect& source, const std::string& to,
                                               std::string& why) {
  TranslateTarget t;
  t.name = to;
  t.extension = ".ngc";
  t.expandTo = "canonical";
  if (to == "canonical") return t; // flat motion by definition: nothing to note
  if (to == "ngc") {
    // LinuxCNC's own structure (O-word subroutines and loops, G81-G89) needs an emitter that
    // proves each construct means the same there; until it exists the motion is written flat
    t.note = "written as plain G0-G3 motion: keeping cycles, subprograms, loops and variables "
             "as LinuxCNC O-words and G81-G89 is not implemented yet";
    return t;
  }
  const Dialect* target = findDialect(to);
  if (!target) {
    why = fmt::format("--to {}: the targets are {}", to, translateTargetNames());
    return std::nullopt;
  }
  if (target->name != source.name) {
    // the same code means other things in another dialect (FMS-3000 G04 E is tenths of a second,
    // NCT G4 P seconds): a copy would look right and move wrong
    why = fmt::format("translating {} to {} is not implemented yet: the {} emitter does not map "
                      "{}'s codes to their meaning (--to canonical or --to ngc writes the motion, "
                      "proven equivalent)",
                      source.name, target->name, target->name, source.name);
    return std::nullopt;
  }
  t.dialect = target;
  t.expandTo = target->name;
  t.extension = target->extensions.empty() ? "" : target->extensions.front();
  if (target->keepsStructureToItself) { // the program as written: every structure kept
    t.printSource = true;
    return t;
  }
  const std::string flat = flattened(target->emits());
  if (!flat.empty()) t.note = fmt::format("{} expanded into the blocks they run", flat);
  return t;
}

} // namespace gcx::cli
