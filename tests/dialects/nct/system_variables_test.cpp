// System variables against nct-macro.md §2.7-§2.9: NC blocks run on a real interpreter, then
// the variables read its positions, modal state and offsets; writes change the next move.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "diag/codes.h"
#include "dialects/nct/profile.h"
#include "dialects/nct/system_variables.h"
#include "machine/interpreter.h"
#include "support/test_support.h"

namespace gcx::test {
namespace {

using macro::Value;

struct Events : motion::Sink {
  std::vector<motion::Event> list;
  void event(const motion::Event& e) override { list.push_back(e); }
};

// One interpreter and its system variables; every call names its own location so that each
// diagnostic can be checked against the range it was given.
struct Rig {
  diag::Engine diags{1000};
  Events sink;
  machine::Interpreter machine;
  nct::SystemVariables vars;
  std::uint32_t nextLine = 1;

  explicit Rig(const machine::Setup& setup = {})
      : machine(nct::profile(), setup, sink, diags), vars(machine, diags) {}

  static SourceRange at(std::uint32_t line) { return SourceRange{SourceLoc{0, line, 3, 0}, 5}; }

  void run(const std::string& text) {
    Parsed p = parseNct(text);
    ASSERT_TRUE(p.errors().empty()) << p.rendered();
    for (const ir::Block& b : p.blocks)
      ASSERT_TRUE(machine.execute(b, {})) << text;
    ASSERT_FALSE(diags.hasErrors());
  }
  // value of #n; fails the test if it is vacant or an error
  double get(int n) {
    auto v = vars.read(n, at(nextLine++));
    EXPECT_TRUE(v && !v->vacant) << "#" << n;
    return v && !v->vacant ? v->number : NAN;
  }
  double get(const std::string& name, std::optional<int> index = std::nullopt) {
    auto v = vars.readNamed(name, index, at(nextLine++));
    EXPECT_TRUE(v && !v->vacant) << "#_" << name;
    return v && !v->vacant ? v->number : NAN;
  }
  bool set(int n, double v) { return vars.write(n, Value::of(v), at(nextLine++)); }
  bool set(const std::string& name, std::optional<int> index, double v) {
    return vars.writeNamed(name, index, Value::of(v), at(nextLine++));
  }
  /// "CODE@line" of each diagnostic since the last call.
  std::vector<std::string> take() {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      out.push_back(d.code + "@" + std::to_string(d.range.begin.line));
    diags.clear();
    return out;
  }
  std::vector<std::string> codes() {
    std::vector<std::string> out;
    for (const diag::Diagnostic& d : diags.all())
      out.push_back(d.code);
    diags.clear();
    return out;
  }
};

using Codes = std::vector<std::string>;

TEST(SystemVariables, ConstantsInShortAndSymbolicForms) {
  Rig r;
  for (int n : {0, 3100}) {
    auto v = r.vars.read(n, {});
    ASSERT_TRUE(v);
    EXPECT_TRUE(v->vacant);
  }
  auto empty = r.vars.readNamed("EMPTY", std::nullopt, {});
  ASSERT_TRUE(empty);
  EXPECT_TRUE(empty->vacant);
  EXPECT_EQ(r.get(3101), std::numbers::pi);
  EXPECT_EQ(r.get("PI"), std::numbers::pi);
  EXPECT_EQ(r.get(3102), std::numbers::e);
  EXPECT_EQ(r.get("e"), std::numbers::e); // symbols are case-insensitive (§1.1 L2)
  EXPECT_TRUE(r.codes().empty());
  EXPECT_TRUE(nct::SystemVariables::isSystem(0));
  EXPECT_TRUE(nct::SystemVariables::isSystem(1000));
  EXPECT_TRUE(nct::SystemVariables::isSystem(3101));
  EXPECT_FALSE(nct::SystemVariables::isSystem(999));
  EXPECT_FALSE(nct::SystemVariables::isSystem(33));
}

TEST(SystemVariables, PlcInputsAreZeroWithOneWarningPerVariable) {
  Rig r;
  EXPECT_EQ(r.get(1000), 0);     // line 1
  EXPECT_EQ(r.get(1000), 0);     // line 2: no second warning
  EXPECT_EQ(r.get("UI", 0), 0);  // line 3: the same variable
  EXPECT_EQ(r.get(1031), 0);     // line 4
  EXPECT_EQ(r.get(1032), 0);     // line 5
  EXPECT_EQ(r.get("UIL", 3), 0); // line 6 = #1035
  EXPECT_EQ(r.take(), (Codes{"NCTW01@1", "NCTW01@4", "NCTW01@5", "NCTW01@6"}));
  EXPECT_EQ(r.diags.errorCount(), 0u);
  EXPECT_FALSE(r.set(1000, 1)); // line 7
  EXPECT_FALSE(r.set("UIL", 1, 2));
  EXPECT_EQ(r.take(), (Codes{"2161@7", "2161@8"}));
}

TEST(SystemVariables, PlcOutputBitsWordAndValues) {
  Rig r;
  EXPECT_TRUE(r.set(1100, 1));
  EXPECT_TRUE(r.set(1101, 0.5)); // 0 < v <= 1 -> 1 (§2.7 A3)
  EXPECT_TRUE(r.set("UO", 3, 1));
  EXPECT_EQ(r.get("UO", 0), 1);
  EXPECT_EQ(r.get(1101), 1);
  EXPECT_EQ(r.get(1102), 0);
  EXPECT_EQ(r.get(1132), 11); // bits 0, 1, 3
  EXPECT_TRUE(r.set(1101, 0));
  EXPECT_EQ(r.get("UOL", 0), 9);
  EXPECT_TRUE(r.set(1132, 6));
  EXPECT_EQ(r.get(1100), 0);
  EXPECT_EQ(r.get(1101), 1);
  EXPECT_EQ(r.get(1102), 1);
  EXPECT_TRUE(r.set(1132, -1)); // a signed bitwise result: all 32 bits
  EXPECT_EQ(r.get(1132), 4294967295.0);
  EXPECT_EQ(r.get("UO", 31), 1);
  EXPECT_TRUE(r.set(1133, 2.5));
  EXPECT_TRUE(r.set("UOL", 3, -7.25));
  EXPECT_EQ(r.get("UOL", 1), 2.5);
  EXPECT_EQ(r.get(1135), -7.25);
  EXPECT_EQ(r.get(1134), 0);
  EXPECT_TRUE(r.codes().empty());
}

TEST(SystemVariables, BitValuesOutsideZeroToOneAre2092) {
  Rig r;
  r.nextLine = 10;
  EXPECT_FALSE(r.set(1100, 1.5));          // 10
  EXPECT_FALSE(r.set(1131, -0.5));         // 11: negative, §2.7 A3 [D]
  EXPECT_FALSE(r.set("UO", 7, 1.0001));    // 12
  EXPECT_FALSE(r.set("M_SBK", {}, 2));     // 13
  EXPECT_FALSE(r.set(3004, 8));            // 14: bits 0-2 only
  EXPECT_FALSE(r.set(3003, 2));            // 15: bit 0 only
  EXPECT_FALSE(r.set(1132, 4294967296.0)); // 16: more than 32 bits
  EXPECT_EQ(r.take(),
            (Codes{"2092@10", "2092@11", "2092@12", "2092@13", "2092@14", "2092@15", "2092@16"}));
  EXPECT_EQ(r.get(1132), 0); // nothing was stored
  EXPECT_EQ(r.get(3004), 0);
}

TEST(SystemVariables, ClocksDateTimeAreRuntimeStubs) {
  Rig r;
  EXPECT_EQ(r.get(3001), 0);          // 1
  EXPECT_EQ(r.get("CLOCK2"), 0);      // 2
  EXPECT_EQ(r.get(3011), 20000101);   // 3
  EXPECT_EQ(r.get("DATE"), 20000101); // 4: same variable, no second warning
  EXPECT_EQ(r.get(3012), 0);          // 5
  EXPECT_EQ(r.take(), (Codes{"NCTW01@1", "NCTW01@2", "NCTW01@3", "NCTW01@5"}));
  EXPECT_TRUE(r.set(3001, 500)); // R/W: the stopwatch can be set
  EXPECT_EQ(r.get("CLOCK1"), 500);
  EXPECT_TRUE(r.codes().empty()); // warned once already
  r.nextLine = 20;
  EXPECT_FALSE(r.set(3011, 20240101));
  EXPECT_FALSE(r.set("TIME", {}, 1));
  EXPECT_EQ(r.take(), (Codes{"2161@20", "2161@21"}));
}

TEST(SystemVariables, ControlWordsAndTheirBits) {
  Rig r;
  EXPECT_TRUE(r.set(3003, 1));
  EXPECT_EQ(r.get("M_SBK"), 1);
  EXPECT_TRUE(r.set("M_SBK", {}, 0));
  EXPECT_EQ(r.get("CNTL1"), 0);
  EXPECT_TRUE(r.set("M_OV", {}, 1));
  EXPECT_TRUE(r.set("m_est", {}, 0.2));
  EXPECT_EQ(r.get(3004), 6);
  EXPECT_EQ(r.get("M_FHD"), 0);
  EXPECT_TRUE(r.set("CNTL2", {}, 1));
  EXPECT_EQ(r.get("M_FHD"), 1);
  EXPECT_EQ(r.get("M_OV"), 0);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 30;
  EXPECT_EQ(r.get("CNTBS"), 0);   // 30
  EXPECT_EQ(r.get("MCHLOCK"), 0); // 31
  EXPECT_FALSE(r.set("TEST", {}, 1));
  EXPECT_EQ(r.take(), (Codes{"NCTW01@30", "NCTW01@31", "2161@32"}));
}

TEST(SystemVariables, MirrorPartsAndMainProgram) {
  Rig r;
  EXPECT_EQ(r.get(3007), 0);
  r.run("G51.1 X0 Z0\n");
  EXPECT_EQ(r.get("MIRIMG"), 5); // axes 1 and 3 (§2.9.3 example)
  r.run("G50.1\n");
  EXPECT_EQ(r.get(3007), 0);
  EXPECT_TRUE(r.set(3901, 12));
  EXPECT_TRUE(r.set("PRTSN", {}, 100));
  EXPECT_EQ(r.get("PRTSA"), 12);
  EXPECT_EQ(r.get(3902), 100);
  EXPECT_EQ(r.get(4000), 0);
  r.vars.setMainProgramNumber(1234);
  EXPECT_EQ(r.get(4000), 1234);
  EXPECT_EQ(r.get("MAINO"), 1234);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 40;
  EXPECT_FALSE(r.set(3007, 1));
  EXPECT_FALSE(r.set(4000, 1));
  EXPECT_EQ(r.take(), (Codes{"2161@40", "2161@41"}));
}

// TV-31 of §10 and the decimal rule of §2.9.4
TEST(SystemVariables, ModalGroupsOfTheLastBlock) {
  Rig r;
  r.run("G17 G90 G54.1 P1\n");
  EXPECT_EQ(r.get(4002), 17);
  EXPECT_EQ(r.get(4003), 90);
  EXPECT_EQ(r.get(4014), 154);
  EXPECT_EQ(r.get(4012), 67);
  EXPECT_EQ(r.get(4001), 0); // G0
  EXPECT_EQ(r.get(4006), 21);
  EXPECT_EQ(r.get(4008), 49);
  EXPECT_EQ(r.get(4009), 80);
  r.run("G91 G18\n");
  EXPECT_EQ(r.get("BUFG", 2), 18);
  EXPECT_EQ(r.get(4003), 91);
  EXPECT_EQ(r.get(4203), 91); // §4.6: #42xx = #40xx
  EXPECT_EQ(r.get("ACTG", 2), 18);
  r.run("G51.1 X0\nG69.1\nG80.8\nG1 X1 F100\nG20 G56\n");
  EXPECT_EQ(r.get(4022), 151);
  EXPECT_EQ(r.get(4018), 169);
  EXPECT_EQ(r.get(4034), 880);
  EXPECT_EQ(r.get(4001), 1);
  EXPECT_EQ(r.get(4006), 20);
  EXPECT_EQ(r.get(4014), 56);
  EXPECT_EQ(r.get(4019), 0); // an empty group
  r.run("G50.1\n");
  EXPECT_EQ(r.get(4222), 150);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 50;
  EXPECT_EQ(r.get(4402), 0);          // 50: runtime only
  EXPECT_EQ(r.get("INTG", 2), 0);     // 51: same variable
  EXPECT_FALSE(r.set(4001, 1));       // 52
  EXPECT_FALSE(r.set("BUFG", 2, 17)); // 53
  EXPECT_FALSE(r.set(4201, 1));       // 54
  EXPECT_EQ(r.take(), (Codes{"NCTW01@50", "2161@52", "2161@53", "2161@54"}));
}

TEST(SystemVariables, ModalWordsOfTheLastBlock) {
  machine::Setup setup;
  setup.tools[3].length = 10;
  Rig r(setup);
  r.run("O0012\nN10 G1 X1 F200 S1200 M3 T5 D7 H3\nM8\n");
  EXPECT_EQ(r.get(4107), 7);
  EXPECT_EQ(r.get("BUFD"), 7);
  EXPECT_EQ(r.get(4109), 200);
  EXPECT_EQ(r.get(4111), 3); // H without G43 is recorded too
  EXPECT_EQ(r.get(4113), 8);
  EXPECT_EQ(r.get(4114), 10);
  EXPECT_EQ(r.get(4115), 12);
  EXPECT_EQ(r.get(4119), 1200);
  EXPECT_EQ(r.get(4120), 5);
  EXPECT_EQ(r.get(4130), 0);
  EXPECT_EQ(r.get(4307), 7);
  EXPECT_EQ(r.get("ACTM"), 8);
  EXPECT_EQ(r.get("ACTS"), 1200);
  r.run("N20 G54.1 P3 S900 M5\nG20 G1 X1 F10\n");
  EXPECT_EQ(r.get("BUFWZP"), 3);
  EXPECT_EQ(r.get(4330), 3);
  EXPECT_EQ(r.get(4114), 20);
  EXPECT_EQ(r.get(4119), 900);
  EXPECT_EQ(r.get(4109), 10); // F in the program's units (inch/min)
  EXPECT_EQ(r.get("BUFF"), 10);
  EXPECT_EQ(r.machine.state().feed, 254);
  r.machine.setCalledProgram(9010); // M98 / G65 P9010 as the expander reports it
  EXPECT_EQ(r.get("BUFO"), 9010);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 60;
  EXPECT_EQ(r.get(4507), 0);                    // 60: runtime only
  EXPECT_FALSE(r.vars.read(4101, Rig::at(61))); // chosen by N1333: not modelled
  EXPECT_FALSE(r.vars.readNamed("ACTC", {}, Rig::at(62)));
  r.nextLine = 63;
  EXPECT_FALSE(r.set(4120, 1)); // read-only
  EXPECT_EQ(r.take(), (Codes{"NCTW01@60", "GCX030@61", "GCX030@62", "2161@63"}));
}

machine::Setup offsetSetup() {
  machine::Setup s;
  s.workOffsets["G54"] = {100, 50, -200};
  s.workOffsets["G55"] = {-10, -20, -30};
  s.tools[1].length = 100;
  return s;
}

TEST(SystemVariables, PositionsInWorkAndMachineCoordinates) {
  Rig r(offsetSetup());
  r.run("G90 G54 G0 X10 Y20 Z30\nG43 H1 Z5\nG0 A45 C-30\n");
  // machine Z = -200 + 100 (length) + 5
  const double absio[] = {10, 20, 5, 45, 0, -30};
  const double absmt[] = {110, 70, -95, 45, 0, -30};
  for (int a = 1; a <= 6; ++a) {
    EXPECT_EQ(r.get(5000 + a), absio[a - 1]) << a;
    EXPECT_EQ(r.get(100000 + a), absio[a - 1]) << a;
    EXPECT_EQ(r.get("ABSIO", a), absio[a - 1]) << a;
    EXPECT_EQ(r.get(5020 + a), absmt[a - 1]) << a;
    EXPECT_EQ(r.get(100050 + a), absmt[a - 1]) << a;
    EXPECT_EQ(r.get("ABSMT", a), absmt[a - 1]) << a;
    EXPECT_EQ(r.get(5040 + a), absio[a - 1]) << a;
    EXPECT_EQ(r.get("ABSOT", a), absio[a - 1]) << a;
  }
  EXPECT_EQ(r.get(5020), 0); // axis 20: not in the channel
  EXPECT_EQ(r.get(100050), 0);
  EXPECT_EQ(r.get(5083), 100); // active length along Z
  EXPECT_EQ(r.get(5081), 0);
  EXPECT_EQ(r.get("TOFS", 3), 100);
  EXPECT_EQ(r.get(100203), 100);
  EXPECT_EQ(r.get(5181), 0); // distance to go between blocks
  EXPECT_EQ(r.get("DIST", 3), 0);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 70;
  EXPECT_EQ(r.get(5061), 10);         // 70: probe = programmed end point
  EXPECT_EQ(r.get("ABSKP", 3), 5);    // 71
  EXPECT_EQ(r.get(100151), 10);       // 72: = #5061
  EXPECT_EQ(r.get(5101), 0);          // 73: servo lag
  EXPECT_EQ(r.get(100651), 0);        // 74: handwheel
  EXPECT_FALSE(r.set(5001, 1));       // 75
  EXPECT_FALSE(r.set("ABSMT", 1, 1)); // 76
  EXPECT_FALSE(r.set(5083, 1));       // 77
  EXPECT_EQ(r.take(), (Codes{"NCTW01@70", "NCTW01@71", "NCTW01@73", "NCTW01@74", "2161@75",
                             "2161@76", "2161@77"}));
}

TEST(SystemVariables, CurrentPositionIsTheMachinePositionLessOffsetsNotTransformed) {
  Rig r(offsetSetup());
  r.run("G54 G0 X10 Y20\nG51.1 X0\nG0 X10\n");
  EXPECT_EQ(r.get(5001), 10);  // the programmed end point
  EXPECT_EQ(r.get(5021), 90);  // mirrored: 100 - 10
  EXPECT_EQ(r.get(5041), -10); // where the tool is in G54
  EXPECT_EQ(r.get(5042), 20);
}

TEST(SystemVariables, PositionsInInch) {
  machine::Setup s;
  s.workOffsets["G54"] = {25.4, 0, 0};
  s.tools[2].length = 50.8;
  Rig r(s);
  r.run("G20 G0 X1 Y0.5\nG43 H2 Z0\n");
  EXPECT_DOUBLE_EQ(r.get(5001), 1);
  EXPECT_DOUBLE_EQ(r.get(5002), 0.5);
  EXPECT_DOUBLE_EQ(r.get(5021), 2);
  EXPECT_DOUBLE_EQ(r.get(5023), 2);
  EXPECT_DOUBLE_EQ(r.get(5041), 1);
  EXPECT_DOUBLE_EQ(r.get(5083), 2);
  EXPECT_DOUBLE_EQ(r.get(5221), 1);
  EXPECT_DOUBLE_EQ(r.get(10002), 2);
}

TEST(SystemVariables, WorkOffsetsReadAndWriteThroughTheMachine) {
  Rig r(offsetSetup());
  EXPECT_EQ(r.get(5221), 100);
  EXPECT_EQ(r.get(5222), 50);
  EXPECT_EQ(r.get(5223), -200);
  EXPECT_EQ(r.get("WZG54", 2), 50);
  EXPECT_EQ(r.get(100351), 100);
  EXPECT_EQ(r.get(5242), -20); // G55 Y
  EXPECT_EQ(r.get(100402), -20);
  EXPECT_EQ(r.get(5201), 0); // common
  EXPECT_EQ(r.get(5224), 0); // axis 4
  r.run("G90 G54 G0 X10 Y20 Z0\n");
  ASSERT_EQ(r.sink.list.back().end.x(), 110);
  EXPECT_TRUE(r.set(5221, 200));
  EXPECT_EQ(r.get(5001), -90); // the tool did not move; its work coordinates did
  EXPECT_EQ(r.machine.machinePosition().x(), 110);
  r.run("G0 X10\n");
  EXPECT_EQ(r.sink.list.back().end.x(), 210);
  EXPECT_TRUE(r.set("WZCMN", 2, 5)); // common offset adds to every system
  r.run("G0 Y20\n");
  EXPECT_EQ(r.sink.list.back().end.y(), 75);
  EXPECT_EQ(r.get(100302), 5);
  EXPECT_TRUE(r.set(100403, 7)); // G55 Z, long form
  EXPECT_EQ(r.get(5263 - 20), 7);
  r.run("G55 G0 Z1\n");
  EXPECT_EQ(r.sink.list.back().end.z(), 8);
  EXPECT_TRUE(r.set(5224, 0)); // axis 4: only 0 is accepted
  EXPECT_TRUE(r.codes().empty());
}

TEST(SystemVariables, ExtendedWorkOffsetsG541) {
  Rig r;
  EXPECT_TRUE(r.set(7041, 5)); // P3 X: #7001 + 20*2
  EXPECT_EQ(r.get(101101), 5); // #101001 + 50*2
  EXPECT_EQ(r.get("WZP3", 1), 5);
  EXPECT_TRUE(r.set("WZP3", 2, -4));
  EXPECT_EQ(r.get(7042), -4);
  EXPECT_EQ(r.machine.setup().workOffset("G54.1 P3")[1], -4);
  r.run("G54.1 P3 G0 X1 Y1\n");
  EXPECT_EQ(r.sink.list.back().end.x(), 6);
  EXPECT_EQ(r.sink.list.back().end.y(), -3);
  EXPECT_TRUE(r.set(7941, 9));       // P48 X: last short-form row
  EXPECT_EQ(r.get(103351), 9);       // §2.9.7 table row of P48
  EXPECT_TRUE(r.set(7960, 0));       // P48 axis 20: last short form (axes > 3 hold 0)
  EXPECT_TRUE(r.set("WZP49", 1, 7)); // long form only
  EXPECT_EQ(r.get(103401), 7);       // §2.9.7 table row of P49
  EXPECT_EQ(r.get(105951 - 50), 0);  // P99 axis 1
  EXPECT_TRUE(r.set(7003, 2));       // P1 Z
  EXPECT_EQ(r.machine.setup().workOffset("G54.1 P1")[2], 2);
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 80;
  EXPECT_FALSE(r.vars.read(7961, Rig::at(80)));   // P49 has no short form
  EXPECT_FALSE(r.vars.read(105951, Rig::at(81))); // beyond P99
  r.nextLine = 82;
  EXPECT_FALSE(r.set("WZP100", 1, 1)); // 82
  EXPECT_FALSE(r.set("WZP1", 51, 1));  // 83
  EXPECT_EQ(r.take(), (Codes{"NCTX01@80", "NCTX01@81", "NCTX01@82", "NCTX01@83"}));
}

// TV-30 of §10, offsets part: G10 and the tool offset variables share the registers
TEST(SystemVariables, ToolOffsetsFollowG10AndTheGeometryPlusWearModel) {
  Rig r;
  r.run("G90 G10 L10 P5 R12.5\nG91 G10 L10 P5 R0.5\n");
  EXPECT_EQ(r.get(10005), 13);
  r.run("G90 G10 L10 P5 RI1\n");
  EXPECT_EQ(r.get("OFSHG", 5), 14);
  EXPECT_TRUE(r.set(11005, -0.02));
  EXPECT_EQ(r.get(11005), -0.02);
  EXPECT_EQ(r.get(10005), 14); // the geometry is kept
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(5).length, 13.98);
  EXPECT_TRUE(r.set("OFSHG", 5, 20));
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(5).length, 19.98);
  EXPECT_EQ(r.get("OFSHW", 5), -0.02);
  r.run("G91 G10 L11 P5 R0.5\n"); // G91: added to the wear, the geometry stays
  EXPECT_DOUBLE_EQ(r.get(11005), 0.48);
  EXPECT_DOUBLE_EQ(r.get(10005), 20);
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(5).length, 20.48);
  r.run("G90 G10 L11 P5 R0.1\n");
  EXPECT_DOUBLE_EQ(r.get(11005), 0.1);
  EXPECT_DOUBLE_EQ(r.get(10005), 20);
  // a new length acts when H is programmed again
  r.run("G43 H5 G0 Z0\n");
  EXPECT_DOUBLE_EQ(r.sink.list.back().end.z(), 20.1);
  EXPECT_DOUBLE_EQ(r.get(5083), 20.1);

  EXPECT_TRUE(r.set(12003, 5));
  EXPECT_TRUE(r.set("OFSDW", 3, 0.1));
  EXPECT_EQ(r.get(12003), 5);
  EXPECT_EQ(r.get(13003), 0.1);
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(3).radius, 5.1);
  EXPECT_TRUE(r.set(13003, 0));
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(3).radius, 5);
  EXPECT_TRUE(r.set(21001, 1.5)); // corner radius: stored
  EXPECT_EQ(r.get("CORR_G", 1), 1.5);
  EXPECT_EQ(r.get(22001), 0);
  EXPECT_EQ(r.get(10999), 0); // register 999
  EXPECT_TRUE(r.codes().empty());
  r.nextLine = 90;
  EXPECT_FALSE(r.vars.read(10000, Rig::at(90)));           // register 0 does not exist
  EXPECT_FALSE(r.vars.read(23001, Rig::at(91)));           // TOL=1 only
  EXPECT_FALSE(r.vars.read(135001, Rig::at(92)));          // TOL=1 only
  EXPECT_FALSE(r.vars.readNamed("OFSZG", 1, Rig::at(93))); // TOL=1 alias
  EXPECT_FALSE(r.vars.write(10001, Value::empty(), Rig::at(94)));
  EXPECT_EQ(r.take(), (Codes{"NCTX01@90", "NCTX01@91", "NCTX01@92", "NCTX01@93", "NCTX05@94"}));
}

TEST(SystemVariables, ToolOffsetsInInch) {
  Rig r;
  r.run("G20\n");
  EXPECT_TRUE(r.set(10001, 2));
  EXPECT_DOUBLE_EQ(r.machine.setup().tools.at(1).length, 50.8);
  EXPECT_DOUBLE_EQ(r.get(10001), 2);
}

TEST(SystemVariables, VacantIntoASystemVariableIsNCTX05) {
  Rig r;
  const SourceRange where = Rig::at(7);
  EXPECT_FALSE(r.vars.write(1100, Value::empty(), where));
  EXPECT_FALSE(r.vars.write(5221, Value::empty(), where));
  EXPECT_FALSE(r.vars.write(3901, Value::empty(), where));
  EXPECT_FALSE(r.vars.writeNamed("M_SBK", {}, Value::empty(), where));
  EXPECT_FALSE(r.vars.write(3101, Value::empty(), where)); // read-only wins (A2 before A4)
  EXPECT_EQ(r.take(), (Codes{"NCTX05@7", "NCTX05@7", "NCTX05@7", "NCTX05@7", "2161@7"}));
  EXPECT_EQ(r.diags.errorCount(), 0u);
}

TEST(SystemVariables, ReadOnlyVariablesAre2161) {
  Rig r;
  r.nextLine = 100;
  for (int n : {0,    3100, 3101, 3102, 1035, 3011, 3012, 3007, 4000,   4039,   4130,
                4239, 4530, 5020, 5060, 5100, 5200, 5500, 5501, 100850, 117000, 8401})
    EXPECT_FALSE(r.set(n, 1)) << n;
  for (const std::string& c : r.codes())
    EXPECT_EQ(c, "2161");
  EXPECT_FALSE(r.set("PI", {}, 3));
  EXPECT_FALSE(r.set("FOFSVAL", 1, 3));
  const diag::Diagnostic d = r.diags.all().front();
  EXPECT_EQ(d.code, "2161");
  EXPECT_EQ(d.message, "#_PI macro variable is read-only (nct-macro.md §2.7 A2)");
  EXPECT_EQ(d.range.begin.line, 100u + 22);
  EXPECT_EQ(d.range.length, 5u);
}

TEST(SystemVariables, UnlistedNumbersAndNamesAreNCTX01) {
  Rig r;
  const int unlisted[] = {1,      34,     999,    1036,   1099,   1136,   2000,   3005,   3008,
                          3010,   3013,   3099,   3103,   3900,   3903,   4040,   4100,   4104,
                          4110,   4131,   4200,   4240,   4304,   4400,   4440,   5121,   5180,
                          5341,   5499,   5681,   7000,   7961,   8399,   8415,   8430,   8451,
                          8506,   8535,   9999,   10000,  11000,  14001,  21000,  23001,  99999,
                          100000, 100701, 100800, 100851, 101000, 105951, 116999, 117451, 120000,
                          120004, 120054, 120060, 120064, 121051, 200000, -1};
  for (int n : unlisted) {
    EXPECT_FALSE(r.vars.read(n, Rig::at(1))) << n;
    EXPECT_FALSE(r.vars.write(n, Value::of(0), Rig::at(2))) << n;
  }
  for (const std::string& c : r.codes())
    EXPECT_EQ(c, "NCTX01");
  struct Name {
    const char* name;
    std::optional<int> index;
  };
  const Name names[] = {{"FOO", {}},     {"ABSIO", 0}, {"ABSIO", 51}, {"ABSIO", {}}, {"PI", 1},
                        {"UI", 32},      {"UI", -1},   {"UO", {}},    {"WRG54", 4},  {"WRP1", 0},
                        {"FOFS9", 1},    {"BUFX", {}}, {"M_SBK", 0},  {"BUFG", 40},  {"OFSHG", 0},
                        {"OFSHG", 1000}, {"WZP", 1},   {"WZP0", 1},   {"WZG60", 1},  {"CNTBS", 1}};
  for (const Name& n : names) {
    EXPECT_FALSE(r.vars.readNamed(n.name, n.index, Rig::at(3))) << n.name;
    EXPECT_FALSE(r.vars.writeNamed(n.name, n.index, Value::of(0), Rig::at(4))) << n.name;
  }
  const std::vector<std::string> codes = r.codes();
  EXPECT_EQ(codes.size(), 2 * std::size(names));
  for (const std::string& c : codes)
    EXPECT_EQ(c, "NCTX01");
  EXPECT_FALSE(r.vars.read(3000, Rig::at(5))); // write-only message variables
  EXPECT_FALSE(r.vars.readNamed("MSG", {}, Rig::at(6)));
  EXPECT_EQ(r.take(), (Codes{"NCTX01@5", "NCTX01@6"}));
}

TEST(SystemVariables, ListedButNotModelledIsGCX030) {
  Rig r;
  r.nextLine = 111;
  EXPECT_FALSE(r.vars.read(8401, Rig::at(110)));                // tool data
  EXPECT_FALSE(r.set(8400, 10));                                // 111: R/W, but no magazine
  EXPECT_TRUE(r.set(120001, 30));                               // 112: basic rotation, stored
  EXPECT_TRUE(r.set("WRP2", 3, 1));                             // 113
  EXPECT_FALSE(r.set(5204, 1));                                 // 114: common offset of axis 4
  EXPECT_FALSE(r.vars.write(3000, Value::of(1), Rig::at(115))); // the expander's messages
  EXPECT_EQ(r.take(), (Codes{"GCX030@110", "GCX030@111", "GCX030@114", "GCX030@115"}));
  EXPECT_EQ(r.get(120001), 30); // stored; moving in a rotated system is GCX030 (interpreter)
  EXPECT_EQ(r.get("WRP2", 3), 1);
  EXPECT_TRUE(r.set(120053, 0));
  EXPECT_TRUE(r.set("FOFS2", 1, 4)); // G54.2 table: stored
  EXPECT_EQ(r.get(5541), 4);
  EXPECT_EQ(r.get(117101), 4);
  EXPECT_EQ(r.get(5500), 0);
  EXPECT_EQ(r.get("FOFSVAL", 1), 0);
  EXPECT_TRUE(r.codes().empty());
}

TEST(SystemVariables, NumberOfSymbols) {
  EXPECT_EQ(nct::sysvar::numberOf("ALM", {}), 3000);
  EXPECT_EQ(nct::sysvar::numberOf("msgbox", {}), 3107);
  EXPECT_EQ(nct::sysvar::numberOf("ABSIO", 3), 100003);
  EXPECT_EQ(nct::sysvar::numberOf("WZP2", 1), 101051);
  EXPECT_EQ(nct::sysvar::numberOf("WRG55", 2), 120012);
  EXPECT_EQ(nct::sysvar::numberOf("WRP1", 1), 120061);
  EXPECT_EQ(nct::sysvar::numberOf("FOFS8", 50), 117450);
  EXPECT_EQ(nct::sysvar::numberOf("ACTWZP", {}), 4330);
  EXPECT_EQ(nct::sysvar::numberOf("INTT", {}), 4520);
  EXPECT_EQ(nct::sysvar::numberOf("UO", 31), 1131);
  EXPECT_EQ(nct::sysvar::numberOf("M_SBK", {}), std::nullopt);
  EXPECT_EQ(nct::sysvar::numberOf("NOPE", {}), std::nullopt);
}

} // namespace
} // namespace gcx::test
