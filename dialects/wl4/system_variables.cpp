#include "dialects/wl4/system_variables.h"

#include <fmt/format.h>

#include "diag/codes.h"
#include "dialects/wl4/control_flow.h"
#include "dialects/wl4/profile.h"
#include "machine/settings.h"

namespace gcx::wl4 {

namespace {

// #101-#107: the modal groups of §2.2, by the profile's group (Table 3) they report
int tableGroup(int number) {
  switch (number) {
  case 101:
    return 1; // G0-G3, G32, G33
  case 102:
    return 3; // G40-G42
  case 103:
    return 5; // G53-G59, G92
  case 104:
    return 8; // G90/G91
  case 105:
    return 9; // G94/G95
  case 106:
    return 10; // G96/G97
  case 107:
    return 7; // G80-G89
  }
  return 0;
}

} // namespace

std::optional<macro::Value> SystemVariables::read(int number, const SourceRange& where) {
  if (const int group = tableGroup(number))
    return macro::Value::of(machine_.modalCode(group) / 10.0);
  const machine::ModalState& s = machine_.state();
  switch (number) {
  case 112: // M3-M5
    return macro::Value::of(s.spindleDirection > 0 ? 3 : s.spindleDirection < 0 ? 4 : 5);
  case 120:
    return macro::Value::of(s.lastS);
  case 114: // M7-M9
    return macro::Value::of(s.coolant);
  case 117: // M41-M48; before any, the setup's power-on gear range
    return macro::Value::of(s.gearRange != 0 ? s.gearRange
                                             : machine::setting(wl4::profile(), machine_.setup(),
                                                                Setting::PowerOnGearRange));
  case 121:
    return macro::Value::of(s.selectedTool);
  case 139:
    return macro::Value::of(s.feed);
  case 141:
    return macro::Value::of(s.lastD);
  case 200: // the tool M6 put in the spindle
    return macro::Value::of(s.tool);
  }
  if (number >= 1000 && number <= 1027 && number % 10 <= 2) { // G38's results (§3.8)
    const machine::Interpreter::ProbeResult& p = machine_.probeResult();
    const machine::Vec3& v = number < 1010 ? p.machine : number < 1020 ? p.work : p.distance;
    return macro::Value::of(v[number % 10]);
  }
  if (number == 108 || (number >= 130 && number <= 140)) {
    auto it = last_.find(number);
    return macro::Value::of(it == last_.end() ? 0.0 : it->second);
  }
  diags_.error(diag::code::SystemReadOnly, where,
               fmt::format("system variable #{} is not modelled by gcx (wl4.md §6.2)", number));
  return std::nullopt;
}

bool SystemVariables::write(int number, const macro::Value&, const SourceRange& where) {
  diags_.error(
      diag::code::SystemReadOnly, where,
      fmt::format("#{} is a system variable: #100 and up are read-only (wl4.md §6.1)", number));
  return false;
}

std::optional<macro::Value> SystemVariables::readNamed(const std::string& name, std::optional<int>,
                                                       const SourceRange& where) {
  diags_.error(diag::code::SystemReadOnly, where,
               fmt::format("#_{}: WL4 has no named variables", name));
  return std::nullopt;
}

bool SystemVariables::writeNamed(const std::string& name, std::optional<int>, const macro::Value&,
                                 const SourceRange& where) {
  diags_.error(diag::code::SystemReadOnly, where,
               fmt::format("#_{}: WL4 has no named variables", name));
  return false;
}

bool SystemVariables::openCycle(const ir::Block& flat, const ir::Word& code) {
  last_[108] = static_cast<int>(code.number);
  takeTarget(flat);
  // G31's I and P: omitted means 0 (002:2539-2541), not an earlier block's value (§10.11)
  const ir::Word* i = flat.find('I');
  const ir::Word* p = flat.find('P');
  last_[136] = i ? i->number : 0;
  last_[140] = p ? p->number : 0;
  return true;
}

void SystemVariables::blockRuns(const ir::Block& flat) {
  for (const ir::Word& w : flat.words) // the internal cycles are group #108's too (§2.2, §5.6)
    if (w.is('G') && (w.number == 76 || ((w.number == 77 || w.number == 78) && flat.find('P'))))
      last_[108] = w.number;
  const char* centres = "IJK";
  for (int a = 0; a < 3; ++a)
    if (const ir::Word* w = flat.find(centres[a])) last_[136 + a] = w->number;
  if (const ir::Word* p = flat.find('P')) last_[140] = p->number;
  if (!axisWordsNoMove(flat) && (flat.find('X') || flat.find('Y') || flat.find('Z') ||
                                 flat.find('U') || flat.find('V') || flat.find('W')))
    takeTarget(flat);
}

void SystemVariables::takeTarget(const ir::Block& flat) {
  machine::Vec3 at = machine_.programPosition();
  bool incremental = machine_.state().incremental;
  bool allowances = false; // G76's U W are its initial allowance, no increments (§5.6)
  for (const ir::Word& w : flat.words) { // the block's own G90/G91 counts for its words
    if (w.is('G') && (w.number == 90 || w.number == 91)) incremental = w.number == 91;
    if (w.is('G') && w.number == 76) allowances = true;
  }
  if (machine_.state().diameterAxes & 1u) at[0] *= 2; // #130/#131 as the X words: diameters
  const char* absolute = "XYZ";
  const char* relative = "UVW";
  for (int a = 0; a < 3; ++a) {
    double target = at[a];
    if (const ir::Word* w = flat.find(absolute[a]))
      target = incremental ? at[a] + w->number : w->number;
    if (const ir::Word* w = flat.find(relative[a]); w && !allowances) target = at[a] + w->number;
    last_[130 + 2 * a] = target;         // #130 #132 #134: the target
    last_[131 + 2 * a] = target - at[a]; // #131 #133 #135: the increment from here
  }
}

} // namespace gcx::wl4
