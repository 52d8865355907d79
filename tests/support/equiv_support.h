// Equivalence options for tests: gcx's side runs through the command line's session with the
// default options, as `gcx equiv` does.
#pragma once
#include "cli/equiv_program.h"
#include "equiv/equiv.h"

namespace gcx::test {

inline equiv::EquivOptions equivOptions() {
  equiv::EquivOptions o;
  o.gcxProgram = cli::gcxProgramMaker(cli::CommonOptions{});
  return o;
}

} // namespace gcx::test
