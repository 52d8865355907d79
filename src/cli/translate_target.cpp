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
// (translate/flat_writer.h), every construct run out.
std::optional<TranslateTarget> otherDialect(const Dialect& target, TranslateTarget& t,
                                            std::string& why) {
  t.motionWriter = emit::motionWriterFor(target.name);
  if (!t.motionWriter) {
    why = fmt::format("translating to {} from another dialect is not implemented yet", target.name);
    return std::nullopt;
  }
  t.dialect = &target;
  t.expandTo = "canonical";
  t.extension = target.extensions.empty() ? "" : target.extensions.front();
  t.note = fmt::format("{} expanded into the motion they run: the codes of another dialect mean "
                       "other things here; machine frame, offsets and tool lengths in the "
                       "coordinates, run without a setup",
                       flattened(emit::Capabilities{}));
  return t;
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
    // LinuxCNC's own structure (O-word subroutines and loops, G81-G89) where it means the
    // same (cli/translate_ngc.h); this is what is written when it does not
    t.note = "written as plain G0-G3 motion";
    return t;
  }
  const Dialect* target = findDialect(to);
  if (!target) {
    why = fmt::format("--to {}: the targets are {}", to, translateTargetNames());
    return std::nullopt;
  }
  if (target->name != source.name) return otherDialect(*target, t, why);
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
