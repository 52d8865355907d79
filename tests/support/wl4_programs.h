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

} // namespace gcx::test
