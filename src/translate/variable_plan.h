// The variables of a program translated to another dialect: which number each source variable
// gets in the target's space, so that what the source shares between a caller and its callee stays
// shared, and what it starts with (a vacant variable, or 0) stays the same.
#pragma once
#include <map>
#include <vector>

#include "dialect/control_flow.h"
#include "translate/steps.h"

namespace gcx::xlate {

struct VariablePlan {
  std::map<int, int> renumber;  // source variable -> target variable
  std::vector<int> zeroAtStart; // target variables the main program sets to 0 first
  std::vector<int> counters;    // free target variables for counted loops, in the order taken
};

/// Plans the variables of `units` (the main program first) between the two control-flow tables,
/// with `counters` free target variables beside them; false with the first variable that has no
/// place of the same meaning in `why`.
bool planVariables(const std::vector<UnitSteps>& units, const ControlFlow& source,
                   const ControlFlow& target, int counters, VariablePlan& plan, Unkept& why);

/// Calls f(variable number, its range, written) for every variable a step reads or writes.
void forEachVariable(const Step& s, const std::function<void(int, const SourceRange&, bool)>& f);

} // namespace gcx::xlate
