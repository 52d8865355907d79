// WL4 text through the real front end (parse and static checks) or the whole run (front end,
// control-flow engine, interpreter), for the WL4 tests.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "front/encoding.h"
#include "machine/setup.h"
#include "support/run_support.h"
#include "support/test_support.h"

namespace gcx::test {

/// Parses WL4 text (UTF-8 unless `encoding` says otherwise) and runs the static checks; without
/// the fast path every block goes through the grammar (grammar/WL4.g4).
Parsed parseWl4(const std::string& text, front::Encoding encoding = front::Encoding::Utf8,
                bool fastPath = true);
/// Each block printed back as WL4 text, one string per block.
std::vector<std::string> printedWl4(const Parsed& p);
/// Runs `main` among `files` (name -> WL4 text, written in KOI8-R's ASCII subset or as given).
MacroRun runWl4(const std::map<std::string, std::string>& files, const std::string& main,
                const machine::Setup& setup = {}, const std::vector<int>& watch = {});
/// One file main.wl4.
MacroRun runWl4(const std::string& text, const machine::Setup& setup = {});
/// Errors without their file name: "line:col CODE".
std::vector<std::string> errorsAt(const MacroRun& r);
/// The lathe profile (wl4.md §0.2): setup parameter `lathe` = 1, X and U are diameters.
machine::Setup wl4Lathe();

} // namespace gcx::test
