// The control-flow engine (docs/control-flow.md): walks a program's jumps, loops, calls, modal
// calls and repeat counts while it drives the machine model, so system variables read the true
// state, and hands flat blocks (all word values literal) with their provenance to the
// interpreter. What each code does, how variables are laid out, how a call binds its arguments
// and how a program is found come from the dialect's ControlFlow (dialect/control_flow.h).
// The methods live in files of one job each: expander.cpp (the run), nc_blocks.cpp (flat
// blocks and the remap table), calls.cpp, modal_calls.cpp, configured_calls.cpp, loops.cpp,
// jumps.cpp, variables.cpp and print.cpp.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "dialect/control_flow.h"
#include "machine/interpreter.h"
#include "passes/macro/evaluator.h"
#include "passes/macro/frames.h"
#include "passes/macro/program_library.h"
#include "passes/macro/system_variable_store.h"
#include "passes/macro/word_values.h"

namespace gcx::macro {

/// Configurable limits: a runaway loop or recursion stops with a located error naming it.
struct Limits {
  std::uint64_t maxJumps = 1'500'000;   // backward jumps (loop ends, jumps, returns, repeats)
  std::uint64_t maxBlocks = 20'000'000; // blocks executed per run
  int maxDepth = 16;                    // nested call levels (NCT: nct-macro.md V5)
};

class Expander : public VariableAccess {
public:
  /// The system variables come from the dialect (ControlFlow::systemVariables).
  Expander(ProgramLibrary& library, machine::Interpreter& machine, diag::Engine& diags,
           Limits limits = {});
  ~Expander() override;

  /// Runs the main program to its end (program end code, end of file). False after an error.
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
  bool assignsInExpressions() const override { return flow_.assignsInExpressions; }
  bool write(int number, const Value& v, const SourceRange& where) override;

private:
  /// A remapped code found in a flat block, with the words its row names.
  struct CodeMatch {
    const Remap* row = nullptr;
    const ir::Word* code = nullptr;
    const ir::Word* program = nullptr; // the row's program word
    const ir::Word* repeat = nullptr;  // the row's repeat word
    const ir::Word* file = nullptr;    // a `<file>` word, when the row takes one
  };

  // expander.cpp: the run
  bool step();
  bool endOfProgram(const Frame& f);
  motion::Provenance provenance(const ir::Block& b) const;
  /// provenance(b) written into p, whose storage is reused: one per executed block.
  void fillProvenance(const ir::Block& b, motion::Provenance& p) const;
  bool fail(const char* code, const SourceRange& where, std::string message);
  ParameterLookup parameters() const;
  const ControlFlow& flow() const { return flow_; }

  // loops.cpp, jumps.cpp: statements that move the program counter
  bool statement(Frame& f, const ir::Block& b);
  bool loopHead(Frame& f, const ir::Stmt& s);
  bool loopBack(Frame& f, std::size_t head, const SourceRange& where);
  bool jumpTo(Frame& f, const ir::Expr& label, const SourceRange& where);
  /// The block ends: its tail (a call, then a jump) if it has one, else the next block.
  bool advance(Frame& f);

  // ordered_blocks.cpp: blocks whose words and statements run left to right (WL4)
  static bool runsInOrder(const ir::Block& b);
  bool orderedBlock(Frame& f, const ir::Block& b);
  bool tailCall(const Frame& f, const ir::Stmt& s, BlockTail& tail);
  bool tailJump(const Frame& f, const ir::Stmt& s, BlockTail& tail);

  // variables.cpp
  bool assign(const ir::Stmt& s);
  bool write(int number, const Value& v, const ir::Stmt& s);
  bool store(int number, const Value& v, const SourceRange& where);
  bool message(const ir::Stmt& s, const MessageRule& rule, int variable, const Value& v);
  Value* locals() { return frames_.top(stack_.back().level); }

  // print.cpp
  bool print(const ir::Stmt& s);

  // nc_blocks.cpp: flat blocks and the remap table
  bool ncBlock(Frame& f, const ir::Block& b);
  /// Every word of b resolved to a literal (or dropped when vacant); false after reporting.
  bool flatten(const ir::Block& b, ir::Block& flat);
  /// Whether b's words may hold a remapped code (sets remapped_), and how its words round.
  WordOptions scanRemaps(const ir::Block& b);
  /// w resolved to a literal and added to flat (or dropped when vacant); false after reporting.
  bool resolveWord(const ir::Word& w, const WordOptions& opt, ir::Block& flat);
  /// A flat block through the remap table: a call, return, modal call or the machine.
  bool ncFlat(Frame& f, const ir::Block& b, ir::Block& flat);
  /// The interpreter's ContourSource: blocks ns..nf of the running program, flat.
  bool contour(std::int64_t ns, std::int64_t nf, std::vector<machine::ContourBlock>& out);
  CodeMatch match(const ir::Word& w, const ir::Block& flat) const;
  /// Runs the block's other words first (a call's NC part); false when the run stops.
  bool runNcPart(const ir::Block& b, ir::Block nc, bool& stopped);
  bool execute(Frame& f, const ir::Block& b, const ir::Block& flat);

  // calls.cpp: calls, returns and repeat counts
  bool call(Frame& f, const ir::Block& b, const CodeMatch& m);
  /// Binds a call's arguments into a new local frame; false after reporting.
  bool bind(const CallSite& site, std::vector<Value>& args);
  bool pushFrame(Frame& f, const LoadedProgram* program, LocalFrame frame, std::vector<Value> args,
                 std::int64_t times, std::string what, const SourceRange& site,
                 std::size_t modalVisible);
  bool returnFromCall(Frame& f, const ir::Block& flat, const CodeMatch& m);
  /// A repeated fragment's first or last block, after its NC part ran (repeats.cpp).
  bool repeatBlock(Frame& f, const ir::Block& flat, const CodeMatch& m);
  std::string describe(const CodeMatch& m, const std::string& unit) const;
  bool tooDeep(const SourceRange& where);
  /// A block with a message that jumps to itself: true after reporting the error its message
  /// names (ordered_blocks.cpp).
  bool errorStop(const Frame& f);
  /// A literal M word of the profile's program stop (M0).
  bool hasProgramStop(const ir::Block& b) const;
  /// FlowAction::CallOpenCycle (open_cycles.cpp).
  bool openCycleCall(Frame& f, const ir::Block& b, const ir::Block& flat, const CodeMatch& m);

  // modal_calls.cpp
  bool modalBlock(Frame& f, const ir::Block& b, const ir::Block& flat, const CodeMatch& m);
  bool everyBlockCall(Frame& f, const ir::Block& b, const ir::Block& flat, const ModalCall& m);
  const ModalCall* visibleModalCall() const;

  // configured_calls.cpp
  bool runConfiguredCall(Frame& f, const ir::Block& b, const ir::Block& flat,
                         const ConfiguredCall& c);
  bool insideConfiguredCall() const;

  ProgramLibrary& library_;
  machine::Interpreter& machine_;
  const ControlFlow& flow_;
  std::unique_ptr<SystemVariableStore> system_;
  diag::Engine& diags_;
  Limits limits_;
  Evaluator eval_;
  std::vector<Frame> stack_;
  std::vector<ModalCall> modalCalls_;
  LocalFrames frames_;
  std::map<int, Value> commons_;
  std::uint64_t jumps_ = 0, blocks_ = 0;
  std::ostream* print_ = nullptr;
  enum class Periphery { Closed, AwaitingName, Open } periphery_ = Periphery::Closed;
  std::function<void(const ir::Block&)> onFlat_;
  bool done_ = false;
  bool remapped_ = false; // the block flatten saw last may hold a remapped code
  // ncBlock's flat block and the provenance of the block being executed: members, so that
  // their storage serves every block (ncBlock does not nest)
  ir::Block flat_;
  motion::Provenance here_;
};

/// True if a program file may need the expansion pass (the dialect's expansion markers, or a
/// variable or expression); plain files are run streaming instead. A cheap byte scan: false
/// positives only cost memory. Only markers that begin at file offsets in [begin, end) count,
/// so two threads may scan the two halves of a file at once.
bool mayNeedExpansion(const std::string& path, const Profile& profile, std::uint64_t begin = 0,
                      std::uint64_t end = UINT64_MAX);

} // namespace gcx::macro
