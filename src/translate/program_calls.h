// The calls a program makes and how it ends, read from its blocks by meaning (the control-flow
// remap table, the machine's M codes, Call statements), so a batch can tell a subprogram, which
// runs only when a program calls it, from a main program without running either.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "dialect/profile.h"
#include "ir/block.h"

namespace gcx::xlate {

struct ProgramCalls {
  /// The programs called by a literal name (`M98 P2001`: "2001", WL4 `L0703`: "07") in source
  /// order, each once; a name computed at run time (`M98 P#1`) is not known here.
  std::vector<std::string> units;
  /// Files called by name (NCT `M98 <a.nct>`).
  std::vector<std::string> files;
  /// The program's first end is a return to a caller (NCT M99), not a program end (M30).
  bool endsByReturn = false;
  /// The code of that end as written ("M99"), for messages.
  std::string endCode;
};

/// Reads one program file block by block (nothing kept but the result): what it calls and how
/// its first end reads.
class CallScanner {
public:
  explicit CallScanner(const Profile& p) : profile_(p) {}
  void block(const ir::Block& b);
  const ProgramCalls& result() const { return out_; }

private:
  void end(bool byReturn, const ir::Word& w);
  const Profile& profile_;
  ProgramCalls out_;
  bool ended_ = false;
};

} // namespace gcx::xlate
