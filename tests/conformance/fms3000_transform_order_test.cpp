// FMS-3000 transformations act in one order, polar -> rotation -> scale -> mirror (fms3000.md
// Q6, §3.12-§3.14): mirroring goes with a rotation or scaling in force, and rotation and
// scaling end in any order (MachineRules::transformRules), unlike NCT (nct.md §3.15).
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

TEST(Fms3000Spec_Q6, MirrorGoesWithARotationAndActsLast) {
  const MacroRun r = runFms("G90 G17 G0 X0 Y0\nG37 X0 Y0 A90\nG67 X50\nG1 X10 Y0 F100\nM30\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  // X10 Y0 turned by 90 degrees to X0 Y10, then mirrored about X50
  EXPECT_EQ(r.motion(), (std::vector<std::string>{"L 100,10,0 F100", "END"}));
}

TEST(Fms3000Spec_Q6, RotationEndsWhileScalingStays) {
  const MacroRun r =
      runFms("G90 G17 G0 X0 Y0\nG37 X0 Y0 A90\nG69 X2 Y2\nG35\nG1 X10 Y0 F100\nM30\n");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (std::vector<std::string>{"L 20,0,0 F100", "END"})); // scaled by 2
}

} // namespace
} // namespace gcx::test
