// The Fanuc-style trap pairs (fms3000.md §9, wl4.md §9) translated between dialects: the result
// carries the target's meaning, not the code's name. Each case pins the text after the header and
// is proven equivalent by translate itself (exit 0).
#include <gtest/gtest.h>

#include <vector>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

struct File {
  const char* name;
  const char* text;
};

struct TrapPair {
  const char* name;
  std::vector<File> files; // the first is translated
  const char* to;          // target dialect
  const char* body;        // the output from its modal line on
};

void PrintTo(const TrapPair& p, std::ostream* os) {
  *os << p.name;
}

class TranslateTrapPairs : public testing::TestWithParam<TrapPair> {};

TEST_P(TranslateTrapPairs, TheResultHasTheTargetsMeaning) {
  const TrapPair& p = GetParam();
  CliFolder folder("translate-traps");
  for (const File& f : p.files)
    folder.write(f.name, f.text);
  const std::string in = p.files.front().name;
  const std::string out = "out." + std::string(p.to);
  const CliResult r = folder.gcx("translate " + in + " --to " + p.to + " -o " + out);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::string text = readFile(folder.path() / out);
  std::erase(text, '\r');
  // the body: after the heading's comment lines (NCT `( )`, WL4 `$`, FMS-3000 `rem`)
  std::size_t body = text.find("translated from");
  ASSERT_NE(body, std::string::npos) << text;
  body = text.find('\n', body) + 1;
  while (body < text.size() &&
         (text[body] == '(' || text[body] == '$' || text.compare(body, 4, "rem ") == 0))
    body = text.find('\n', body) + 1;
  EXPECT_EQ(text.substr(body), p.body);
}

const TrapPair kPairs[] = {
    // FMS-3000 M98 ends a program; NCT M98 calls one: the call is the target's own, P1000 (a
    // file of its own) or L99 (%1000 has no two-digit name)
    {"NctM98CallToFms3000IsAPCall",
     {{"A.nct", "G90 G0 X0 Y0\nM98 P1000\nM30\n"},
      {"O1000.nct", "O1000\nG1 X5 F100\nG0 Y5\nM99\n"}},
     "fms3000",
     "G90 G00 X0 Y0\nP1000\nM30\n"},
    {"NctM98CallToWl4IsAnLCall",
     {{"A.nct", "G90 G0 X0 Y0\nM98 P1000\nM30\n"},
      {"O1000.nct", "O1000\nG1 X5 F100\nG0 Y5\nM99\n"}},
     "wl4",
     "G90 G0 X0 Y0\nL99\nM30\n%\n%99\nG1 X5 F100\nG0 Y5\nM99\n%\n"},
    {"Fms3000M98EndToWl4IsM2",
     {{"J.fms", "G90 G00 X1\nM98\n"}},
     "wl4",
     "G90 G94 G17\nG0 X1 Y0 Z0\nM2\n%\n"},
    // FMS-3000 calls by P alone (Fanuc P is a dwell or an argument): NCT's call is M98 P
    {"Fms3000PCallToNctIsM98",
     {{"B.fms", "G90 G00 X0 Y0\nP19\nM30\n"}, {"19.fms", "G01 X5 F100\nG00 Y5\nM99\n"}},
     "nct",
     "G90 G0 X0 Y0\nM98 P19\nM30\n"},
    // WL4 L0102 calls %01 twice (Fanuc M98 P L): NCT's M98 P1 L2
    {"Wl4LCallToNctIsM98WithItsRepeats",
     {{"C.wl4", "%C\nG0 X0 Y0\nL0102\nM30\n%\n%01\nG91 G1 X5 F100\nM99\n%\n"}},
     "nct",
     "G0 X0 Y0\nM98 P1 L2\nM30\n"},
    // WL4 U is an increment of X (Fanuc mill U: an axis) and G4 E is seconds
    {"Wl4UAndDwellToNct",
     {{"D.wl4", "%D\nG90 G0 X10 Y0\nG1 U5 F100\nG4 E2\nM30\n%\n"}},
     "nct",
     "G90 G94 G17 G21\nG0 X10 Y0 Z0\nG1 X15 Y0 Z0 F100\nG4 P2\nM30\n"},
    {"Wl4UAndDwellToFms3000",
     {{"D.wl4", "%D\nG90 G0 X10 Y0\nG1 U5 F100\nG4 E2\nM30\n%\n"}},
     "fms3000",
     "G90 G94 G17\nG00 X10 Y0 Z0\nG01 X15 Y0 Z0 F100\nG04 E20\nM30\n"},
    // FMS-3000 G28 goes straight to machine zero on the axes it names (Fanuc: via the point)
    {"Fms3000G28ToNctIsARapidToMachineZero",
     {{"E.fms", "G90 G00 X10 Y10 Z5\nG28 X0\nM30\n"}},
     "nct",
     "G90 G94 G17 G21\nG0 X10 Y10 Z5\nG0 X0 Y10 Z5\nM30\n"},
    // FMS-3000 G10 is the helix qualifier (Fanuc/NCT G10: data input)
    {"Fms3000G10HelixToNctIsG3WithItsHeight",
     {{"F.fms", "G90 G00 X10 Y0 Z0\nG17 G03 G10 X-10 Y0 I-10 J0 Z-5 K-10 F100\nM30\n"}},
     "nct",
     "G90 G94 G17 G21\nG0 X10 Y0 Z0\nG3 X-10 Y0 Z-5 I-10 J0 F100\nM30\n"},
    {"Fms3000G10HelixToWl4IsG3WithItsHeight",
     {{"F.fms", "G90 G00 X10 Y0 Z0\nG17 G03 G10 X-10 Y0 I-10 J0 Z-5 K-10 F100\nM30\n"}},
     "wl4",
     "G90 G94 G17\nG0 X10 Y0 Z0\nG3 X-10 Y0 Z-5 I-10 J0 F100\nM30\n%\n"},
    // WL4 G51 X-1 mirrors X (Fanuc/NCT G51: scaling)
    {"Wl4G51MirrorToNctIsTheMirroredPath",
     {{"G.wl4", "%G\nG90 G0 X10 Y5\nG51 X-1\nG1 X20 F100\nG50\nG0 X0\nM30\n%\n"}},
     "nct",
     "G90 G94 G17 G21\nG0 X10 Y5 Z0\nG1 X-20 Y5 Z0 F100\nG0 X0 Y5 Z0\nM30\n"},
    {"NctG51ScalingToWl4IsTheScaledPath",
     {{"H.nct", "G90 G0 X0 Y0\nG51 X0 Y0 P2\nG1 X10 Y5 F100\nG50\nM30\n"}},
     "wl4",
     "G90 G94 G17\nG1 X20 Y10 Z0 F100\nM30\n%\n"},
    // WL4 G12 is a quarter-circle fillet (Fanuc G12: circle cutting)
    {"Wl4G12FilletToNctIsAQuarterArc",
     {{"I.wl4", "%I\nG90 G0 X0 Y0\nG12 X10 Y-10 F100\nM30\n%\n"}},
     "nct",
     "G90 G94 G17 G21\nG2 X10 Y-10 Z0 I0 J-10 F100\nM30\n"},
};

INSTANTIATE_TEST_SUITE_P(Translate, TranslateTrapPairs, testing::ValuesIn(kPairs),
                         [](const testing::TestParamInfo<TrapPair>& i) { return i.param.name; });

} // namespace
} // namespace gcx::test
