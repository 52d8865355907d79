// Drilling cycles where NCT and LinuxCNC deliberately differ (docs/nct-vs-linuxcnc.md,
// "Drilling cycles"). The programs in tests/differential/cycles stay outside the identical set of
// tests/differential/programs; each test pins down the difference:
//  * dNN: rs274 runs the program; the comparer's first divergence (event, source line on both
//    sides, reason) is asserted exactly, and where the difference is a single event kind the rest
//    of the motion is shown to agree;
//  * rNN: rs274 rejects the program (the NCT meaning has no LinuxCNC counterpart); its message and
//    gcx's motion for the disputed block are asserted.
// gcx runs with the spec's test parameters (cycles.md §2.8: N1500 0.5, N1501 1.0, N1502 100).
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "emit/canonical.h"
#include "oracle/canon.h"
#include "oracle/compare.h"
#include "oracle/rs274.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

fs::path cyclesDir() {
  return sourceDir() / "tests" / "differential" / "cycles";
}

struct Both {
  ProgramRun ours;
  oracle::Rs274Result raw;
  std::vector<motion::Event> theirs;
};

Both runBoth(const std::string& name) {
  Both b;
  const std::string text = readFile(cyclesDir() / (name + ".nct"));
  b.ours = runNct(text);
  b.raw = oracle::Rs274().run(text);
  if (b.raw.ok()) {
    oracle::CanonOptions copt;
    copt.programText = text;
    b.theirs = oracle::parseCanon(b.raw.canonLines, copt);
  }
  return b;
}

struct Divergence {
  std::uint32_t gcxLine;   // source line of gcx's first divergent event
  std::uint32_t rs274Line; // source line of rs274's first divergent event
  std::string report;      // the comparer's report, exactly
};

// rs274 runs the program; the first divergence is the expected one.
void expectDivergence(const std::string& name, const Divergence& want,
                      const oracle::CompareOptions& opt = {}) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const Both b = runBoth(name);
  ASSERT_TRUE(b.ours.errors.empty()) << b.ours.rendered;
  ASSERT_TRUE(b.raw.ok()) << b.raw.summary();
  const oracle::CompareResult c = oracle::compareEvents(b.ours.events, b.theirs, opt);
  ASSERT_FALSE(c.equivalent) << name << ": expected a divergence";
  ASSERT_NE(c.leftIndex, oracle::CompareResult::npos) << c.report;
  ASSERT_NE(c.rightIndex, oracle::CompareResult::npos) << c.report;
  EXPECT_EQ(b.ours.events[c.leftIndex].from.at.line, want.gcxLine) << c.report;
  EXPECT_EQ(b.theirs[c.rightIndex].from.at.line, want.rs274Line) << c.report;
  EXPECT_EQ(c.report, want.report);
}

// rs274 rejects the program with `message` (its stderr names the message, then the block).
void expectRs274Rejects(const std::string& name, const std::string& message,
                        const std::string& block) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  const Both b = runBoth(name);
  EXPECT_EQ(b.raw.exitCode, 1) << b.raw.summary();
  // the block as rs274 ran it: with the N<line> the oracle puts in front
  EXPECT_EQ(b.raw.stderrText, "executing\n" + message + "\nN5 " + block + "\n");
}

// gcx's motion (modal changes left out) of the events from source line `line`.
std::vector<std::string> motionOfLine(const ProgramRun& run, std::uint32_t line) {
  std::vector<std::string> out;
  for (const motion::Event& e : run.events)
    if (e.from.at.line == line && (e.kind == motion::Kind::Rapid || e.kind == motion::Kind::Feed ||
                                   e.kind == motion::Kind::Dwell))
      out.push_back(describe(e));
  return out;
}

// gcx runs the program without errors; its motion of line 5, the cycle block.
void expectGcxCycleBlock(const std::string& name, const std::vector<std::string>& want) {
  const ProgramRun run = runNct(readFile(cyclesDir() / (name + ".nct")));
  ASSERT_TRUE(run.errors.empty()) << run.rendered;
  EXPECT_EQ(motionOfLine(run, 5), want);
}

oracle::CompareOptions withoutDwells() {
  oracle::CompareOptions o;
  o.kinds = {motion::Kind::Rapid, motion::Kind::Feed, motion::Kind::Arc};
  return o;
}

// §2.3/§2.9: op 1 positions in the plane at the current level (the initial level Z1), op 3 rapids
// up to R; G98 returns to the initial level (000:9455-9462). LinuxCNC first rapids up to R and
// returns to max(R, initial) (refs/linuxcnc 02c).
TEST(CyclesDifference, CyclesSpec_2_3_G98WithInitialLevelBelowR) {
  expectDivergence(
      "d01_g98_initial_below_r",
      {5, 5,
       "first divergence after 1 matching events: end points differ by 10.000000 mm (tolerance "
       "0.0001)\n"
       "  gcx    #1 line 5:\n"
       "           Rapid (0.0000, 0.0000, 1.0000) -> (10.0000, 0.0000, 1.0000)\n"
       "  rs274  #1 line 5:\n"
       "           Rapid (0.0000, 0.0000, 1.0000) -> (0.0000, 0.0000, 2.0000)"});
}

// §2.9: after a G99 hole the tool is at R; op 1 of the next hole rapids in the plane at that
// level, and the G98 return is after the hole (000:9455-9462). LinuxCNC rapids X and Z together up
// to its clear level (the initial level) first.
TEST(CyclesDifference, CyclesSpec_2_9_G98HoleAfterG99HolePositionsAtR) {
  expectDivergence("d02_g98_after_g99",
                   {6, 6,
                    "first divergence after 5 matching events: end points differ by 8.000000 mm "
                    "(tolerance 0.0001)\n"
                    "  gcx    #5 line 6:\n"
                    "           Rapid (10.0000, 0.0000, 2.0000) -> (20.0000, 0.0000, 2.0000)\n"
                    "  rs274  #5 line 6:\n"
                    "           Rapid (10.0000, 0.0000, 2.0000) -> (20.0000, 0.0000, 10.0000)"});
}

// §3.1 G89: op 7 always feeds to R at F*I/100, op 9 rapids to the initial level under G98
// (000:10308, 10321). LinuxCNC feeds out all the way to the clear level (refs/linuxcnc 04b).
TEST(CyclesDifference, CyclesSpec_3_1_G89UnderG98FeedsToROnly) {
  expectDivergence(
      "d03_g89_g98",
      {5, 5,
       "first divergence after 5 matching events: end points differ by 8.000000 mm (tolerance "
       "0.0001)\n"
       "  gcx    #6 line 5:\n"
       "           Feed (40.0000, 0.0000, -5.0000) -> (40.0000, 0.0000, 2.0000) F120\n"
       "  rs274  #6 line 5:\n"
       "           Feed (40.0000, 0.0000, -5.0000) -> (40.0000, 0.0000, 10.0000) F120"});
}

// §3.1 G84: dwell only when P > 0, op 7 always feeds to R, op 9 rapids to the initial level
// (000:9910-9924). LinuxCNC prints DWELL(0) and feeds out to the clear level (refs/linuxcnc 05).
TEST(CyclesDifference, CyclesSpec_3_1_G84UnderG98FeedsToROnly) {
  expectDivergence("d04_g84_g98",
                   {5, 5,
                    "first divergence after 4 matching events: different kinds: Feed vs Dwell\n"
                    "  gcx    #7 line 5:\n"
                    "           Feed (10.0000, 0.0000, -5.0000) -> (10.0000, 0.0000, 2.0000) F500\n"
                    "  rs274  #6 line 5:\n"
                    "           Dwell 0 s"});
  // without the 0 s dwell the first difference is the feed out
  expectDivergence(
      "d04_g84_g98",
      {5, 5,
       "first divergence after 4 matching events: end points differ by 8.000000 mm (tolerance "
       "0.0001)\n"
       "  gcx    #7 line 5:\n"
       "           Feed (10.0000, 0.0000, -5.0000) -> (10.0000, 0.0000, 2.0000) F500\n"
       "  rs274  #7 line 5:\n"
       "           Feed (10.0000, 0.0000, -5.0000) -> (10.0000, 0.0000, 10.0000) F500"},
      withoutDwells());
}

// §3.1 G86: feed in, M5, rapid out, M3 - no dwell (000:10142, 10150-10160). LinuxCNC requires P
// and dwells before stopping the spindle; the motion is otherwise the same.
TEST(CyclesDifference, CyclesSpec_3_1_G86HasNoDwell) {
  expectDivergence("d05_g86_p0",
                   {5, 5,
                    "first divergence after 4 matching events: different kinds: Rapid vs Dwell\n"
                    "  gcx    #6 line 5:\n"
                    "           Rapid (30.0000, 0.0000, -5.0000) -> (30.0000, 0.0000, 10.0000)\n"
                    "  rs274  #5 line 5:\n"
                    "           Dwell 0 s"});
  if (!oracle::rs274Available()) return;
  const Both b = runBoth("d05_g86_p0");
  const oracle::CompareResult c = oracle::compareEvents(b.ours.events, b.theirs, withoutDwells());
  EXPECT_TRUE(c.equivalent) << c.report;
}

// §3.2 G73: back-off d = E, else N1500 (000:9593-9594, 9694). LinuxCNC: fixed 0.254 mm.
TEST(CyclesDifference, CyclesSpec_3_2_G73BackOffIsN1500) {
  expectDivergence("d06_g73_n1500",
                   {5, 5,
                    "first divergence after 4 matching events: end points differ by 0.246000 mm "
                    "(tolerance 0.0001)\n"
                    "  gcx    #4 line 5:\n"
                    "           Rapid (30.0000, 10.0000, 0.0000) -> (30.0000, 10.0000, 0.5000)\n"
                    "  rs274  #4 line 5:\n"
                    "           Rapid (30.0000, 10.0000, 0.0000) -> (30.0000, 10.0000, 0.2540)"});
}

// §3.2 G83: clearance c = E, else N1501 (000:9595, 9882-9883). LinuxCNC: fixed 0.254 mm.
TEST(CyclesDifference, CyclesSpec_3_2_G83ClearanceIsN1501) {
  expectDivergence("d07_g83_n1501",
                   {5, 5,
                    "first divergence after 5 matching events: end points differ by 0.746000 mm "
                    "(tolerance 0.0001)\n"
                    "  gcx    #5 line 5:\n"
                    "           Rapid (10.0000, 10.0000, 2.0000) -> (10.0000, 10.0000, 1.0000)\n"
                    "  rs274  #5 line 5:\n"
                    "           Rapid (10.0000, 10.0000, 2.0000) -> (10.0000, 10.0000, 0.2540)"});
}

// §2.3: G98 is re-established when cycle mode is cancelled (000:9456-9459). LinuxCNC keeps the
// retract mode (G99) across G80.
TEST(CyclesDifference, CyclesSpec_2_3_G80ReestablishesG98) {
  expectDivergence("d08_g80_restores_g98",
                   {8, 8,
                    "first divergence after 9 matching events: end points differ by 8.000000 mm "
                    "(tolerance 0.0001)\n"
                    "  gcx    #9 line 8:\n"
                    "           Rapid (20.0000, 0.0000, -5.0000) -> (20.0000, 0.0000, 10.0000)\n"
                    "  rs274  #9 line 8:\n"
                    "           Rapid (20.0000, 0.0000, -5.0000) -> (20.0000, 0.0000, 2.0000)"});
}

// §2.5: L0 stores the cycle data and drills nothing (000:9617-9618); LinuxCNC rejects L0.
TEST(CyclesDifference, CyclesSpec_2_5_L0StoresTheDataOnly) {
  expectRs274Rejects("r01_l0", "Cannot do zero repeats of cycle", "G91 G81 X5 Z-7 R-8 L0");
  expectGcxCycleBlock("r01_l0", {}); // nothing moves
}

// §3.1 G85: op 7 feeds to R at F*I/100 (000:10118-10133); LinuxCNC has no I in G85.
TEST(CyclesDifference, CyclesSpec_3_1_G85RetractOverrideI) {
  expectRs274Rejects("r02_g85_override_i",
                     "I word with no G2, G3, G5, G5.1, G10, G33.1, G76, or G87 to use it",
                     "G99 G85 X10 Y0 Z-5 R2 I50");
  expectGcxCycleBlock(
      "r02_g85_override_i",
      std::vector<std::string>{"R 10,0,10", "R 10,0,2", "L 10,0,-5 F120", "L 10,0,2 F60"});
}

// §3.10 G87 variant B (ORI=1): R below the bottom, the tool bores upward (000:10202-10251).
// LinuxCNC's G87 takes R above Z and K as the top of the back bore.
TEST(CyclesDifference, CyclesSpec_3_10_G87BackBoring) {
  expectRs274Rejects("r03_g87_back_boring", "R less than z in cycle in xy plane",
                     "G87 X10 Y0 Z-5 R-25 I-0.5");
  // the worked example of §3.10
  expectGcxCycleBlock("r03_g87_back_boring",
                      {"R 10,0,50", "R 9.5,0,50", "R 9.5,0,-25", "R 10,0,-25", "L 10,0,-5 F40",
                       "R 9.5,0,-5", "R 9.5,0,50", "R 10,0,50"});
}

// §3.5 G76 fine boring with the I J shift (000:9763-9788); LinuxCNC's G76 is lathe threading.
TEST(CyclesDifference, CyclesSpec_3_5_G76FineBoring) {
  expectRs274Rejects("r04_g76_fine_boring", "I J or K words missing with G76",
                     "G76 X40 Y30 Z-20 R2 I0.3 J-0.2 P1");
  // the worked example of §3.5
  expectGcxCycleBlock("r04_g76_fine_boring",
                      std::vector<std::string>{"R 40,30,50", "R 40,30,2", "L 40,30,-20 F60",
                                               "DW 1s", "R 40.3,29.8,-20", "R 40.3,29.8,50",
                                               "R 40,30,50"});
}

} // namespace
} // namespace gcx::test

namespace gcx::test {
namespace {

// G76 and G87 stop the spindle oriented before the bar shifts sideways. LinuxCNC ignores a bare
// M19 (it orients only with R), so gcx writes `M19 R<angle>`: rs274 run on the canonical output
// orients at the same points, and the comparer counts the oriented stop as spindle state.
void expectCanonicalOrientedStops(const std::string& name, long stops) {
  if (!oracle::rs274Available()) GTEST_SKIP() << "rs274 (linuxcnc-uspace) is not installed";
  std::ostringstream canonical;
  emit::CanonicalEmitter emitter(canonical);
  const ProgramRun ours = runNct(readFile(cyclesDir() / (name + ".nct")), {}, &emitter);
  ASSERT_TRUE(ours.errors.empty()) << ours.rendered;
  const std::string text = canonical.str(); // CanonOptions::programText only views it
  const oracle::Rs274Result raw = oracle::Rs274().run(text);
  ASSERT_TRUE(raw.ok()) << raw.summary();
  oracle::CanonOptions copt;
  copt.programText = text;
  const std::vector<motion::Event> theirs = oracle::parseCanon(raw.canonLines, copt);
  const auto orients = [](const std::vector<motion::Event>& events) {
    return std::count_if(events.begin(), events.end(), [](const motion::Event& e) {
      return e.kind == motion::Kind::SpindleOrient;
    });
  };
  EXPECT_EQ(orients(ours.events), stops) << canonical.str();
  EXPECT_EQ(orients(theirs), stops) << canonical.str();
  const oracle::CompareResult c = oracle::compareEvents(ours.events, theirs);
  EXPECT_TRUE(c.equivalent) << c.report << "\n--- canonical:\n" << canonical.str();
}

TEST(CyclesDifference, CyclesSpec_G76_CanonicalOrientedStopIsHonouredByRs274) {
  expectCanonicalOrientedStops("r04_g76_fine_boring", 1); // at the bottom, before the shift
}

TEST(CyclesDifference, CyclesSpec_G87_CanonicalOrientedStopIsHonouredByRs274) {
  expectCanonicalOrientedStops("r03_g87_back_boring", 2); // above the bore and at the bottom
}

} // namespace
} // namespace gcx::test
