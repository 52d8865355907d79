// Cutter radius compensation: the test vectors of nct.md §7 (TV18-TV20) and the rules of
// §3.17 they pin, as exact tool-centre motion (docs/compensation.md).
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(CompNctSpec_7, TV18_SquareG42) {
  ProgramRun r = runNct("N10 G54 G17 G49 M3 S500\nN20 G0 X-40 Y-40\nN30 G43 Z2 H1\n"
                        "N40 G1 Z-5 F500\nN50 G42 G0 X0 Y0 D1\nN60 G1 X60\nN70 Y60\nN80 X0\n"
                        "N90 Y0\nN100 G40 G0 X-40 Y-40\nN110 M30\n",
                        compSetup(5, 0, 0, 100));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"EV S500 M3", "R -40,-40,100", "R -40,-40,2", "L -40,-40,-5 F500", "R 0,-5,-5",
               "L 65,-5,-5 F500", "L 65,65,-5 F500", "L -5,65,-5 F500", "L -5,0,-5 F500",
               "R -40,-40,-5"}));
}

// nct.md §3.17.2 (000:7446-7472): a start-up block without plane words moves nothing; the next
// block first moves r perpendicular to its start, then to its corner with the block after it.
TEST(CompNctSpec_7, TV18_StartUpWithoutPlaneWords) {
  ProgramRun r = runNct("G17 G0 X-40 Y-40\nN50 G42 G0 D1\nN60 X0 Y0\nN70 G1 X60 F500\nN80 Y60\n"
                        "N90 G40 X60 Y80\n",
                        compSetup(5, 0, 0, 0));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()), (V{"R -40,-40,0", "R -36.4645,-43.5355,0", "R 2.0711,-5,0",
                                       "L 65,-5,0 F500", "L 65,60,0 F500", "L 60,80,0 F500"}));
}

TEST(CompNctSpec_7, TV19_ArcApproachAndFullCircle) {
  ProgramRun r = runNct("G54 G17\nN50 G0 X0 Y0\nN60 G43 Z1 H1\nN70 G1 Z-2 F1000\n"
                        "N80 G42 G0 X10 Y50 D1\nN90 G2 X60 Y0 R50\nN100 G2 I-60\n"
                        "N110 G2 X10 Y-50 R50\nN120 G40 G0 X0 Y0\n",
                        compSetup(5, 0, 0, 1));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"L 0,0,-2 F1000", "R 10,45,-2", "CW 55,0,-2 C10,0 r45 θ90",
               "CW 55,0,-2 C0,0 r55 θ360", "CW 10,-45,-2 C10,0 r45 θ90", "R 0,0,-2"}));
}

TEST(CompNctSpec_7, TV20_StartUpAndCancelWithIJ) {
  ProgramRun r = runNct("N10 G54 G17 M3 S300\nN20 G0 X0 Y0 Z100\nN30 G43 Z5 H1\nN40 G1 Z-5 F1000\n"
                        "N50 G41 G0 X100 Y0 I50 J86.603 D1\nN60 G1 X50 Y86.603\nN70 X-50\n"
                        "N80 X-100 Y0\nN90 X-50 Y-86.603\nN100 X50\nN110 X100 Y0\n"
                        "N120 G40 G0 X0 I-50 J86.603\nN130 M30\n",
                        compSetup(5, 0, 0, 100));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(
      compMotion(r.motion()),
      (V{"EV S300 M3", "R 0,0,5", "L 0,0,-5 F1000", "R 94.2265,0,-5", "L 47.1132,81.603,-5 F1000",
         "L -47.1132,81.603,-5 F1000", "L -94.2265,0,-5 F1000", "L -47.1132,-81.603,-5 F1000",
         "L 47.1132,-81.603,-5 F1000", "L 94.2265,0,-5 F1000", "R 0,0,-5"}));
}

} // namespace
} // namespace gcx::test
