// Fixed cases found by the compensation properties (comp_property_test.cpp), as exact
// tool-centre motion (docs/compensation.md).
#include <gtest/gtest.h>

#include "machine/comp_support.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

// nct.md §3.17.2 (000:7446-7472): the triangle (60,0) (-60,0) (-30,-51.962) with edge 0 through
// the origin. The inside start-up from the origin to the middle of edge 0 has no displacement,
// so it moves nothing; the first edge's block first moves r perpendicular to its start (the
// tool's side, inside the triangle), then runs on its offset. The G40 block, the last, has no
// displacement either: the last edge ends on its end perpendicular (000:7889-7915), not on the
// contour.
TEST(CompNctSpec_3_17_2, StartUpOnTheContourMovesInTheNextBlock) {
  ProgramRun r = runNct("G17 G90 G0 X0.0000 Y0.0000\nG41 G1 X0.0000 Y0.0000 D1 F1000\n"
                        "G1 X-60.0000 Y0.0000\nG1 X-30.0000 Y-51.9620\nG1 X60.0000 Y0.0000\n"
                        "G1 X0.0000 Y0.0000\nG40 G1 X0.0000 Y0.0000\n",
                        compSetup(0.5));
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(compMotion(r.motion()),
            (V{"L 0,-0.5,0 F1000", "L -59.134,-0.5,0 F1000", "L -29.817,-51.279,0 F1000",
               "L 58.134,-0.5,0 F1000", "L 0,-0.5,0 F1000"}));
  ASSERT_GE(r.events.size(), 2u);
  EXPECT_EQ(r.events[1].from.at.line, 3u); // the r-move belongs to the first edge's block
}

} // namespace
} // namespace gcx::test
