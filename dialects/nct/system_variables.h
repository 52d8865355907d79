// The NCT system variables (#0, #1000 and up, #_NAME[i]; nct-macro.md §2.9), answered from the
// machine model the expansion pass drives (§2.8: SBM=0, no look-ahead, so #42xx = #40xx).
// Lengths are read and written in the program's current units (inch under G20), angles in
// degrees. Runtime-only values come from the §2.8 stubs with warning NCTW01, once per variable.
//
// Tool offsets (§2.9.6, TOL=0): the interpreter keeps one length and one radius per register,
// geometry + wear (the G10 L10/L11 model). #11000+n / #13000+n read the wear last written by
// G10 L11 or these variables (0 otherwise); #10000+n / #12000+n read the register minus that
// wear. Writing a geometry keeps the wear; writing a wear changes the register by the
// difference. A new value takes effect when H (D) is programmed again (nct.md §2.3).
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "diag/diagnostic.h"
#include "dialects/nct/system_variable_map.h"
#include "machine/interpreter.h"
#include "passes/macro/system_variable_store.h"

namespace gcx::nct {

using macro::Value;

class SystemVariables : public macro::SystemVariableStore {
public:
  SystemVariables(machine::Interpreter& machine, diag::Engine& diags);

  /// #0 and every number from #1000 up belong here (§2.1); whether §2.9 lists the number is
  /// decided by read / write (NCTX01).
  static bool isSystem(int number) { return number == 0 || number >= 1000; }
  /// The number a symbol stands for (#_ABSIO[3] -> 100003, #_ALM -> 3000), nullopt for the
  /// symbols without one (#_M_SBK, #_CNTBS) and unknown ones: lets the expander route
  /// #_ALM / #_MSG / #_MSGSTP / #_MSGBOX writes to its message handling.
  std::optional<int> numberOf(const std::string& name, std::optional<int> index) const override {
    return sysvar::numberOf(name, index);
  }

  /// Reads #n; nullopt after reporting NCTX01 (not listed, write-only) or GCX030 (listed,
  /// not modelled).
  std::optional<Value> read(int number, const SourceRange& where) override;
  /// Writes #n: 2161 read-only, NCTX05 vacant, 2092 bit value outside 0..1 (§2.7 A2-A5),
  /// NCTX01 not listed, GCX030 listed but not modelled. False after reporting.
  bool write(int number, const Value& v, const SourceRange& where) override;
  /// #_NAME / #_NAME[index]; name without "#_", any case.
  std::optional<Value> readNamed(const std::string& name, std::optional<int> index,
                                 const SourceRange& where) override;
  bool writeNamed(const std::string& name, std::optional<int> index, const Value& v,
                  const SourceRange& where) override;

  /// #4000 #_MAINO: the running main program's number (0 if its name is not O + digits).
  void setMainProgramNumber(int number) { mainProgram_ = number; }
  /// Sets #4000 from the main program's file name: O + digits (nct-macro.md §2.9.3).
  void startMain(const std::string& path) override;

private:
  std::optional<Value> read(const sysvar::Ref& r, const std::string& label,
                            const SourceRange& where);
  bool write(const sysvar::Ref& r, const std::string& label, const Value& v,
             const SourceRange& where);
  std::optional<Value> modal(const sysvar::Ref& r, const std::string& label,
                             const SourceRange& where);
  std::optional<Value> position(const sysvar::Ref& r, const std::string& label,
                                const SourceRange& where);
  std::optional<Value> toolOffset(const sysvar::Ref& r) const;
  bool writeToolOffset(const sysvar::Ref& r, double v);
  bool writeWorkOffset(const sysvar::Ref& r, const std::string& label, double v,
                       const SourceRange& where);
  bool isWritable(const sysvar::Ref& r) const;
  /// A3: 0 -> 0, 0 < v <= 1 -> 1, otherwise 2092.
  std::optional<int> bit(double v, const std::string& label, const SourceRange& where);
  /// The §2.8 stub value of a runtime-only variable; NCTW01 the first time r is read.
  Value runtime(const sysvar::Ref& r, const std::string& label, const SourceRange& where,
                double stub, const char* what);
  bool fail(const char* code, const SourceRange& where, std::string message);
  double toUnits(double mm) const; // mm -> program units
  double toMm(double v) const;     // program units -> mm

  machine::Interpreter& machine_;
  diag::Engine& diags_;
  int mainProgram_ = 0;
  std::uint32_t outputBits_ = 0;                         // #1100-#1131, #1132
  std::array<double, 3> outputs_{};                      // #1133-#1135
  std::array<double, 2> clocks_{};                       // #3001, #3002 as last written
  std::array<unsigned, 2> control_{};                    // #3003, #3004
  std::array<double, 2> parts_{};                        // #3901, #3902
  std::map<std::pair<int, int>, double> cornerRadius_;   // (register, 0 geometry / 1 wear)
  std::map<std::pair<int, int>, double> dynamicOffsets_; // (G54.2 P, axis)
  std::set<sysvar::Ref> warned_;
};

} // namespace gcx::nct
