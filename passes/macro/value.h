// Macro variable values and the variable store the evaluator reads (nct-macro.md §2).
#pragma once
#include <optional>
#include <string>

#include "ir/source.h"

namespace gcx::macro {

/// A binary64 number or the distinct vacant state (nct-macro.md §2.4, §2.5).
struct Value {
  bool vacant = true;
  double number = 0; // 0 while vacant

  static Value of(double v) { return Value{false, v}; }
  static Value empty() { return Value{}; }
  /// The number an operator or function sees: vacant counts as 0 (§2.5 rule 2).
  double orZero() const { return vacant ? 0.0 : number; }
};

/// Access to the variables, parameters and axes of the running channel; the macro pass
/// implements it. Every method returns nullopt only after reporting a located error.
class VariableAccess {
public:
  virtual ~VariableAccess() = default;
  /// Reads #n; nullopt after reporting a located error (undefined number, ...).
  virtual std::optional<Value> read(int number, const SourceRange& where) = 0;
  /// Reads #_NAME or #_NAME[index].
  virtual std::optional<Value> readNamed(const std::string& name, std::optional<int> index,
                                         const SourceRange& where) = 0;
  /// PRM[id, bit]/[index]: nullopt after reporting.
  virtual std::optional<double> parameter(int id, std::optional<int> bit, std::optional<int> index,
                                          const SourceRange& where) = 0;
  /// AXNUM[letter]: number of the axis in the channel, nullopt after reporting (2017).
  virtual std::optional<int> axisNumber(char letter, const SourceRange& where) = 0;
  /// Whether `#n=e` may stand inside an expression (WL4, wl4.md §6.4); NCT has no such form.
  virtual bool assignsInExpressions() const { return false; }
  /// Stores v in #n for an assignment inside an expression; false after reporting a located
  /// error. Called only when assignsInExpressions().
  virtual bool write(int number, const Value& v, const SourceRange& where) {
    (void)number, (void)v, (void)where;
    return false;
  }
};

} // namespace gcx::macro
