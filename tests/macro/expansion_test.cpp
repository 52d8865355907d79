// The expansion pass against the test vectors of nct-macro.md §10: exact variable values and
// exact expanded motion, plus the limits and the provenance chain.
#include <gtest/gtest.h>

#include "passes/macro/evaluator.h"
#include "support/run_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

std::string value(const MacroRun& r, int n) {
  auto it = r.vars.find(n);
  if (it == r.vars.end()) return "?";
  return it->second.vacant ? "vac" : n4(it->second.number);
}

V withoutEnd(V v) {
  if (!v.empty() && v.back() == "END") v.pop_back();
  return v;
}

TEST(MacroSpec_10, TV08_GotoAndIfGoto) {
  MacroRun r = runMacro({{"O0001.nct", "#1=100\n#2=60\nGOTO[#1+#2]\n#3=1\nN160 #100=52.28\n"
                                       "#101=16.87\nIF[#100GT#101]GOTO210\n#102=1\n"
                                       "N210 #103=0\nN220 #103=#103+1\nIF[#103LT4]GOTO220\nM30\n"}},
                        "O0001.nct", {3, 102, 103});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 3), "vac");
  EXPECT_EQ(value(r, 102), "vac");
  EXPECT_EQ(value(r, 103), "4");
}

TEST(MacroSpec_10, TV09_IfThen) {
  MacroRun r = runMacro({{"O0001.nct", "#100=0\n#101=0\n#1=20\nIF[#1EQ20]THEN#100=3.15\n"
                                       "IF[#100GT3.15]#101=5\nM30\n"}},
                        "O0001.nct", {100, 101});
  EXPECT_EQ(value(r, 100), "3.15");
  EXPECT_EQ(value(r, 101), "0");
}

TEST(MacroSpec_10, TV10_WhileLoopManualMillingExample) {
  MacroRun r = runMacro({{"O0001.nct", "#1=0\n#2=10\nG0 X#2\nZ[#1+1]\nWHILE[#1GT-5.39]DO1\n"
                                       "#1=#1-0.2\n#2=-#2\nG1 Z#1 F100\nX#2 F500\nEND1\nG0 Z20\n"
                                       "M30\n"}},
                        "O0001.nct", {1, 2});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V expected{"R 10,0,0", "R 10,0,1"};
  for (int k = 1; k <= 27; ++k) {
    expected.push_back("L " + n4(k % 2 ? 10 : -10) + ",0," + n4(-0.2 * k) + " F100");
    expected.push_back("L " + n4(k % 2 ? -10 : 10) + ",0," + n4(-0.2 * k) + " F500");
  }
  expected.push_back("R -10,0,20");
  EXPECT_EQ(withoutEnd(r.motion()), expected);
  EXPECT_EQ(value(r, 1), "-5.4");
  EXPECT_EQ(value(r, 2), "-10");
}

TEST(MacroSpec_10, TV11_NestedLoopsLeavingALoopReusingAnId) {
  MacroRun r = runMacro({{"O0001.nct", "#100=0\n#1=1\nWHILE[#1LE3]DO1\n#2=1\nWHILE[#2LE4]DO2\n"
                                       "#100=#100+#1*#2\n#2=#2+1\nEND2\n#1=#1+1\nEND1\n#3=0\nDO1\n"
                                       "#3=#3+1\nIF[#3GE5]GOTO50\nEND1\nN50 #4=#3*2\nM30\n"}},
                        "O0001.nct", {100, 1, 2, 3, 4});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 100), "60");
  EXPECT_EQ(value(r, 1), "4");
  EXPECT_EQ(value(r, 2), "5");
  EXPECT_EQ(value(r, 3), "5");
  EXPECT_EQ(value(r, 4), "10");
}

TEST(MacroSpec_10, TV12_JumpingIntoALoop) {
  MacroRun r = runMacro({{"O0001.nct", "#1=0\n#2=0\nGOTO150\nWHILE[#1LT3]DO1\n#1=#1+1\n"
                                       "N150 #2=#2+10\nEND1\nM30\n"}},
                        "O0001.nct", {1, 2});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 1), "3");
  EXPECT_EQ(value(r, 2), "40");
}

TEST(MacroSpec_10, TV13_G65SpecificationIAndControlWords) {
  MacroRun r = runMacro(
      {{"O0001.nct", "#1=7\nG65 P9100 L1 A1.5 B-2 C3 X10 Y20 Z30 M3 S500 F200 H4\n#101=#1\nM30\n"},
       {"O9100.nct", "#150=#1\n#151=#2\n#152=#3\n#153=#9\n#154=#10\n#155=#11\n#156=#12\n"
                     "#157=#13\n#158=#16\n#159=#19\n#160=#24\n#161=#26\n#162=#4\nM99\n"}},
      "O0001.nct", {150, 151, 152, 153, 154, 155, 156, 157, 158, 159, 160, 161, 162, 101});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 150), "1.5");
  EXPECT_EQ(value(r, 151), "-2");
  EXPECT_EQ(value(r, 152), "3");
  EXPECT_EQ(value(r, 153), "200");
  EXPECT_EQ(value(r, 154), "65");
  EXPECT_EQ(value(r, 155), "4");
  EXPECT_EQ(value(r, 156), "1");
  EXPECT_EQ(value(r, 157), "3");
  EXPECT_EQ(value(r, 158), "9100");
  EXPECT_EQ(value(r, 159), "500");
  EXPECT_EQ(value(r, 160), "10");
  EXPECT_EQ(value(r, 161), "30");
  EXPECT_EQ(value(r, 162), "vac");
  EXPECT_EQ(value(r, 101), "7");
  EXPECT_EQ(withoutEnd(r.motion()), V{}); // M3 S500 were arguments
}

TEST(MacroSpec_10, TV14_SpecificationIIAndMixed) {
  const std::string o2200 = "#150=#1\n#151=#2\n#152=#5\n#153=#8\n#154=#11\nM99\n";
  MacroRun r = runMacro(
      {{"O0001.nct", "G65 P2200 A2.12 B3.213 J36.9 E129.73 J-12\nM30\n"}, {"O2200.nct", o2200}},
      "O0001.nct", {150, 151, 152, 153, 154});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 152), "36.9");
  EXPECT_EQ(value(r, 153), "129.73");
  EXPECT_EQ(value(r, 154), "-12");
  MacroRun ijk = runMacro({{"O0001.nct", "G65 P2201 I1 J2 K3 I4 J5 K6\nM30\n"},
                           {"O2201.nct", "#160=#4\n#161=#5\n#162=#6\n#163=#7\n#164=#8\n#165=#9\n"
                                         "#166=#10\nM99\n"}},
                          "O0001.nct", {160, 163, 165, 166});
  ASSERT_TRUE(ijk.errors.empty()) << ijk.rendered;
  EXPECT_EQ(value(ijk, 160), "1");
  EXPECT_EQ(value(ijk, 163), "4");
  EXPECT_EQ(value(ijk, 165), "6");
  EXPECT_EQ(value(ijk, 166), "65");
}

TEST(MacroSpec_10, TV15_NAsAnArgument) {
  MacroRun r = runMacro({{"O0001.nct", "N130 G65 P9101 X12.3 Y32.6 N250\nM30\n"},
                         {"O9101.nct", "#150=#24\n#151=#25\n#152=#14\nM99\n"}},
                        "O0001.nct", {150, 151, 152});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 150), "12.3");
  EXPECT_EQ(value(r, 151), "32.6");
  EXPECT_EQ(value(r, 152), "250");
}

TEST(MacroSpec_10, TV16_LocalLevelsM98SharesG65Isolates) {
  MacroRun r =
      runMacro({{"O0001.nct", "#1=10\nM98 P20\n#101=#1\nG65 P21 A5\n#102=#1\n#103=#2\nM30\n"},
                {"O0020.nct", "#1=#1+1\nM99\n"},
                {"O0021.nct", "#1=#1*2\n#104=#1\n#2=99\nM99\n"}},
               "O0001.nct", {101, 102, 103, 104});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 101), "11");
  EXPECT_EQ(value(r, 104), "10");
  EXPECT_EQ(value(r, 102), "11");
  EXPECT_EQ(value(r, 103), "vac");
}

TEST(MacroSpec_10, TV17_RecursionAndTheSixteenLevelLimit) {
  const std::string o9300 =
      "IF[#1GT1]GOTO10\n#100=1\nM99\nN10 G65 P9300 A[#1-1]\n#100=#100*#1\nM99\n";
  MacroRun five =
      runMacro({{"O0001.nct", "G65 P9300 A5\nM30\n"}, {"O9300.nct", o9300}}, "O0001.nct", {100});
  ASSERT_TRUE(five.errors.empty()) << five.rendered;
  EXPECT_EQ(value(five, 100), "120");
  MacroRun sixteen =
      runMacro({{"O0001.nct", "G65 P9300 A16\nM30\n"}, {"O9300.nct", o9300}}, "O0001.nct", {100});
  ASSERT_TRUE(sixteen.errors.empty()) << sixteen.rendered;
  EXPECT_EQ(value(sixteen, 100), "20922789888000");
  MacroRun deep =
      runMacro({{"O0001.nct", "G65 P9300 A17\nM30\n"}, {"O9300.nct", o9300}}, "O0001.nct");
  EXPECT_EQ(deep.errors, V{"O9300.nct:4:1 NCTX03"});
}

TEST(MacroSpec_10, TV18_G65WithLStartsEachRunFresh) {
  MacroRun r = runMacro({{"O0001.nct", "#100=0\nG65 P9102 L3 A2\nM30\n"},
                         {"O9102.nct", "#1=#1+1\n#100=#100+#1\n#101=#12\nM99\n"}},
                        "O0001.nct", {100, 101});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 100), "9");
  EXPECT_EQ(value(r, 101), "3");
}

TEST(MacroSpec_10, TV23_M98WithLAndM99WithL) {
  MacroRun r = runMacro({{"O0001.nct", "#100=0\nM98 P11 L20\n#101=#100\nM98 P12 L6\nM30\n"},
                         {"O0011.nct", "#100=#100+1\nIF[#100NE1]GOTO9\nM99 L5\nN9 M99\n"},
                         {"O0012.nct", "#102=#102+1\nM99\n"}},
                        "O0001.nct", {100, 101, 102});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 100), "6");
  EXPECT_EQ(value(r, 101), "6");
  EXPECT_EQ(value(r, 102), "6");
}

TEST(MacroSpec_10, TV20_G66DrillingAfterEachPositioning) {
  MacroRun r = runMacro({{"O0001.nct", "G66 P1250 Z-100 R-1 X2 F130\nN100 G91 G0 X100\nN110 Y30\n"
                                       "N180 X150\nG67\nN190 X10\nM30\n"},
                         {"O1250.nct", "G0 Z#18\nG1 Z#26 F#9\nG4 P#24\nG0 Z-[#18+#26]\nM99\n"}},
                        "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  V expected;
  for (const char* at : {"100,0", "100,30", "250,30"}) {
    expected.push_back(std::string("R ") + at + ",0");
    expected.push_back(std::string("R ") + at + ",-1");
    expected.push_back(std::string("L ") + at + ",-101 F130");
    expected.push_back("DW 2s");
    expected.push_back(std::string("R ") + at + ",0");
  }
  expected.push_back("R 260,30,0");
  EXPECT_EQ(withoutEnd(r.motion()), expected);
}

TEST(MacroSpec_10, TV21_NestedG66) {
  MacroRun r = runMacro({{"O0001.nct", "F500\nN10 G66 P2\nN11 G1 G91 Z10\nN12 G66 P3\nN13 Z20\n"
                                       "N14 G67\nN15 G67\nN16 Z-5\nM30\n"},
                         {"O0002.nct", "N20 X4\nN21 M99\n"},
                         {"O0003.nct", "N30 Z2\nN31 Z3\nN32 M99\n"}},
                        "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()),
            (V{"L 0,0,10 F500", "L 4,0,10 F500", "L 4,0,30 F500", "L 4,0,32 F500", "L 8,0,32 F500",
               "L 8,0,35 F500", "L 12,0,35 F500", "L 12,0,30 F500"}));
}

TEST(MacroSpec_10, TV22_G661AxisExchange) {
  MacroRun r = runMacro(
      {{"O0001.nct", "G66.1 P400\nG18 X0 Y0 Z-5\nG1 X40 Y30 F1000\nG3 X0 Y50 I-40 J-30\nG1 Y0\n"
                     "G67\nM30\n"},
       {"O0400.nct", "IF[#10EQ66.1]GOTO10\nG#10 X-#24 Y#26 Z#25 I-#4 K#5 R#18 F#9\nN10 M99\n"}},
      "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 0,-5,0", "L -40,-5,30 F1000",
                                       "CCW 0,-5,50 C0,0 r50 θ53.1301", "L 0,-5,0 F1000"}));
}

TEST(NctSpec_7, TV24_SubprogramRepetitionAndM99P) {
  MacroRun r = runMacro({{"O0010.nct", "G90 G0 X0 Y0\nG1 F100\nM98 P11 L3\nM30\n"},
                         {"O0011.nct", "G91 G1 X10\nG90\nM99\n"}},
                        "O0010.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(withoutEnd(r.motion()), (V{"L 10,0,0 F100", "L 20,0,0 F100", "L 30,0,0 F100"}));
  MacroRun p = runMacro({{"O0001.nct", "N101 M98 P11\nN102 G0 X100\nN250 G0 X200\nM30\n"},
                         {"O0011.nct", "M99 P250\n"}},
                        "O0001.nct");
  ASSERT_TRUE(p.errors.empty()) << p.rendered;
  EXPECT_EQ(withoutEnd(p.motion()), V{"R 200,0,0"});
  MacroRun wrongExtension =
      runMacro({{"O0001.nct", "M98 P11\nM30\n"}, {"O0011.prg", "M99\n"}}, "O0001.nct");
  EXPECT_EQ(wrongExtension.errors, V{"O0001.nct:1:5 NCTX07"});
}

TEST(MacroSpec_10, TV24_M99PAndM99InTheMainProgram) {
  MacroRun p = runMacro({{"O0001.nct", "N101 M98 P13\nN102 #1=1\nN250 #2=2\nM30\n"},
                         {"O0013.nct", "#3=3\nM99 P250\n"}},
                        "O0001.nct", {1, 2, 3});
  ASSERT_TRUE(p.errors.empty()) << p.rendered;
  EXPECT_EQ(value(p, 1), "vac");
  EXPECT_EQ(value(p, 2), "2");
  EXPECT_EQ(value(p, 3), "3");
  MacroRun loop =
      runMacro({{"O0001.nct", "#100=#100+1\nIF[#100GE3]GOTO10\nM99\nN10 #101=#100\nM30\n"}},
               "O0001.nct", {100, 101});
  ASSERT_TRUE(loop.errors.empty()) << loop.rendered;
  EXPECT_EQ(value(loop, 100), "3");
  EXPECT_EQ(value(loop, 101), "3");
  machine::Setup skipOn;
  skipOn.blockSkip = {1};
  MacroRun skipped = runMacro({{"O0001.nct", "#100=#100+1\n/ M99\n#101=1\nM30\n"}}, "O0001.nct",
                              {100, 101}, skipOn);
  ASSERT_TRUE(skipped.errors.empty()) << skipped.rendered;
  EXPECT_EQ(value(skipped, 100), "1");
  EXPECT_EQ(value(skipped, 101), "1");
}

TEST(MacroSpec_10, TV30_G10AndOffsetVariables) {
  MacroRun r =
      runMacro({{"O0001.nct", "G90 G10 L2 P1 X100 Y50\n#1=#5221\n#2=#_WZG54[2]\nG10 L10 P5 R12.5\n"
                              "G91 G10 L10 P5 R0.5\n#3=#10005\nG90 G10 L10 P5 RI1\n#4=#_OFSHG[5]\n"
                              "#11005=-0.02\n#5=#11005\nG10 L2 P1 I30\n#6=#120001\nM30\n"}},
               "O0001.nct", {1, 2, 3, 4, 5, 6});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 1), "100");
  EXPECT_EQ(value(r, 2), "50");
  EXPECT_EQ(value(r, 3), "13");
  EXPECT_EQ(value(r, 4), "14");
  EXPECT_EQ(value(r, 5), "-0.02");
  EXPECT_EQ(value(r, 6), "30");
  EXPECT_EQ(withoutEnd(r.motion()), V{});
}

TEST(MacroSpec_10, TV31_ModalInformationAndIndirectAxes) {
  MacroRun r = runMacro(
      {{"O0001.nct", "G17 G90 G54.1 P1\n#1=#4002\n#2=#4003\n#3=#4014\n#4=#4012\nG91 G18\n"
                     "#5=#_BUFG[2]\n#6=#4003\n#101=AXNUM[X]\n#102=AXNUM[Y]\n#103=AXNUM[Z]\n"
                     "G90 G0 AX[#101]=10 AX[#102]=20 AX[#103]=30\nM30\n"}},
      "O0001.nct", {1, 2, 3, 4, 5, 6, 101, 102, 103});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 1), "17");
  EXPECT_EQ(value(r, 2), "90");
  EXPECT_EQ(value(r, 3), "154");
  EXPECT_EQ(value(r, 4), "67");
  EXPECT_EQ(value(r, 5), "18");
  EXPECT_EQ(value(r, 6), "91");
  EXPECT_EQ(value(r, 101), "1");
  EXPECT_EQ(value(r, 103), "3");
  EXPECT_EQ(withoutEnd(r.motion()), V{"R 10,20,30"});
  EXPECT_EQ(runMacro({{"O0001.nct", "#104=AXNUM[U]\nM30\n"}}, "O0001.nct").errors,
            V{"O0001.nct:1:6 2017"});
  EXPECT_EQ(runMacro({{"O0001.nct", "G0 AX[9]=1\nM30\n"}}, "O0001.nct").errors,
            V{"O0001.nct:1:4 2018"});
}

TEST(MacroSpec_10, TV32_DomainAndAssignmentErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"#1=SQRT[-1]", "1:4 2122"},  {"#1=TAN[90]", "1:4 2116"},       {"#1=TAN[-270]", "1:4 2116"},
      {"#1=ASIN[1.5]", "1:4 2117"}, {"#1=ACOS[-1.0001]", "1:4 2117"}, {"#1=LN0", "1:4 2118"},
      {"#1=LN[-2]", "1:4 2118"},    {"#1=LN#0", "1:4 2118"},          {"#1=5/0", "1:4 2093"},
      {"#1=5MOD#0", "1:4 2093"},    {"#3101=3", "1:1 2161"},          {"#0=1", "1:1 2161"},
      {"#1100=2", "1:1 2092"},      {"#50=1", "1:1 NCTX01"},
  };
  for (auto [block, expected] : cases) {
    MacroRun r = runMacro({{"O0001.nct", std::string(block) + "\nM30\n"}}, "O0001.nct");
    EXPECT_EQ(r.errors, V{std::string("O0001.nct:") + expected}) << block << "\n" << r.rendered;
  }
  MacroRun bit = runMacro({{"O0001.nct", "#1100=0.4\nM30\n"}}, "O0001.nct", {1100});
  ASSERT_TRUE(bit.errors.empty()) << bit.rendered;
  EXPECT_EQ(value(bit, 1100), "1");
}

TEST(MacroSpec_10, TV27_MCodeMacroAndMCodeSubprogram) {
  machine::Setup s;
  s.parameters["N1743"] = 500;
  s.parameters["N1744"] = 3500;
  s.parameters["N1745"] = 20;
  s.parameters["N1720"] = 60;
  MacroRun r =
      runMacro({{"O0001.nct", "#1=4\nN10 M505 X1.5 M3\nG0 X5 M60\nM30\n"},
                {"SystemMacros/Channel1/O3505.nct", "#150=#24\n#151=#13\n#152=#1\nM505\nM99\n"},
                {"SystemMacros/Channel1/O9000.nct", "#153=#1\nM60\nM99\n"}},
               "O0001.nct", {150, 151, 152, 153}, s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 150), "1.5");
  EXPECT_EQ(value(r, 151), "3");
  EXPECT_EQ(value(r, 152), "vac");
  EXPECT_EQ(value(r, 153), "4");
  EXPECT_EQ(withoutEnd(r.motion()), V{"R 5,0,0"});
}

TEST(MacroSpec_10, TV28_TCodeSubprogram) {
  machine::Setup s;
  s.parameters["N1746.TM"] = 1;
  MacroRun r = runMacro({{"O0001.nct", "G0 X10 T5\nM30\n"},
                         {"SystemMacros/Channel1/O9034.nct", "#150=#199\nT#199 M6\nM99\n"}},
                        "O0001.nct", {150, 199}, s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 199), "5");
  EXPECT_EQ(value(r, 150), "5");
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 10,0,0", "EV T5 M6"}));
}

TEST(MacroSpec_10, TV29_GCodeMacrosSingleAndModal) {
  machine::Setup s;
  s.parameters["N1704"] = 101;
  s.parameters["N1705"] = -120;
  MacroRun r = runMacro(
      {{"O0001.nct", "G101 X5 P7 L2\nG120 Z-1\nG0 X10\nG1 Y10 F100\nG67\nG0 X0\nM30\n"},
       {"SystemMacros/Channel1/O9010.nct", "#150=#24\n#151=#16\n#152=#12\n#153=#10\nM99\n"},
       {"SystemMacros/Channel1/O9011.nct", "#160=#160+1\nM99\n"}},
      "O0001.nct", {150, 151, 152, 153, 160}, s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 150), "5");
  EXPECT_EQ(value(r, 151), "7");
  EXPECT_EQ(value(r, 152), "2");
  EXPECT_EQ(value(r, 153), "101");
  EXPECT_EQ(value(r, 160), "2");
  EXPECT_EQ(withoutEnd(r.motion()), (V{"R 10,0,0", "L 10,10,0 F100", "R 0,10,0"}));
}

TEST(MacroSpec_10, TV25_DprntAndBprnt) {
  const std::string program = "#130=35.897421\n#500=-150.8\n#10=14.8\n#110=318.49362\n"
                              "#120=0.723415\n#112=23.9\nPOPEN31\nDPRNT[RESULT]\n"
                              "DPRNT[X#130[53]Y#500[53]T#10[20]]\n"
                              "BPRNT[C*/X#110[3]Y#120[3]M#112[0]]\nPCLOS31\nM30\n";
  MacroRun r = runMacro({{"O0001.nct", program}}, "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  const std::string bprnt("\x43\x20\x2F\x58\x00\x04\xDC\x1E\x59\x00\x00\x02\xD3\x4D\x00\x00"
                          "\x00\x18\x0D\x0A",
                          20);
  EXPECT_EQ(r.printed, "(file RESULT)\r\n%\r\nX    35.897Y-  150.800T 15\r\n" + bprnt + "%\r\n");
  EXPECT_EQ(withoutEnd(r.motion()), V{});
  machine::Setup pnt;
  pnt.parameters["N1757.PNT"] = 1;
  MacroRun omitted = runMacro({{"O0001.nct", program}}, "O0001.nct", {}, pnt);
  EXPECT_NE(omitted.printed.find("X35.897Y-150.800T15\r\n"), std::string::npos);
}

TEST(MacroSpec_5_8, AsciiLetterSubprogramCall) {
  machine::Setup s;
  s.parameters["N1747"] = 'Q'; // the letter Q (ASCII 81) calls O0777, its value in #191
  s.parameters["N1751"] = 777;
  MacroRun r = runMacro({{"O0001.nct", "G0 X1 Q42\nM30\n"}, {"O0777.nct", "#150=#191\nM99\n"}},
                        "O0001.nct", {150, 191}, s);
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 150), "42");
  EXPECT_EQ(withoutEnd(r.motion()), V{"R 1,0,0"});
}

TEST(MacroSpec_12, VacantOrderSwitchForFanucControls) {
  const macro::Value vacant = macro::Value::empty(), zero = macro::Value::of(0);
  EXPECT_TRUE(macro::compare(vacant, ir::RelOp::Gt, zero)); // the manual's table (§2.5)
  EXPECT_FALSE(macro::compare(vacant, ir::RelOp::Gt, zero, macro::VacantOrder::Fanuc));
  EXPECT_TRUE(macro::compare(vacant, ir::RelOp::Ge, zero, macro::VacantOrder::Fanuc));
  EXPECT_FALSE(macro::compare(vacant, ir::RelOp::Eq, zero, macro::VacantOrder::Fanuc));
}

TEST(MacroExpansion, RunawayLoopHitsTheJumpLimit) {
  MacroRun r = runMacro({{"O0001.nct", "#1=0\nWHILE[#1GE0]DO1\n#1=#1+1\nEND1\nM30\n"}}, "O0001.nct",
                        {}, {}, 1000);
  EXPECT_EQ(r.errors, V{"O0001.nct:4:1 GCX040"});
}

TEST(MacroExpansion, ErrorsAreLocatedInTheCalledProgram) {
  MacroRun r =
      runMacro({{"O0001.nct", "M98 P20\nM30\n"}, {"O0020.nct", "#1=1/0\nM99\n"}}, "O0001.nct");
  EXPECT_EQ(r.errors, V{"O0020.nct:1:4 2093"});
  MacroRun missing =
      runMacro({{"O0001.nct", "M98 P20\nM30\n"}, {"O0020.nct", "G0 X1\n"}}, "O0001.nct");
  EXPECT_EQ(missing.errors, V{"O0001.nct:1:1 NCTX08"});
  MacroRun readOnly = runMacro({{"O0001.nct", "#0=1\nM30\n"}}, "O0001.nct");
  EXPECT_EQ(readOnly.errors, V{"O0001.nct:1:1 2161"});
  MacroRun g65 = runMacro({{"O0001.nct", "G65 A1\nM30\n"}}, "O0001.nct");
  EXPECT_EQ(g65.errors, V{"O0001.nct:1:1 2004"});
}

TEST(MacroExpansion, ProvenanceNamesTheWholeChain) {
  // a block from a loop inside a G65 macro called from a subprogram
  MacroRun r = runMacro({{"O0001.nct", "M98 P20\nM30\n"},
                         {"O0020.nct", "G65 P30 A2\nM99\n"},
                         {"O0030.nct", "#2=0\nWHILE[#2LT#1]DO1\n#2=#2+1\nG0 X#2\nEND1\nM99\n"}},
                        "O0001.nct");
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  ASSERT_GE(r.events.size(), 2u);
  const motion::Event& second = r.events[1]; // G0 X2, in the second loop iteration
  ASSERT_EQ(second.from.chain.size(), 3u);
  EXPECT_EQ(second.from.at.line, 4u);
  EXPECT_EQ(second.from.chain[0].what, "O0020 (M98 P20)");
  EXPECT_EQ(second.from.chain[0].call.line, 1u);
  EXPECT_EQ(second.from.chain[1].what, "O0030 (G65 P30)");
  EXPECT_EQ(second.from.chain[2].what, "loop DO1 iteration 2");
}

} // namespace
} // namespace gcx::test

namespace gcx::test {
namespace {

TEST(MacroSpec_9, G10L52WritesAParameterThatPrmReadsAndTheMachineUses) {
  // N1339 Radius Diff 0.5 accepts an arc whose end radius is 0.3 off (else alarm 2012)
  MacroRun r = runMacro({{"O0001.nct", "G10 L52\nN1339 R0.5\nG11\n#1=PRM[1339]\n"
                                       "G0 X10 Y0\nG3 X-10.3 Y0 I-10 F100\nM30\n"}},
                        "O0001.nct", {1});
  ASSERT_TRUE(r.errors.empty()) << r.rendered;
  EXPECT_EQ(value(r, 1), "0.5");
  EXPECT_EQ(r.motion().at(1), "CCW -10.3,0,0 C0,0 r10->10.3 θ180");
}

TEST(MacroExpansion, ErrorInACallCarriesTheCallChainAsNotes) {
  MacroRun r = runMacro({{"O0001.nct", "G65 P30 A1\nM30\n"},
                         {"O0030.nct", "M98 P20\nM99\n"},
                         {"O0020.nct", "#2=1/0\nM99\n"}},
                        "O0001.nct");
  EXPECT_EQ(r.errors, V{"O0020.nct:1:4 2093"});
  EXPECT_NE(r.rendered.find("note: in O0030 (G65 P30)"), std::string::npos) << r.rendered;
  EXPECT_NE(r.rendered.find("note: in O0020 (M98 P20)"), std::string::npos) << r.rendered;
}

} // namespace
} // namespace gcx::test
