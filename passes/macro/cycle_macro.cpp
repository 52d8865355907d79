#include "passes/macro/cycle_macro.h"

#include <filesystem>
#include <fmt/format.h>

#include "emit/number.h"
#include "machine/code_names.h"

namespace gcx::macro {

namespace {

bool checkArguments(const CycleMacro& cycle, const CycleMacroSite& site,
                    const machine::Interpreter& machine, diag::Engine& diags) {
  if (!cycle.check) return true;
  CycleMacroCall call;
  call.block = &site.block;
  call.callWord = &site.callWord;
  call.args.resize(site.args.size());
  for (std::size_t i = 1; i < site.args.size(); ++i)
    if (!site.args[i].vacant) call.args[i] = site.args[i].number;
  call.plane = machine.state().plane;
  call.planeCode =
      machine::codeName(machine.profile(), call.plane == motion::Plane::ZX   ? GAction::PlaneZX
                                           : call.plane == motion::Plane::YZ ? GAction::PlaneYZ
                                                                             : GAction::PlaneXY);
  call.inch = machine.state().inch;
  call.toolRadius = [&machine](int reg) {
    const auto& tools = machine.setup().tools;
    auto it = tools.find(reg);
    return it == tools.end() ? 0.0 : it->second.radius;
  };
  return cycle.check(call, diags);
}

} // namespace

bool checkCycleMacroCall(const CycleMacro& cycle, const CycleMacroSite& site,
                         const machine::Interpreter& machine, const ProgramLibrary& library,
                         diag::Engine& diags) {
  if (!checkArguments(cycle, site, machine, diags)) return false;
  const std::string unit = std::to_string(cycle.program);
  if (!library.locate(unit, site.caller).empty()) return true;
  const std::string file =
      library.label(unit) + std::filesystem::path(site.caller.path).extension().string();
  std::string folders;
  for (const std::string& f : library.searchFolders(site.caller))
    folders += (folders.empty() ? "" : ", ") + (f.empty() ? std::string(".") : f);
  diags.error(cycle.missingCode, site.p.range,
              fmt::format("{}{} P{} is the {}; its macro program {} was not found in {} ({}). "
                          "Supply the machine builder's {} next to the program or with --lib",
                          site.callWord.address, emit::formatNumber(site.callWord.number),
                          cycle.program, cycle.name, file, folders, cycle.spec, file));
  return false;
}

} // namespace gcx::macro
