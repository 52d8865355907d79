// The WL4 programs the round-trip tests run: every example, every differential program and the
// vectors of wl4.md §8 that run on the mill profile.
#pragma once
#include <string>
#include <vector>

#include "support/cli_folder.h"

namespace gcx::test {

inline std::vector<fs::path> wl4Programs() {
  std::vector<fs::path> out = filesUnder(sourceDir() / "examples" / "wl4", {".wl4"});
  for (const fs::path& p : filesUnder(sourceDir() / "tests" / "differential" / "wl4", {".wl4"}))
    out.push_back(p);
  return out;
}

// wl4.md §8 in the spelling of tests/conformance (the mill profile runs them as listed there)
inline std::vector<std::string> wl4SpecVectors() {
  return {
      "%TV1\nG90G54G17G0X0Y100\nG12X100Y0F100\nM2\n%\n",
      "%TV2\nG90 G17 G0 X0 Y100\nG13 X100 Y0 F100\nG91 G12 X-20 Y-20\nG90 M2\n%\n",
      "%TV3\nG90G54G17G1X-50Y86.603F100\nG2X0Y100I50J-86.603\nG1X-50Y86.603\n"
      "G2X0Y100R100\nM2\n%\n",
      "%TV4\nG90 G17 G0 X10 Y10 Z5\nG1 U5 V-5 F200\nX30 W-10\nG91 X5 V5\nU-5\nM2\n%\n",
      "%TV7\nG90 G17 G0 X0 Y0 Z0\n#1=0\nN010 #1=(#1+1) G1 X(#1*10) F100\nIF (#1<3) N10\nM2\n%\n",
      "%TV8\nG90 G0 X50 Z150\n#1=5 #2=3\nG1 X0 Z100 F500 IF ((#1-#2)>0) Z0\n#1=1\n"
      "G1 X10 Z100 IF ((#1-#2)>0) Z0\nM2\n%\n",
      "%TV9\nG90 G17 G0 X0 Y0 Z0\n#1=5 #30=0\nL0702\nG1 X#1 Y#30 F100\nM2\n%\n"
      "%07\n#1=(#1*2) #30=(#30+#1)\nG91 G1 X#1 F200\nG90 M99\n%\n",
      "%TV10\nG90 G17 G0 X0 Y0 Z50\nG81 #2=2 #3=-10 F100\nX10 Y10\nX20\nG80\nG0 Z50\nM2\n%\n",
      "%TV11\nG90 G17 G0 X0 Y0 Z50\nG83 #2=1 #3=-17 #5=5 F100\nG90G0X100Y200\nG80\nM2\n%\n",
      "%TV13\nG18 G90 G0 X100 Z5\nG70 X60 Z-50 F0.2 #1=10 #2=10\nM2\n%\n",
      "%TV14\nG18 G90 G0 X50 Z-20\nG72 X30 W-5 F0.05 #1=6 #2=1\nM2\n%\n",
      "%TV15\nG18 G90 G0 X80 Z2\nG74 X50 Z-5 F0.05 #1=8\nM2\n%\n",
      "%TV16\nG18 G90 G0 X50 Z2\nG77 X40 Z-30 F0.3 #1=4 #2=2.5 #3=0.1\nM2\n%\n",
      "%TV17\nG18 G90 G0 X52 Z0\nG78 X20 Z-6 F0.2 #1=2 #2=3 #3=0.1\nM2\n%\n",
      "%TV20\nG90 G17 G0 X0 Y0 Z0\nG51 X-1\nG1 X10 Y5 F100\nG2 X20 Y15 I10 J0\nG50\nG0 X0 Y0\n"
      "M2\n%\n",
      "%TV22\n#1=1.0004 #2=1.0001\nIF3 (#1>#2) G1 X1 F100\nIF (#1>#2) G1 X2 F100\nM2\n%\n",
  };
}

/// A WL4 program with the setup it runs on (JSON, empty for none).
struct Wl4ProgramOnSetup {
  std::string name, text, setup;
};

// wl4.md §8 vectors that need a setup or the lathe, and the runnable examples of §7 (7 stops at
// M0, 16 loops for ever, 21-23 are the contour cycles, below): each as a whole program
inline std::vector<Wl4ProgramOnSetup> wl4ProgramsOnSetups() {
  const std::string lathe = R"({"wl4": {"parameters": {"lathe": 1, "b_chamfer": 1}}})";
  return {
      {"tv5",
       "%TV5\nG18 G90\nN20 G0 X0 Z0\nN21 G1 Z5 F100\nN22 X100\n"
       "/ N23 G0 Z100 M0 $ RUNS ONLY WITH THE FLAG\n/ N24 Z5\nN25 G1 Z20\nM2\n%\n",
       R"({"block_skip": [1]})"},
      {"tv6",
       "%TV6\nN5 #1=10 #2=20 #3=30 #4=40\nN10 G90 G0 X#1 Z#2 #1=(#1+#3) #2=(#2+#4)\n"
       "N15 X#1 Z#2\nN20 #5=(#4/2+15*(#3>#4))\nN25 #5=(#4/2+15*(#3<#4))\n"
       "N30 X#1=(ABS(#3-#4) + #5=(40.78*#2))\nM2\n%\n",
       ""},
      {"tv12", "%TV12\nG90 G17 G0 X0 Y0 Z20 S500 M3\nG84 #2=3 #3=-15 F750\nX30 Y40\nG80 M2\n%\n",
       ""},
      {"tv18",
       "%TV18\nG18 G90 G0 X30 Z5\n"
       "G31 X24 Z-20 F1.5 P0 I0 #1=1 #2=0.25 #3=0 #4=0 #5=1.5\nM2\n%\n",
       lathe},
      {"tv19", "%TV19\nG18 G90 G95 G0 X40 Z70\nG1 X100 F0.2 B10\nZ10\nM2\n%\n", lathe},
      {"tv21", "%TV21\nG92 X100 Y250 Z30\nG90 G0 X0 Y0\nG54 G0 X0 Y0\nM2\n%\n",
       R"({"work_offsets": {"G54": [200, 100, 0]}})"},
      {"example1", "%E1\nX.23\nZ123.4\nM2\n%\n", ""},
      {"example3", "%E3\nG18 G90\nX100Z86.603F0.2\nG2X0Z100I-50K-86.603\nG1 X40 Z0 F0.2\nM2\n%\n",
       lathe},
      {"example6", "%E6\nG0 X10 Y10 Z10\nN100 G36 Z0\nN101 G36 X0 Y0\nM2\n%\n", ""},
      {"example8", "%E8\nG18 G0 X0 Z0\nG94G38G2Z100R200F200\nM2\n%\n", ""},
      {"example9", "%E9\nG0 X10 Y20 Z5\nG92X100Y250Z30\nG1 X110 F100\nM2\n%\n", ""},
      {"example10",
       "%E10\nG0 X0 Y0\nG51X-1\nG1 X10 Y5 F100\nG51X1Y-1\nG1 X20 Y10\nG50\n"
       "G0 X0 Y0\nM2\n%\n",
       ""},
      {"example11", "%E11\nG51 S2000\nS1500 M3\nG0 X10\nM5\nM2\n%\n", ""},
      {"example12", "%E12\nG94 F10.4\nG1 X10\nG95 F0.5 S20 M3\nG1 X20\nM2\n%\n", ""},
      {"example13",
       "%E13\nG18 G90 G95\nN50 G0 X40 Z70\nN51 G1 X100 F0.2 B10\nN52 Z10\n"
       "N10 G0 X60 Z80\nN11 G3 X100 Z50 R50 B8 F0.2\nN12 G2 X80 Z40 R40\nM2\n%\n",
       lathe},
      {"example14", "%E14\n#1=4 #3=5 #4=1 #7=3 #20=7\nG0 X#20\nX#(#20)\nX#(ABS(#3-#4*2))\nM2\n%\n",
       ""},
      {"example17",
       "%E17\n#1=3 #2=1 #30=2\nN010 IF3 (#1>=#2) #1=(#1-0.5) N10\n"
       "IF (#30) #30=(#30-1)\nIF (#30<>0) #30=#30-1\nG1 X#1 Z#30 F500\n"
       "N20 G1 X0 Z100 F500 IF ((#1-#2)>0) Z0\nM2\n%\n",
       ""},
      {"example18", "%E18\nG0 X0\nL07\nL0703\nM2\n%\n%07\nG91 G1 X1 F100\nG90 M99\n%\n", ""},
  };
}

// The contour cycles of wl4.md §5.6 on the lathe: the manual's examples 21-23 (their elided
// blocks left out, G18 added; example 23's N124 gets the G1 the manual forgot: as printed it is
// a G2 without R, docs/wl4.md "Manual versus spec") and the spec's worked example. Their
// contours stand after M2.
inline std::vector<Wl4ProgramOnSetup> wl4ContourCyclePrograms() {
  const std::string lathe = R"({"wl4": {"parameters": {"lathe": 1}}})";
  return {
      {"example21",
       "%TEST_G77_1\nG18\nN9 G0 X10 Z40\nN10 G77 G0 X2 Z45 P120 Q124 I0.5 K0.5 E2 F0.7 S500 M3\n"
       "M2\nN120 G1 Z35 F0.3\nN121 G2 X5 Z25 R10\nN122 G3 X7 Z20 R8\nN123 G1 X8.5 Z18\n"
       "N124 Z5\n%\n",
       lathe},
      {"example22",
       "%TEST_G77\nG18\nN10 G0 Z100\nN11 T1 M6\nN12 G0 X10 Z40\n"
       "N13 G77 G41 G0 X2 Z45 P120 Q124 R0.5 E2 F0.7 S500 M3\nN14 G0 Z100\nN15 T2 M6\n"
       "N16 G0 X10 Z40\nN11 G77 G41 G0 X2 Z45 P120 Q124 R0.2 F0.3 S800\n"
       "N12 G77 G41 G0 X2 Z45 P120 Q124 F0.3 S800\nM2\nN120 G1 Z35\nN121 G2 X5 Z25 R10\n"
       "N122 G3 X7 Z20 R8\nN123 G1 X8.5 Z18\nN124 Z5\n%\n",
       lathe},
      {"example23",
       "%TEST_G78\nG18\nN10 G0 Z100\nN11 T1 M6\nN12 G0 X10 Z40\n"
       "N13 G78 G41 G0 X10 Z5 P120 Q124 R0.5 E2 F0.7 S500 M3\nN14 G0 Z100\nN15 T2 M6\n"
       "N16 G0 X10 Z40\nN11 G78 G41 G0 X10 Z5 P120 Q124 R0.2 F0.3 S800\n"
       "N12 G78 G41 G0 X10 Z5 P120 Q124 F0.3 S800\nM2\nN120 G1 X8.5\nN121 G1 X8 Z15\n"
       "N122 G3 X7 Z20 R10\nN123 G2 X5 Z25 R8\nN124 G1 Z40\n%\n",
       lathe},
      {"g77pq",
       "%P\nG18 G90 G0 X50 Z2\nG77 P200 Q202 G1 X30 Z0 I0 K0 E2.5 F0.25\nM2\nN200 G1 Z-20\n"
       "N201 X40 Z-30\nN202 X50\n%\n",
       lathe},
  };
}

} // namespace gcx::test
