// FMS-3000 machine parameters that change the meaning of words (fms3000.md §0), one test per
// spec section: the exact motion in machine coordinates under each value.
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

machine::Setup withParameter(const char* key, double value) {
  machine::Setup s;
  s.parameters[key] = value;
  return s;
}

V run(const std::string& program, const machine::Setup& setup) {
  const MacroRun r = runFms(program, setup);
  EXPECT_EQ(r.errors, V{}) << r.rendered;
  V m = r.motion();
  if (!m.empty() && m.back() == "END") m.pop_back();
  return m;
}

const std::string kG92 = "G0 X10 Y10\nG92 X100 Y50\nG0 X0 Y0\nX10\nG92 X1\nG0 X0 Y0\nM30\n";

TEST(Fms3000Machine_3_10, G92WithN3031ZeroNamesTheToolsPosition) {
  // the tool at machine (10,10) becomes (100,50): the origin at (-90,-40); then the tool at
  // machine X-80 becomes X1
  EXPECT_EQ(run(kG92, withParameter("N3031", 0)),
            (V{"R 10,10,0", "R -90,-40,0", "R -80,-40,0", "R -81,-40,0"}));
}

TEST(Fms3000Machine_3_10, G92WithN3031OneIsAnOriginFromMachineZero) {
  // like G54-G59 (001:1789-1800, Fig 29): the origin at machine (100,50), then X at 1
  EXPECT_EQ(run(kG92, withParameter("N3031", 1)),
            (V{"R 10,10,0", "R 100,50,0", "R 110,50,0", "R 1,50,0"}));
}

TEST(Fms3000Machine_3_10, G92WithN3031TwoShiftsTheOriginAndAddsUp) {
  // successive G92 add their shifts (Fig 30): the origin at (100,50), then at (101,50)
  EXPECT_EQ(run(kG92, withParameter("N3031", 2)),
            (V{"R 10,10,0", "R 100,50,0", "R 110,50,0", "R 101,50,0"}));
}

TEST(Fms3000Machine_3_10, N3031OutsideZeroToTwoIsALocatedError) {
  EXPECT_EQ(runFms(kG92, withParameter("N3031", 3)).errors, V{"main.fms:2:1 2002"});
}

} // namespace
} // namespace gcx::test
