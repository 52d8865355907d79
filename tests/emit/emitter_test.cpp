// The program-level emitter interface and the dialect registry: what a target can express, and
// how the command line finds a dialect by name and by file extension.
#include <gtest/gtest.h>

#include <sstream>

#include "dialect/dialect.h"
#include "dialects/nct/printer.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using emit::Capabilities;
using emit::Construct;

TEST(Capabilities, HoldsExactlyTheConstructsGiven) {
  const Capabilities some{Construct::CannedCycles, Construct::Loops};
  EXPECT_TRUE(some.has(Construct::CannedCycles));
  EXPECT_TRUE(some.has(Construct::Loops));
  EXPECT_FALSE(some.has(Construct::Subprograms));
  EXPECT_FALSE(some.has(Construct::Variables));
  EXPECT_FALSE(some.has(Construct::ModalCalls));
  for (Construct c : emit::kAllConstructs)
    EXPECT_FALSE(Capabilities{}.has(c)) << emit::constructName(c);
  EXPECT_EQ(some, (Capabilities{Construct::Loops, Construct::CannedCycles}));
  EXPECT_NE(some, Capabilities{Construct::Loops});
}

TEST(Capabilities, NctExpressesEveryConstruct) {
  // nct.md §4 canned cycles, nct-macro.md: M98/G65 calls, WHILE, #variables, G66
  const Dialect& nct = *findDialect("nct");
  for (Construct c : emit::kAllConstructs)
    EXPECT_TRUE(nct.emits().has(c)) << emit::constructName(c);
  std::ostringstream out;
  EXPECT_EQ(nct.emitter(out)->capabilities(), nct.emits());
}

TEST(NctEmitter, WritesEachBlockAsTheNctPrinterDoesAndNothingElse) {
  const Parsed p = parseNct("%\nO0001\n#1=2 (SET)\nG81 X1 Y2 Z-3 R1 F100\nM30\n%\n");
  ASSERT_EQ(p.errors(), std::vector<std::string>{});
  std::ostringstream out;
  auto emitter = findDialect("nct")->emitter(out);
  emitter->beginProgram({"O0001"});
  std::string expected;
  for (const ir::Block& b : p.blocks) {
    emitter->block(b);
    expected += nct::printBlock(b) + "\n";
  }
  emitter->endProgram();
  EXPECT_EQ(out.str(), expected);
  EXPECT_EQ(out.str(), "%\nO1\n#1=2 (SET)\nG81 X1 Y2 Z-3 R1 F100\nM30\n%\n");
}

TEST(Registry, FindsDialectsByNameAndExtension) {
  EXPECT_EQ(dialectNames(), (std::vector<std::string>{"nct", "fms3000", "wl4"}));
  EXPECT_EQ(dialectForPath("PART.WL4"), findDialect("wl4"));
  ASSERT_NE(findDialect("nct"), nullptr);
  EXPECT_EQ(findDialect("nct")->name, "nct");
  EXPECT_EQ(findDialect("NCT"), nullptr);
  EXPECT_EQ(findDialect("canonical"), nullptr);
  EXPECT_EQ(dialectForPath("progs/O0001.nct"), findDialect("nct"));
  EXPECT_EQ(dialectForPath("O0001.NCT"), findDialect("nct"));
  EXPECT_EQ(dialectForPath("O0001.ngc"), nullptr);
  EXPECT_EQ(dialectForPath("nct"), nullptr);
  EXPECT_EQ(dialectForPath("progs/019.fms"), findDialect("fms3000"));
  EXPECT_EQ(dialectForPath("0019.FMS"), findDialect("fms3000"));
}

TEST(Registry, EveryDialectIsComplete) {
  for (const Dialect& d : dialects()) {
    EXPECT_FALSE(d.extensions.empty()) << d.name;
    EXPECT_NE(d.profile, nullptr) << d.name;
    EXPECT_NE(d.lexicalRules, nullptr) << d.name;
    EXPECT_NE(d.openSource, nullptr) << d.name;
    EXPECT_NE(d.emitter, nullptr) << d.name;
    EXPECT_NE(d.emits, nullptr) << d.name;
    EXPECT_FALSE(d.encoding.has_value()) << d.name << ": the registry leaves it to --encoding";
  }
}

} // namespace
} // namespace gcx::test
