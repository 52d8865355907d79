// FMS-3000 programs through the real front end: parsed (reader and static checks, as
// `gcx check`), printed back (`gcx fmt`), and run through the control-flow engine and the
// machine (as `gcx run`), with the test state S0 of fms3000.md §8.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "support/run_support.h"
#include "support/test_support.h"

namespace gcx::test {

/// A program in the spec's notation, blocks separated by " · " (fms3000.md §8), as CR LF lines.
std::string specBlocks(const std::string& spec);
Parsed parseFms(const std::string& text);
/// Each block as `gcx fmt` writes it (without the CR LF).
std::vector<std::string> printedFms(const Parsed& p);
/// `main` is "main.fms" among files; the motion as run_support describes it.
MacroRun runFms(const std::map<std::string, std::string>& files, const machine::Setup& setup = {});
MacroRun runFms(const std::string& main, const machine::Setup& setup = {});

} // namespace gcx::test
