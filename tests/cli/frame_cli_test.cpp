// gcx run --trace --frame: the adapters in front of the sinks (docs/machine-model.md, frames).
// One program under a work offset, a rotation, a scaling, a mirror and G20, traced in the
// machine, work and program frames; the statistics measure the machine's path in every case.
#include <gtest/gtest.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

constexpr const char* kProgram = "O0001\n"
                                 "G90 G17 G21 G54\n"
                                 "G0 X0 Y0 Z5\n"
                                 "G68 X10 Y0 R90\n"
                                 "G1 X20 Y0 F200\n"
                                 "G2 X30 Y10 R10\n"
                                 "G69\n"
                                 "G51 X0 Y0 P2.\n"
                                 "G1 X5 Y5\n"
                                 "G50\n"
                                 "G51.1 X0\n"
                                 "G3 X5 Y15 I0 J5\n"
                                 "G50.1 X0\n"
                                 "G20\n"
                                 "G1 X1 Y1 F10\n"
                                 "M30\n";
constexpr const char* kSetup = R"({"work_offsets": {"G54": [100, 50, -20]}})";

struct Traced {
  CliResult run;
  std::string trace;
};

Traced traced(const std::string& frame) {
  CliFolder dir("frame-" + frame);
  dir.write("O0001.nct", kProgram);
  dir.write("s.json", kSetup);
  Traced t;
  t.run = dir.gcx("run O0001.nct --setup s.json --stats --trace t.jsonl --frame " + frame);
  t.trace = readFile(dir.path() / "t.jsonl");
  return t;
}

TEST(FrameCli, ProgramFrameReadsAsTheProgramWroteIt) {
  const Traced t = traced("program");
  ASSERT_EQ(t.run.exitCode, 0) << t.run.err;
  // each move ends where the program put it; a start is the previous end seen through the
  // transformation in force now, so the path jumps where a transformation changes
  EXPECT_EQ(t.trace,
            R"({"kind":"rapid","start":[-100,-50,20],"end":[0,0,5],"at":"O0001.nct:3:1"}
{"kind":"feed","start":[10,10,5],"end":[20,0,5],"feed":200,"at":"O0001.nct:5:1"}
{"kind":"arc","start":[20,0,5],"end":[30,10,5],"center":[30,0,5],"plane":"XY","dir":"cw","turns":0,"feed":200,"at":"O0001.nct:6:1"}
{"kind":"feed","start":[0,10,5],"end":[5,5,5],"feed":200,"at":"O0001.nct:9:1"}
{"kind":"arc","start":[-10,10,5],"end":[5,15,5],"center":[5,10,5],"plane":"XY","dir":"ccw","turns":0,"feed":200,"at":"O0001.nct:12:1"}
{"kind":"units","code":20,"at":"O0001.nct:14:1"}
{"kind":"feed","start":[-0.19685,0.590551,0.19685],"end":[1,1,0.19685],"feed":10,"at":"O0001.nct:15:1"}
{"kind":"end","at":"O0001.nct:16:1"}
)");
}

TEST(FrameCli, WorkFrameKeepsTransformationsAndMillimetres) {
  const Traced t = traced("work");
  ASSERT_EQ(t.run.exitCode, 0) << t.run.err;
  EXPECT_EQ(t.trace,
            R"({"kind":"rapid","start":[-100,-50,20],"end":[0,0,5],"at":"O0001.nct:3:1"}
{"kind":"feed","start":[0,0,5],"end":[10,10,5],"feed":200,"at":"O0001.nct:5:1"}
{"kind":"arc","start":[10,10,5],"end":[0,20,5],"center":[10,20,5],"plane":"XY","dir":"cw","turns":0,"feed":200,"at":"O0001.nct:6:1"}
{"kind":"feed","start":[0,20,5],"end":[10,10,5],"feed":200,"at":"O0001.nct:9:1"}
{"kind":"arc","start":[10,10,5],"end":[-5,15,5],"center":[-5,10,5],"plane":"XY","dir":"cw","turns":0,"feed":200,"at":"O0001.nct:12:1"}
{"kind":"units","code":20,"at":"O0001.nct:14:1"}
{"kind":"feed","start":[-5,15,5],"end":[25.4,25.4,5],"feed":254,"at":"O0001.nct:15:1"}
{"kind":"end","at":"O0001.nct:16:1"}
)");
}

TEST(FrameCli, StatisticsMeasureTheMachinePathInEveryFrame) {
  const Traced machine = traced("machine");
  ASSERT_EQ(machine.run.exitCode, 0) << machine.run.err;
  EXPECT_NE(machine.trace.find(R"("end":[125.4,75.4,-15],"feed":254)"), std::string::npos);
  EXPECT_NE(machine.run.out.find("bounds: X 0.000 .. 125.400, Y 0.000 .. 75.400, Z -15.000 .. "
                                 "0.000\n"),
            std::string::npos)
      << machine.run.out;
  EXPECT_EQ(traced("program").run.out, machine.run.out);
  EXPECT_EQ(traced("work").run.out, machine.run.out);
}

TEST(FrameCli, UnknownFrameIsAUsageError) {
  CliFolder dir("frame-bad");
  dir.write("O0001.nct", kProgram);
  const CliResult r = dir.gcx("run O0001.nct --frame tool");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--frame"), std::string::npos) << r.err;
}

} // namespace
} // namespace gcx::test
