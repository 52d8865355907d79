// Round trip (fms3000.md §7, §8): an FMS-3000 program written back by the FMS-3000 emitter (what
// `gcx fmt` and `expand --to fms3000` write) reads again into the same blocks and runs into the
// same motion.
#include <gtest/gtest.h>

#include <sstream>

#include "dialect/dialect.h"
#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

std::string emitted(const Parsed& p) {
  std::ostringstream out;
  auto emitter = findDialect("fms3000")->emitter(out);
  emitter->beginProgram({});
  for (const ir::Block& b : p.blocks)
    emitter->block(b);
  emitter->endProgram();
  return out.str();
}

machine::Setup s0() {
  machine::Setup s;
  s.parameters = {{"N7001", 10}, {"N7101", 20}, {"N7201", 300}};
  s.tools[1].length = 50;
  s.workOffsets["G55"] = {500, 200, 100};
  return s;
}

// the §8 vectors gcx runs, in the spec's compact spelling (blocks on CR LF lines)
const char* const kPrograms[] = {
    "G0X200Y40\r\nG90G17G03X140Y100I-60F300\r\nG02X120Y60I-50\r\nM30\r\n",
    "G0X10Y0\r\nG2I-10F100\r\nG0X0Y0\r\nG2X10Y10R10\r\nG0X0Y0\r\nG2X10Y10R-10\r\nG3X20R-10\r\nM30"
    "\r\n",
    "X10 G90 G1 F200 Y5.5\r\nZ-.5\r\nG91 X-10. Y+0\r\nM30\r\n",
    "G1X10F100G04E25\r\nG04E5\r\nM30\r\n",
    "G91G2G10X-50Y-50I-50Z40K160F100\r\nM30\r\n",
    "G0X10\r\nG3G10X10Y0I-10Z-6K-2F100\r\nM30\r\n",
    "G1G91X10G47F100\r\nG1G91X10G48\r\nG2G91X-10G48\r\nG2G91Y10G48\r\nM30\r\n",
    "G90G55G00X100Y50Z20\r\nG53G0X0Y0\r\nX10\r\nG54G0X50Y50\r\nG92X0Y0\r\nG0X10Y10\r\nM30\r\n",
    "G0X30Y40Z100\r\nG43H1\r\nG0Z10\r\nG44H1Z10\r\nG49Z10\r\nG28X5Y5\r\nG30Z0\r\nM30\r\n",
    "G0X10\r\nG60X5\r\nG60X8\r\nG91G60X0\r\nM30\r\n",
    "G0X100Y0\r\nG67X100\r\nG90G1F100X110\r\nX140Y15\r\nG2X180I20J0\r\nG68X0\r\nG0X0Y0\r\nM30\r\n",
    "G37X0Y0A90\r\nG1X10Y0F100\r\nX10Y10\r\nG37A0\r\nG0X0Y0\r\nM30\r\n",
    "G69X2Y2\r\nG1X10Y5F100\r\nG69X1Y1\r\nG1X10Y5\r\nM30\r\n",
    "rem E34 finishing pass (R15: radius X, see T29)\r\nN110 G0 X10\r\nN120 G1 Z0 F0.5\r\nN130 X15 "
    "Z-40\r\nN140 G18 G3 "
    "X35 Z-50 R15\r\nN150 G1 X40\r\nM30\r\n",
};

class Fms3000RoundTrip : public testing::TestWithParam<const char*> {};

TEST_P(Fms3000RoundTrip, EmittedTextReadsBackIntoTheSameMotion) {
  const std::string source = GetParam();
  const Parsed p = parseFms(source);
  ASSERT_EQ(p.errors(), V{}) << p.rendered();
  const std::string text = emitted(p);
  const Parsed again = parseFms(text);
  EXPECT_EQ(again.errors(), V{}) << text;
  EXPECT_EQ(printedFms(again), printedFms(p));
  const MacroRun a = runFms(source, s0()), b = runFms(text, s0());
  ASSERT_EQ(a.errors, V{}) << a.rendered;
  EXPECT_EQ(b.errors, V{}) << b.rendered;
  EXPECT_FALSE(a.motion().empty());
  EXPECT_EQ(b.motion(), a.motion()) << text;
}

INSTANTIATE_TEST_SUITE_P(Vectors, Fms3000RoundTrip, testing::ValuesIn(kPrograms));

} // namespace
} // namespace gcx::test
