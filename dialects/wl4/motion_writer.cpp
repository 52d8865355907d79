#include "dialects/wl4/motion_writer.h"

#include "dialects/wl4/emitter.h"
#include "dialects/wl4/hole_writer.h"
#include "dialects/wl4/profile.h"
#include "translate/flat_writer.h"

namespace gcx::wl4 {

namespace {

// `%NAME` (wl4.md §1.2): the source's name in upper case (lower case is no program text, §1.1)
// when it is one WL4 allows for a main program (letters, digits and `_`, at most 80, not the
// one- and two-digit names of subprograms), else MAIN.
std::string unitName(const std::string& name) {
  std::string upper;
  bool digitsOnly = true;
  for (char c : name) {
    const bool digit = c >= '0' && c <= '9';
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    if (!digit && !(c >= 'A' && c <= 'Z') && c != '_') return "MAIN";
    digitsOnly = digitsOnly && digit;
    upper += c;
  }
  const bool ok = !upper.empty() && upper.size() <= 80 && !(digitsOnly && upper.size() <= 2);
  return ok ? upper : "MAIN";
}

} // namespace

std::unique_ptr<emit::MotionWriter>
makeMotionWriter(std::ostream& out, const emit::MotionWriterOptions& opt, diag::Engine& diags) {
  emit::FlatSyntax s;
  s.profile = &profile();
  s.label = "WL4";
  s.decimals = 3; // resolution 0.001 mm (002:40); more decimals are rounded when used
  s.programName = unitName(opt.programName);
  s.comment = emit::lineComment;
  if (opt.keepCycles) s.holes = makeHoleWriter();
  return std::make_unique<emit::FlatWriter>(makeEmitter(out), std::move(s), opt, diags);
}

} // namespace gcx::wl4
