// Round trip through `gcx expand --to wl4` (wl4.md §5.1, §7, §8): every WL4 example, every
// differential program and the spec's vectors, expanded (calls, cycles and macro statements
// flattened into plain WL4 blocks), read back and run, move the tool as the original does by
// `gcx equiv`; and a KOI8-R file and its UTF-8 twin give identical results.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

class Wl4ExpandRoundTrip : public testing::Test {
protected:
  void write(const std::string& name, const std::string& bytes) { folder_.write(name, bytes); }
  CliResult gcx(const std::string& args) { return folder_.gcx(args); }
  /// Expands name to WL4 and compares both runs; the expanded text.
  std::string roundTrip(const std::string& name) {
    const CliResult e = gcx(fmt::format("expand {} --to wl4 -o expanded.wl4", name));
    EXPECT_EQ(e.exitCode, 0) << name << "\n" << e.err;
    const CliResult q = gcx(fmt::format("equiv {} expanded.wl4", name));
    const std::string text = readFile(folder_.path() / "expanded.wl4");
    EXPECT_EQ(q.exitCode, 0) << name << "\n" << q.out << q.err << text;
    return text;
  }

  CliFolder folder_{"wl4-roundtrip"};
};

std::vector<fs::path> programs() {
  std::vector<fs::path> out = filesUnder(sourceDir() / "examples" / "wl4", {".wl4"});
  for (const fs::path& p : filesUnder(sourceDir() / "tests" / "differential" / "wl4", {".wl4"}))
    out.push_back(p);
  return out;
}

TEST_F(Wl4ExpandRoundTrip, EveryExampleAndDifferentialProgram) {
  const std::vector<fs::path> files = programs();
  ASSERT_GE(files.size(), 17u); // 2 examples, 15 differential programs
  for (const fs::path& f : files) {
    write(f.filename().string(), readFile(f));
    const std::string text = roundTrip(f.filename().string());
    // flattened: no call, no cycle selection and no jump is left to run twice
    EXPECT_EQ(text.find(" L0"), std::string::npos) << f << "\n" << text;
    EXPECT_EQ(text.find("G8"), std::string::npos) << f << "\n" << text;
  }
}

TEST_F(Wl4ExpandRoundTrip, TheSpecsVectors) {
  // wl4.md §8 in the spelling of tests/conformance (the machine runs them as listed there)
  const char* const vectors[] = {
      "%TV1\nG90G54G17G0X0Y100\nG12X100Y0F100\nM2\n%\n",
      "%TV2\nG90 G17 G0 X0 Y100\nG13 X100 Y0 F100\nG91 G12 X-20 Y-20\nG90 M2\n%\n",
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
  int k = 0;
  for (const char* v : vectors) {
    const std::string name = fmt::format("v{}.wl4", ++k);
    write(name, v);
    roundTrip(name);
  }
}

TEST_F(Wl4ExpandRoundTrip, AKoi8rFileAndItsUtf8TwinGiveIdenticalResults) {
  // "$ ДЕТАЛЬ ВАЛ" in KOI8-R bytes and in UTF-8: comments are the only place for Cyrillic (§1.1)
  const std::string koi8 = "%P\n$ \xE4\xE5\xF4\xE1\xEC\xF8 \xF7\xE1\xEC\nG0 X10 Y5\n"
                           "G1 X20 F100 $ \xF3\xF4\xEF\xF0\nM2\n%\n";
  const std::string utf8 = "%P\n$ \u0414\u0415\u0422\u0410\u041B\u042C \u0412\u0410\u041B\n"
                           "G0 X10 Y5\nG1 X20 F100 $ \u0421\u0422\u041E\u041F\nM2\n%\n";
  write("k.wl4", koi8);
  write("u.wl4", utf8);
  const CliResult a = gcx("expand k.wl4 --to canonical");
  const CliResult b = gcx("expand u.wl4 --to canonical --encoding utf-8");
  EXPECT_EQ(a.exitCode, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out.find("G1 X20"), std::string::npos) << a.out;
  const CliResult fa = gcx("fmt k.wl4");
  const CliResult fb = gcx("fmt u.wl4 --encoding utf-8");
  EXPECT_EQ(fa.exitCode, 0) << fa.err;
  EXPECT_EQ(fa.out, fb.out); // comments come out in UTF-8 both times
  EXPECT_NE(fa.out.find("\u0414\u0415\u0422\u0410\u041B\u042C"), std::string::npos) << fa.out;
}

} // namespace
} // namespace gcx::test
