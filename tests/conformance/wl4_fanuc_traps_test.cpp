// The Fanuc habits of wl4.md §9: each gets its WL4 meaning or a located error, plus a warning
// naming the likely Fanuc intent.
#include <gtest/gtest.h>

#include "support/wl4_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

TEST(Wl4FanucTraps_9, ANumberWithoutAPointIsWholeMillimetresWithAWarning) {
  Parsed p = parseWl4("G0 X1030 Y999 Z-2000.\n");
  EXPECT_TRUE(p.errors().empty()) << p.rendered();
  EXPECT_EQ(p.blocks[0].words[1].number, 1030);
  EXPECT_EQ(p.warnings(), (V{"1:4 GCXW21"})); // Y999 is below 1000, Z-2000. has its point
  EXPECT_NE(p.rendered().find("a Fanuc program would mean 1.03 mm (write X1.030)"),
            std::string::npos)
      << p.rendered();
}

TEST(Wl4FanucTraps_9, ParenthesesAsACommentAreAnErrorWithAWarning) {
  Parsed p = parseWl4("G0 X10 (MOVE)\n");
  EXPECT_EQ(p.errors(), (V{"1:8 GCX060"})) << p.rendered();
  EXPECT_EQ(p.warnings(), (V{"1:8 GCXW20"}));
  EXPECT_NE(p.rendered().find("(a Fanuc comment?)"), std::string::npos) << p.rendered();
}

TEST(Wl4FanucTraps_9, G98InACycleBlockIsAnUnknownCodeWithAWarning) {
  MacroRun r = runWl4("%P\nG90 G0 Z10\nG81 G98 #2=1 #3=-5\nX5\nG80\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"3:5 GCX031"})) << r.rendered;
  EXPECT_NE(r.rendered.find("main.wl4:3:5: warning: G98 is no WL4 code: a WL4 cycle has no "
                            "return level, the tool stays at #2 (Fanuc G98/G99"),
            std::string::npos)
      << r.rendered;
}

TEST(Wl4FanucTraps_9, G99InACycleBlockIsAnUnknownCodeWithAWarning) {
  // G99 (Fanuc: back to the R level) after the cycle's own G82: located where it stands
  MacroRun r = runWl4("%P\nG90 G0 Z10\nG82 #2=1 #3=-5 #4=1 G99\nX5\nG80\nM2\n%\n");
  EXPECT_EQ(errorsAt(r), (V{"3:21 GCX031"})) << r.rendered;
  EXPECT_NE(r.rendered.find("main.wl4:3:21: warning: G99 is no WL4 code"), std::string::npos)
      << r.rendered;
  EXPECT_NE(r.rendered.find("[GCXW22]"), std::string::npos) << r.rendered;
}

TEST(Wl4FanucTraps_9, M98IsAMachineCodeNotACall) {
  // M98 P07 calls nothing: the program goes on, %07 never runs
  MacroRun r = runWl4("%P\nM98 P07\nG0 X1\nM2\n%\n%07\nG0 Y5\nM99\n%\n");
  EXPECT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(r.motion(), (V{"R 1,0,0", "END"}));
  EXPECT_NE(r.rendered.find("main.wl4:2:1: warning: M98 calls nothing in WL4 (a machine M code): "
                            "call program %nn with L nn or L nnpp (Fanuc M98 P"),
            std::string::npos)
      << r.rendered;
}

} // namespace
} // namespace gcx::test
