// The WL4 system variables #100 and up (wl4.md §2.2, §6.2): read-only, answered from the
// machine model, and the target of the last open-cycle block (G31, G70-G78), which the control
// hands to %1 in #130-#140 (§5.1). gcx keeps #130-#140 for open-cycle blocks only: no program
// of the manual reads them elsewhere.
#pragma once
#include <map>

#include "diag/diagnostic.h"
#include "machine/interpreter.h"
#include "passes/macro/system_variable_store.h"

namespace gcx::wl4 {

class SystemVariables : public macro::SystemVariableStore {
public:
  SystemVariables(machine::Interpreter& machine, diag::Engine& diags)
      : machine_(machine), diags_(diags) {}

  std::optional<macro::Value> read(int number, const SourceRange& where) override;
  /// Always an error: #100 and up are read-only (§6.1).
  bool write(int number, const macro::Value& v, const SourceRange& where) override;
  std::optional<macro::Value> readNamed(const std::string& name, std::optional<int> index,
                                        const SourceRange& where) override;
  bool writeNamed(const std::string& name, std::optional<int> index, const macro::Value& v,
                  const SourceRange& where) override;
  std::optional<int> numberOf(const std::string&, std::optional<int>) const override {
    return std::nullopt;
  }
  void startMain(const std::string&) override {}
  /// #108 the cycle, #130-#135 its target and increments, #136 I, #139 F, #140 P (§5.1).
  bool openCycle(const ir::Block& flat, const ir::Word& code) override;

private:
  machine::Interpreter& machine_;
  diag::Engine& diags_;
  std::map<int, double> cycle_; // #108 and #130-#140 of the last open-cycle block
};

} // namespace gcx::wl4
