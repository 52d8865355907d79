// Runs NCT text on the interpreter and describes the motion compactly, in the notation of the
// spec's test vectors: "R 100,0,30" (rapid to), "L 20,50,0 F100" (feed to),
// "CCW 60,90,0 C60,20 r70 θ90" (arc to, centre in the plane, radius, sweep in degrees),
// "DW 2s", "EV S1000 M3".
#pragma once
#include <string>
#include <vector>

#include "machine/setup.h"
#include "motion/event.h"
#include "support/test_support.h"

namespace gcx::test {

struct ProgramRun {
  std::vector<motion::Event> events;
  motion::Vec3 program = motion::Vec3::Zero(); // programmed position at the end (work frame)
  std::vector<std::string> errors;             // "line:col CODE"
  std::vector<std::string> warnings;           // runMacro*: "file:line:col CODE"
  std::string rendered;
  std::vector<std::string> motion() const; // descriptions of the events, modal changes left out
  std::vector<std::string> all() const;    // every event, modal changes included
};

/// Runs text through the NCT front end, static checks and interpreter; events also go to
/// `also` when given (an emitter, a plotter).
ProgramRun runNct(const std::string& text, const machine::Setup& setup = {},
                  motion::Sink* also = nullptr);
std::string describe(const motion::Event& e);
/// Number rounded to 4 decimals, trailing zeros removed.
std::string n4(double v);

} // namespace gcx::test

#include <map>

#include "passes/macro/value.h"

namespace gcx {
struct Dialect;
}
namespace gcx::macro {
struct Limits;
}

namespace gcx::test {

/// A macro program run through the expansion pass: files (name -> text) are written to a fresh
/// temporary folder; `main` is run; the values of the `watch` variables are read at the end.
/// `libraryDirs` (`--lib`) are folders of that temporary folder.
struct MacroRun : ProgramRun {
  std::map<int, macro::Value> vars;
  std::string printed; // DPRNT output
};
MacroRun runMacro(const std::map<std::string, std::string>& files, const std::string& main,
                  const std::vector<int>& watch = {}, const machine::Setup& setup = {},
                  std::uint64_t maxJumps = 100000,
                  const std::vector<std::string>& libraryDirs = {});
/// The same under the given limits on jumps, blocks and call depth (`--max-jumps` ...).
MacroRun runMacroLimited(const std::map<std::string, std::string>& files, const std::string& main,
                         const macro::Limits& limits);
/// The same through another dialect's profile and program lookup (NCT syntax, its own
/// ControlFlow): the control-flow engine under hand-made remap tables.
MacroRun runMacroAs(const Dialect& dialect, const std::map<std::string, std::string>& files,
                    const std::string& main, const std::vector<int>& watch = {});
/// The same with a machine setup (another dialect's own programs and parameters).
MacroRun runMacroWith(const Dialect& dialect, const std::map<std::string, std::string>& files,
                      const std::string& main, const machine::Setup& setup);
/// The same with a machine setup and limits.
MacroRun runMacroAs(const Dialect& dialect, const std::map<std::string, std::string>& files,
                    const std::string& main, const std::vector<int>& watch,
                    const machine::Setup& setup, const macro::Limits& limits);

} // namespace gcx::test
