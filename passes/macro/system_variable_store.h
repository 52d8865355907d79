// The system variables of a run as the control-flow engine sees them: every number above the
// dialect's common range and every #_NAME. Each dialect implements its own (NCT:
// dialects/nct/system_variables.h) and hands it over through ControlFlow::systemVariables.
#pragma once
#include <optional>
#include <string>

#include "ir/source.h"
#include "passes/macro/value.h"

namespace gcx::macro {

class SystemVariableStore {
public:
  virtual ~SystemVariableStore() = default;
  /// Reads #n; nullopt after reporting a located error.
  virtual std::optional<Value> read(int number, const SourceRange& where) = 0;
  /// Writes #n; false after reporting a located error.
  virtual bool write(int number, const Value& v, const SourceRange& where) = 0;
  /// #_NAME / #_NAME[index]; name without "#_", any case.
  virtual std::optional<Value> readNamed(const std::string& name, std::optional<int> index,
                                         const SourceRange& where) = 0;
  virtual bool writeNamed(const std::string& name, std::optional<int> index, const Value& v,
                          const SourceRange& where) = 0;
  /// The number a symbol stands for, so a named write reaches the message rules; nullopt for
  /// symbols without a number.
  virtual std::optional<int> numberOf(const std::string& name, std::optional<int> index) const = 0;
  /// The run's main program is the file at `path` (NCT reads its number from a system variable).
  virtual void startMain(const std::string& path) = 0;
  /// An open cycle's block (FlowAction::CallOpenCycle, words evaluated) is about to call its
  /// program: the store takes its target. False after reporting a located error.
  virtual bool openCycle(const ir::Block& /*flat*/, const ir::Word& /*code*/) { return true; }
  /// An NC block (words evaluated) is about to run on the machine: a store that reports the
  /// last programmed words (WL4 #130-#140) takes them here.
  virtual void blockRuns(const ir::Block& /*flat*/) {}
};

} // namespace gcx::macro
