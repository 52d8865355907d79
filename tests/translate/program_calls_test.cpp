// The call scan a batch uses to tell subprograms from main programs (translate/program_calls.h):
// programs read by the real front end, the calls and first end found by meaning.
#include <gtest/gtest.h>

#include "dialect/dialect.h"
#include "support/test_support.h"
#include "translate/program_calls.h"

namespace gcx::test {
namespace {

xlate::ProgramCalls scanNct(const std::string& text) {
  const Parsed p = parseNct(text);
  EXPECT_EQ(p.diags.errorCount(), 0u) << p.rendered();
  xlate::CallScanner scanner(findDialect("nct")->profile());
  for (const ir::Block& b : p.blocks)
    scanner.block(b);
  return scanner.result();
}

// nct.md §5.1: M98 P names the program, L the repeats; G65 P a macro; M99 returns
TEST(ProgramCalls, NctCallsByLiteralNumberAndTheFirstEnd) {
  const xlate::ProgramCalls c = scanNct("M98 P2 L3\nG65 P9010 A1\nM98 P2\nM98 P#1\nM30\nM99\n");
  EXPECT_EQ(c.units, (std::vector<std::string>{"2", "9010"})); // P#1 is known only at run time
  EXPECT_FALSE(c.endsByReturn);
  EXPECT_EQ(c.endCode, "M30");
}

TEST(ProgramCalls, AProgramWhoseFirstEndIsM99IsASubprogram) {
  const xlate::ProgramCalls c = scanNct("G91 G1 X10 F100\nM99\nM30\n");
  EXPECT_TRUE(c.units.empty());
  EXPECT_TRUE(c.endsByReturn);
  EXPECT_EQ(c.endCode, "M99");
}

// A program word no program number has names nothing (and is converted to no integer).
TEST(ProgramCalls, AProgramWordBeyondFifteenDigitsNamesNothing) {
  ir::Block b;
  ir::Word m, p;
  m.address = "M", m.number = 98, m.text = "98";
  p.address = "P", p.number = 1e300, p.text = "1e300";
  b.words = {m, p};
  xlate::CallScanner scanner(findDialect("nct")->profile());
  scanner.block(b);
  EXPECT_TRUE(scanner.result().units.empty());
}

} // namespace
} // namespace gcx::test
