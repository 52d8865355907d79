// The macro expansion pass (nct-macro.md §2-§6): walks NCT control flow and calls while it
// drives the machine model, so system variables read the true state, and hands flat blocks
// (all word values literal) with their provenance to the interpreter.
#pragma once
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "machine/interpreter.h"
#include "passes/macro/evaluator.h"
#include "passes/macro/program_library.h"
#include "passes/macro/system_variables.h"

namespace gcx::macro {

/// Configurable limits: a runaway loop or recursion stops with a located error naming it.
struct Limits {
  std::uint64_t maxJumps = 2'000'000;   // backward jumps (END, GOTO, M99, L repeats) per run
  std::uint64_t maxBlocks = 20'000'000; // blocks executed per run
  int maxDepth = 16;                    // nested M98/G65 levels (nct-macro.md V5)
};

class Expander : public VariableAccess {
public:
  Expander(ProgramLibrary& library, machine::Interpreter& machine, SystemVariables& system,
           diag::Engine& diags, Limits limits = {});

  /// Runs the main program to its end (M2/M30, end of file). False after an error.
  bool run(const LoadedProgram& main);
  /// DPRNT/BPRNT output goes here (standard output by default in the CLI).
  void setPrintOutput(std::ostream* out) { print_ = out; }
  /// Called with every flat NC block (values literal, calls and macro statements gone) just
  /// before the machine executes it: `gcx expand --to nct --expand macros,subprograms`.
  void onFlatBlock(std::function<void(const ir::Block&)> f) { onFlat_ = std::move(f); }
  /// `--vacant-order fanuc`: vacant compares like 0 (nct-macro.md §12 Q1).
  void setVacantOrder(VacantOrder o) { eval_.setVacantOrder(o); }

  // VariableAccess
  std::optional<Value> read(int number, const SourceRange& where) override;
  std::optional<Value> readNamed(const std::string& name, std::optional<int> index,
                                 const SourceRange& where) override;
  std::optional<double> parameter(int id, std::optional<int> bit, std::optional<int> index,
                                  const SourceRange& where) override;
  std::optional<int> axisNumber(char letter, const SourceRange& where) override;

private:
  struct Loop {
    std::size_t head;        // the WHILE/DO block
    std::uint64_t iteration; // 1 on entry
  };
  struct Frame {
    const LoadedProgram* program = nullptr;
    std::size_t pc = 0;
    int level = 0;              // local-variable level (G65 opens one, M98 does not)
    std::int64_t remaining = 0; // runs left after this one (L)
    std::size_t callBlock = 0;  // index of the calling block in the caller
    SourceLoc callSite;
    std::string what;             // "M98 P11", "G65 P9010"
    std::array<Value, 34> args{}; // G65: the frame each run starts from
    std::vector<Loop> loops;
    bool macro = false;
    std::size_t modalVisible = static_cast<std::size_t>(-1); // modal calls this frame sees
    bool configured = false; // started by a code configured as a call (§5.8)
  };
  /// A G, M or letter code the parameters turn into a call (nct-macro.md §5.8).
  struct ConfiguredCall {
    enum Kind { MacroG, ModalG, MacroM, SubprogramM, SubprogramLetter } kind;
    std::int64_t program;
    const ir::Word* word;
    int valueVariable = 0; // #195-#199 for A B C S T
  };
  std::optional<ConfiguredCall> configuredCall(const ir::Block& flat);
  bool runConfiguredCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                         const ConfiguredCall& c);
  bool insideConfiguredCall() const;
  /// A G66 / G66.1 registration (nct-macro.md §5.5-§5.7).
  struct ModalCall {
    const LoadedProgram* program = nullptr;
    std::array<Value, 34> args{};
    std::int64_t times = 1;
    bool everyBlock = false; // G66.1
    std::string what;
  };

  bool step();
  bool statement(Frame& f, const ir::Block& b);
  bool assign(const ir::Stmt& s);
  bool write(int number, const Value& v, const ir::Stmt& s);
  bool jumpTo(Frame& f, const ir::Expr& label, const SourceRange& where);
  bool loopBack(Frame& f, std::size_t head, const SourceRange& where);
  bool ncBlock(Frame& f, const ir::Block& b);
  /// Every word of b resolved to a literal (or dropped when vacant); false after reporting.
  bool flatten(const ir::Block& b, ir::Block& flat);
  /// The interpreter's ContourSource: blocks ns..nf of the running program, flat.
  bool contour(std::int64_t ns, std::int64_t nf, std::vector<machine::ContourBlock>& out);
  bool callSubprogram(Frame& f, const ir::Block& b, const ir::Word* p, const ir::Word* file,
                      std::int64_t times);
  bool callMacro(Frame& f, const ir::Block& b, const ir::Word* p, const ir::Word* file,
                 std::int64_t times);
  /// Binds a call block's arguments (§5.4); the control values #10/#12/#16 where not taken.
  bool bindCall(const ir::Block& b, double callCode, const ir::Word* p, std::array<Value, 34>& args,
                bool controlPL = true);
  bool pushMacro(Frame& f, const LoadedProgram* program, const std::array<Value, 34>& args,
                 std::int64_t times, std::string what, const SourceRange& site,
                 std::size_t modalVisible);
  bool modalBlock(Frame& f, const ir::Block& b, const ir::Block& flat, const ir::Word& code);
  const ModalCall* visibleModalCall() const;
  bool returnFromCall(Frame& f, const ir::Block& b);
  bool endOfProgram(const Frame& f);
  bool print(const ir::Stmt& s);
  bool message(const ir::Stmt& s, int variable, const Value& v);
  motion::Provenance provenance(const ir::Block& b) const;
  bool fail(const char* code, const SourceRange& where, std::string message);
  std::array<Value, 34>& locals() { return locals_[stack_.back().level]; }

  ProgramLibrary& library_;
  machine::Interpreter& machine_;
  SystemVariables& system_;
  diag::Engine& diags_;
  Limits limits_;
  Evaluator eval_;
  std::vector<Frame> stack_;
  std::vector<ModalCall> modalCalls_;
  std::vector<std::array<Value, 34>> locals_;
  std::map<int, Value> commons_;
  std::uint64_t jumps_ = 0, blocks_ = 0;
  std::ostream* print_ = nullptr;
  enum class Periphery { Closed, AwaitingName, Open } periphery_ = Periphery::Closed;
  std::function<void(const ir::Block&)> onFlat_;
  bool done_ = false;
};

/// True if a program file may need the expansion pass (macro statements, calls, variables);
/// plain files are run streaming instead. A cheap byte scan: false positives only cost memory.
bool mayNeedExpansion(const std::string& path);

} // namespace gcx::macro
