// The WL4 system variables #100 and up (wl4.md §2.2, §6.2): read-only, answered from the
// machine model, and the words of the last blocks: #130-#135 the target and increments of the
// last block with axis words (an open cycle's block included: the control hands them to %1,
// §5.1), #136-#138 the last I J K, #140 the last P, #108 the last open or contour cycle.
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
  /// #108 the cycle, #130-#135 its target and increments, #136 I, #140 P (§5.1).
  bool openCycle(const ir::Block& flat, const ir::Word& code) override;
  /// #130-#135 for a block with axis words that move, #136-#138 I J K, #140 P (§6.2); #108
  /// for a contour cycle (G76, G77/G78 with P, §5.6).
  void blockRuns(const ir::Block& flat) override;

private:
  machine::Interpreter& machine_;
  /// #130-#135 from the block's X Y Z U V W (lathe X a diameter), before it runs.
  void takeTarget(const ir::Block& flat);

  diag::Engine& diags_;
  std::map<int, double> last_; // #108, #130-#138, #140
};

} // namespace gcx::wl4
