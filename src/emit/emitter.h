// A dialect as a target: a program-level emitter that writes IR blocks as the dialect's text, and
// the constructs that text can express. A pass that rewrites a program for a target (expand
// --to <dialect>) keeps a construct where the target has it and flattens it where it has not.
#pragma once
#include <initializer_list>
#include <string>
#include <string_view>

#include "ir/block.h"

namespace gcx::emit {

/// Program structure beyond flat motion blocks.
enum class Construct : unsigned char {
  CannedCycles, // a drilling or turning cycle kept as one block (G81, G71 ...)
  Subprograms,  // calls of other programs (M98, L)
  Loops,        // WHILE / repeat loops in the program text
  Variables,    // variables and expressions in words (#1, [#1+2])
  ModalCalls,   // a call repeated after every move (G66)
};
inline constexpr Construct kAllConstructs[] = {Construct::CannedCycles, Construct::Subprograms,
                                               Construct::Loops, Construct::Variables,
                                               Construct::ModalCalls};

std::string_view constructName(Construct c);

/// A set of constructs.
class Capabilities {
public:
  constexpr Capabilities() = default;
  constexpr Capabilities(std::initializer_list<Construct> constructs) {
    for (Construct c : constructs)
      bits_ |= bit(c);
  }
  constexpr bool has(Construct c) const { return (bits_ & bit(c)) != 0; }
  constexpr bool operator==(const Capabilities&) const = default;

private:
  static constexpr unsigned bit(Construct c) { return 1u << static_cast<unsigned>(c); }
  unsigned bits_ = 0;
};

/// One program unit of the output: NCT writes one per file, WL4 several (`%name` ... `%`).
struct ProgramUnit {
  std::string name; // empty: the file's only program
};

class ProgramEmitter {
public:
  virtual ~ProgramEmitter() = default;
  virtual Capabilities capabilities() const = 0;
  virtual void beginProgram(const ProgramUnit& unit) = 0;
  /// One block; its kind and words must be expressible (capabilities()).
  virtual void block(const ir::Block& b) = 0;
  virtual void endProgram() = 0;
};

} // namespace gcx::emit
