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

// Another dialect: the executed motion in its syntax, each code chosen by its meaning
// (translate/flat_writer.h), drilling cycles as the target's cycles unless --expand names them,
// every other construct run out; the note names them (cli/translate_flat.h).
std::optional<TranslateTarget> otherDialect(const Dialect& target, TranslateTarget& t,
                                            const ExpandSet& expand, std::string& why) {
  t.motionWriter = emit::motionWriterFor(target.name);
  if (!t.motionWriter) {
    why = fmt::format("translating to {} from another dialect is not implemented yet", target.name);
    return std::nullopt;
  }
  t.dialect = &target;
  t.expandTo = "canonical";
  t.extension = target.extensions.empty() ? "" : target.extensions.front();
  t.keepCycles = !expand.cycles;
  return t;
}

} // namespace

NoteParts splitNote(const std::string& note) {
  // "kept as T cycles: ...; run out into motion: ...; machine frame, ..." (another dialect),
  // "kept as LinuxCNC's own: ..." or "written as plain G0-G3 motion: why" (ngc), "X expanded
  // into the blocks they run" (the same dialect)
  NoteParts p;
  std::size_t pos = 0;
  while (pos < note.size()) {
    std::size_t end = note.find("; ", pos);
    if (end == std::string::npos) end = note.size();
    const std::string part = note.substr(pos, end - pos);
    const std::size_t colon = part.find(": ");
    if (part.starts_with("kept as ") && colon != std::string::npos)
      p.kept = part.substr(colon + 2);
    else if (part.starts_with("run out into motion: "))
      p.expanded = part.substr(colon + 2);
    else if (part.starts_with("written as plain") ||
             part.find(" expanded into ") != std::string::npos)
      p.expanded = part;
    pos = end + 2;
  }
  return p;
}

std::string translateTargetNames() {
  std::string names = "canonical, ngc";
  for (const std::string& d : dialectNames())
    names += ", " + d;
  return names;
}

std::optional<ExpandSet> parseExpand(const std::string& list, std::string& why) {
  ExpandSet e;
  std::size_t pos = 0;
  while (pos <= list.size() && !list.empty()) {
    std::size_t comma = list.find(',', pos);
    if (comma == std::string::npos) comma = list.size();
    const std::string word = list.substr(pos, comma - pos);
    if (word == "all")
      e.cycles = e.subprograms = e.loops = e.variables = true;
    else if (word == "cycles")
      e.cycles = true;
    else if (word == "subprograms")
      e.subprograms = true;
    else if (word == "loops")
      e.loops = true;
    else if (word == "variables")
      e.variables = true;
    else {
      why = fmt::format("'{}' is none of cycles, subprograms, loops, variables, all", word);
      return std::nullopt;
    }
    pos = comma + 1;
  }
  return e;
}

std::optional<TranslateTarget> translateTarget(const Dialect& source, const std::string& to,
                                               const ExpandSet& expand, std::string& why) {
  TranslateTarget t;
  t.name = to;
  t.extension = ".ngc";
  t.expandTo = "canonical";
  if (to == "canonical") return t; // flat motion by definition: nothing to note
  if (to == "ngc") {
    // LinuxCNC's own structure (O-word subroutines and loops, G81-G89) where it means the
    // same (cli/translate_ngc.h); this is what is written when it does not
    t.note = expand.any() ? "written as plain G0-G3 motion as --expand asks"
                          : "written as plain G0-G3 motion";
    return t;
  }
  const Dialect* target = findDialect(to);
  if (!target) {
    why = fmt::format("--to {}: the targets are {}", to, translateTargetNames());
    return std::nullopt;
  }
  // to itself with its cycles run out: the flat motion, as for another dialect
  if (target->name != source.name || expand.cycles) return otherDialect(*target, t, expand, why);
  t.dialect = target;
  t.expandTo = target->name;
  t.extension = target->extensions.empty() ? "" : target->extensions.front();
  if (target->keepsStructureToItself && !expand.any()) { // as written: every structure kept
    t.printSource = true;
    return t;
  }
  const std::string flat = flattened(target->emits());
  if (!flat.empty()) t.note = fmt::format("{} expanded into the blocks they run", flat);
  return t;
}

} // namespace gcx::cli
