// A program's units by meaning (translate/steps.h) written in a target dialect with their
// structure: each G and M code chosen by its action from the target's profile, words in the
// target's units (a dwell in its own unit, M S T on the side of the motion the target acts on
// them), variables renumbered (translate/variable_plan.h), expressions in the target's operators
// (translate/expression_lowering.h), calls, repeats, loops and jumps in the target's own forms
// (translate/structured_spelling.h). A construct the target cannot write with the same meaning
// is refused with the reason; nothing is approximated.
#pragma once
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "emit/emitter.h"
#include "motion/event.h"
#include "translate/steps.h"
#include "translate/structured_spelling.h"

namespace gcx::xlate {

/// One file of the result: its name (the main program's is empty: the caller's output) and text.
struct WrittenFile {
  std::string name;
  std::string text;
};

/// A structure the result keeps, with the source blocks that hold it.
struct KeptStructure {
  std::string what; // "subprogram calls", "loops", "variables"
  std::vector<SourceLoc> at;
};

struct StructuredResult {
  std::vector<WrittenFile> files; // the main program first
  std::vector<KeptStructure> kept;
};

using EmitterMaker = std::unique_ptr<emit::ProgramEmitter> (*)(std::ostream&);

/// What each run of a source block did, in the program's frame: the events of every run.
using BlockRuns = std::vector<std::vector<motion::Event>>;

struct StructuredInput {
  std::vector<UnitSteps> units; // the main program first, then every unit it calls
  const Profile* source = nullptr;
  std::string mainStem;           // the source file's name without its extension
  std::vector<std::string> notes; // comment lines at the top of the main program
  /// The runs of the block at a step's location (null: it never ran), for the holes of its
  /// drilling cycle (Step::cycle).
  std::function<const BlockRuns*(const SourceLoc&)> runs;
};

/// Writes `in` for the target; false with what it could not keep in `why`.
bool writeStructured(StructuredInput in, const StructuredSpelling& target, EmitterMaker emitter,
                     StructuredResult& out, Unkept& why);

} // namespace gcx::xlate
