#include "dialects/wl4/control_flow.h"

#include "diag/codes.h"
#include "dialects/wl4/system_programs.h"
#include "dialects/wl4/system_variables.h"
#include "dialects/wl4/word_value_rules.h"
#include "ir/block.h"

namespace gcx::wl4 {

namespace {

RemapTable remaps() {
  RemapTable t;
  Remap back;
  back.address = "M";
  back.code = 99;
  back.action = FlowAction::Return;
  back.spec = "wl4.md §6.7";
  t.rows.push_back(back);
  // G81-G89 select the cycle; every later block with axis words runs its own motion, then
  // program %8n with a copy of the locals, until G80 (§5.1)
  for (int g = 81; g <= 89; ++g) {
    Remap cycle;
    cycle.address = "G";
    cycle.code = g;
    cycle.action = FlowAction::ModalCall;
    cycle.program = ProgramSource::CodeDigits;
    cycle.frame = LocalFrame::Copy;
    cycle.registerRunsBlock = true;
    cycle.replacesModalCall = true; // one cycle at a time in group 7
    cycle.modalGroup = 7;
    cycle.modalCode10 = g * 10;
    cycle.spec = "wl4.md §5.1";
    t.rows.push_back(cycle);
  }
  // G31, G70-G75, G77, G78: the block's axis words are the target of system program %1, which
  // does all the moving, dispatched on #108 (§5.1, §5.3); G79 too, for which %1 has no section:
  // it stops with "UNKNOWN CYCLE IN RANGE G70-G79". G77/G78 with P are the internal contour
  // cycles the machine runs (the profile's G-code table, §5.6)
  for (int g : {31, 70, 71, 72, 73, 74, 75, 77, 78, 79}) {
    Remap open;
    open.address = "G";
    open.code = g;
    open.action = FlowAction::CallOpenCycle;
    open.program = ProgramSource::Fixed;
    open.fixedProgram = "1";
    open.frame = LocalFrame::Copy;
    open.cycleWords = "IP"; // G31: lead increment and phase (#136, #140)
    if (g == 77 || g == 78) open.unlessWord = 'P';
    open.spec = "wl4.md §5.1";
    t.rows.push_back(open);
  }
  Remap cancel;
  cancel.address = "G";
  cancel.code = 80;
  cancel.action = FlowAction::ModalCancel;
  cancel.modalGroup = 7;
  cancel.modalCode10 = 800;
  cancel.spec = "wl4.md §5.1";
  t.rows.push_back(cancel);
  return t;
}

} // namespace

// no canned cycle runs after such a block (§5.1), and it leaves #130-#135 alone (§6.2)
bool axisWordsNoMove(const ir::Block& flat) {
  for (const ir::Word& w : flat.words)
    if (w.is('G') && w.isLiteral() &&
        (w.number == 4 || w.number == 36 || w.number == 51 || w.number == 92))
      return true;
  return false;
}

bool isLabel(std::string_view sequenceText) {
  return sequenceText.size() > 1 && sequenceText[0] == '0';
}

const ControlFlow& controlFlow() {
  static const ControlFlow flow = [] {
    ControlFlow f;
    f.remaps = remaps();
    f.variables = VariableSpace{1, 29, 30, 99}; // locals, globals; system from #100 (§6.1)
    f.variables.vacant = false;                 // user variables are 0 at the start
    f.wordValues = wordValueRules();            // §6.1: integers and 0.001
    f.expansionMarkers = {"%"};                 // every file is a sequence of %-programs
    f.namedUnits = true;
    f.callFrame = LocalFrame::Copy; // L: the callee gets a copy of the caller's locals (§6.7)
    f.assignsInExpressions = true;  // X#1=(...) (§6.4)
    f.isLabel = &isLabel;
    f.programFiles = [](const std::string& unit, const std::string& ext) {
      return std::vector<std::string>{unit + ext};
    };
    f.programLabel = [](const std::string& unit) { return "%" + unit; };
    f.systemProgram = &systemProgram; // %1, %81-%89 (§5.2, §5.4)
    f.systemVariables = [](machine::Interpreter& m, diag::Engine& d) {
      return std::unique_ptr<macro::SystemVariableStore>(std::make_unique<SystemVariables>(m, d));
    };
    f.axisWordsNoMove = &axisWordsNoMove;
    f.returnInMainError = diag::code::Wl4ReturnInMain; // M99 in the main program (§6.7)
    f.maxCallDepth = 5; // the main program and 5 levels; cycles and %1 count (§6.7)
    return f;
  }();
  return flow;
}

} // namespace gcx::wl4
