#include "translate/structure_scan.h"

#include <algorithm>

#include "dialect/control_flow.h"

namespace gcx::xlate {

namespace {

// What a remapped code starts: a call of a cycle program (WL4 G81 runs %81, named by its own
// digits), of a subprogram, or a repeated fragment (FMS-3000 G25).
std::optional<Structure> remapped(const Remap& r) {
  if (r.onlyIfProgramExists) return std::nullopt; // FMS-3000 G<n>: the built-in code without one
  switch (r.action) {
  case FlowAction::CallSubprogram:
  case FlowAction::CallMacro:
  case FlowAction::ModalCallEveryBlock:
    return Structure::Subprogram;
  case FlowAction::ModalCall:
    return r.program == ProgramSource::CodeDigits ? Structure::Cycle : Structure::Subprogram;
  case FlowAction::CallCycle:
  case FlowAction::CallOpenCycle:
    return Structure::Cycle;
  case FlowAction::RepeatStart:
    return Structure::Loop;
  default:
    return std::nullopt;
  }
}

std::optional<Structure> ofStatement(const ir::Stmt& s) {
  switch (s.kind) {
  case ir::StmtKind::Assign:
  case ir::StmtKind::IfThen:
  case ir::StmtKind::Guard:
    return Structure::Variable;
  case ir::StmtKind::Goto:
  case ir::StmtKind::IfGoto:
  case ir::StmtKind::While:
  case ir::StmtKind::Do:
  case ir::StmtKind::Jump:
    return Structure::Loop;
  case ir::StmtKind::Call:
    return Structure::Subprogram;
  case ir::StmtKind::CycleCall:
    return Structure::Cycle;
  default:
    return std::nullopt;
  }
}

} // namespace

std::string_view structureName(Structure s) {
  switch (s) {
  case Structure::Cycle:
    return "cycles";
  case Structure::Subprogram:
    return "subprogram calls";
  case Structure::Loop:
    return "loops and jumps";
  case Structure::Variable:
    return "variables";
  }
  return "cycles";
}

std::vector<StructureAt> scanStructures(const std::vector<ir::Block>& blocks, const Profile& p) {
  std::vector<StructureAt> out;
  for (const ir::Block& b : blocks) {
    std::vector<Structure> kinds;
    for (const ir::Word& w : b.words) {
      if (!w.isLiteral()) kinds.push_back(Structure::Variable);
      if (!w.isLiteral() || w.address.empty()) continue;
      if (w.is('G'))
        if (const GCodeSpec* g = p.gcode(w.number); // the table's own lookup: any value is safe
            g && (g->action == GAction::DrillCycle || g->action == GAction::LevelDrillCycle ||
                  g->action == GAction::TurningCycle))
          kinds.push_back(Structure::Cycle);
      if (p.controlFlow && p.controlFlow->remaps.mayMatch(w.address))
        if (const Remap* r = p.controlFlow->remaps.find(w.address, w.number))
          if (const std::optional<Structure> s = remapped(*r)) kinds.push_back(*s);
    }
    for (const ir::Stmt& s : b.stmts)
      if (const std::optional<Structure> k = ofStatement(s)) kinds.push_back(*k);
    std::sort(kinds.begin(), kinds.end());
    kinds.erase(std::unique(kinds.begin(), kinds.end()), kinds.end());
    for (Structure k : kinds)
      out.push_back({k, b.range.begin});
  }
  return out;
}

} // namespace gcx::xlate
