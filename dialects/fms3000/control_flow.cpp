#include "dialects/fms3000/control_flow.h"

#include "dialects/fms3000/block_rules.h"

namespace gcx::fms3000 {

namespace {

Remap row(const char* address, std::optional<double> code, FlowAction action) {
  Remap r;
  r.address = address;
  r.code = code;
  r.action = action;
  r.spec = "fms3000.md §6.1";
  return r;
}

} // namespace

// `P019` calls program "019" after the block (the digits as written: P19 is another program);
// M99 returns; M98 ends the program (it is no call, §2.2); G<n> calls the user program "G<n>"
// when one exists, with the block's other words as arguments; GG<n> is the built-in G<n>.
RemapTable remapTable() {
  RemapTable t;
  Remap p = row("P", std::nullopt, FlowAction::CallSubprogram);
  p.program = ProgramSource::CodeDigits;
  p.parameterCode = isCycleCode; // after a cycle code P is a parameter (§6.3)
  t.rows.push_back(p);
  t.rows.push_back(row("M", 99, FlowAction::Return));
  t.rows.push_back(row("M", 98, FlowAction::EndProgram));
  // G25 L<n> ... M25: the fragment runs n times (001:358-375; L = runs, §10 Q2)
  Remap g25 = row("G", 25, FlowAction::RepeatStart);
  g25.repeatWord = 'L';
  g25.spec = "fms3000.md §6.2";
  t.rows.push_back(g25);
  Remap m25 = row("M", 25, FlowAction::RepeatEnd);
  m25.spec = "fms3000.md §6.2";
  t.rows.push_back(m25);
  Remap g = row("G", std::nullopt, FlowAction::CallMacro);
  g.program = ProgramSource::CodeDigits;
  g.namePrefix = "G";
  g.frame = LocalFrame::Arguments;
  g.onlyIfProgramExists = true;
  t.rows.push_back(g);
  Remap gg = row("GG", std::nullopt, FlowAction::Builtin);
  gg.builtin = "G";
  t.rows.push_back(gg);
  return t;
}

const ControlFlow& controlFlow() {
  static const ControlFlow flow = [] {
    ControlFlow f;
    f.remaps = remapTable();
    f.hasVariables = false; // no #-variables in the manual; user cycles are refused (FMSX01)
    f.expansionMarkers = {"P", "M98", "M99", "GG", "G25", "M25"};
    f.returnInMainEnds = true; // a subprogram run on its own ends at its M99 (§2.2)
    // a unit is the file named by its digits beside the caller: "019" -> 019.fms (§1.3)
    f.programFiles = [](const std::string& unit, const std::string& ext) {
      return std::vector<std::string>{unit + (ext.empty() ? std::string(".fms") : ext)};
    };
    f.programLabel = [](const std::string& unit) { return "program " + unit; };
    return f;
  }();
  return flow;
}

} // namespace gcx::fms3000
