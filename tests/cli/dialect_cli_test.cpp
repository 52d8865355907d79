// The command line's dialect plumbing: --encoding, and --dialect / expand --to from the registry.
#include <gtest/gtest.h>

#include "support/cli_folder.h"

namespace gcx::test {
namespace {

using Result = CliResult;

class DialectCli : public testing::Test {
protected:
  fs::path write(const std::string& name, const std::string& bytes) {
    return folder_.write(name, bytes);
  }
  Result gcx(const std::string& args) { return folder_.gcx(args); }

  CliFolder folder_{"dialect-cli"};
};

// fmt writes the encoding it read, so its output reads back as the same program (it wrote
// UTF-8 before, which the same command line then read as KOI8-R mojibake).
TEST_F(DialectCli, FmtOfAKoi8rFileWritesKoi8r) {
  write("O0001.nct", "G1 X1 (\xF0\xF2\xE9\xF7\xE5\xF4)\nM30\n");
  const Result r = gcx("fmt O0001.nct --encoding koi8-r");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "G1 X1 (\xF0\xF2\xE9\xF7\xE5\xF4)\nM30\n");
}

TEST_F(DialectCli, CalledProgramsAreReadInTheChosenEncoding) {
  write("O0001.nct", "M98 P2 (\xCF)\nM30\n");
  write("O0002.nct", "G0 X5 (\xD0)\nM99\n");
  const Result r = gcx("expand O0001.nct --to nct --encoding cp1251");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "G0 X5\nM30\n");
  // UTF-8, NCT's default, rejects the CP1251 byte of the called program
  EXPECT_NE(gcx("check O0002.nct").err.find("O0002.nct:1:8: error: invalid UTF-8"),
            std::string::npos);
}

TEST_F(DialectCli, InvalidByteIsALocatedErrorWithExitOne) {
  write("O0001.nct", "G1 X1\n(\x98)\n");
  const Result r = gcx("check O0001.nct --encoding cp1251");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("O0001.nct:2:2: error: byte 0x98 is not valid cp1251 text; choose the "
                       "file's encoding with --encoding [GCX008]"),
            std::string::npos)
      << r.err;
}

TEST_F(DialectCli, UnknownEncodingOrDialectIsAUsageError) {
  write("O0001.nct", "M30\n");
  EXPECT_EQ(gcx("check O0001.nct --encoding latin1").exitCode, 2);
  const Result r = gcx("check O0001.nct --dialect fms");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("fms not in {nct,fms3000,wl4}"), std::string::npos) << r.err;
}

TEST_F(DialectCli, ExpandTargetsComeFromTheRegistry) {
  write("O0001.nct", "G81 X1 Y1 Z-1 R1 F100\nG80\nM30\n");
  Result r = gcx("expand O0001.nct --to canonical --keep cycles");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "gcx: error: --keep cycles needs a target with canned cycles (--to nct, --to "
                   "fms3000); canonical motion has none\n");
  r = gcx("expand O0001.nct --to nct --keep cycles");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "G81 X1 Y1 Z-1 R1 F100\nG80\nM30\n");
}

// Writing one dialect's blocks as another's would copy codes whose meaning differs (NCT G4 P is
// seconds, FMS-3000 G04 P is not a dwell): that is translation, which translate does.
TEST_F(DialectCli, ExpandToAnotherDialectIsRefused) {
  write("O0001.nct", "G4 P1.5\nG81 X1 Y1 Z-1 R1 F100\nG80\nM30\n");
  Result r = gcx("expand O0001.nct --to fms3000 -o out.fms");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "gcx: error: --to fms3000 from a nct program is a translation between "
                   "dialects: gcx translate --to fms3000 writes its motion with the codes' "
                   "meaning\n");
  EXPECT_FALSE(fs::exists(folder_.path() / "out.fms"));
  r = gcx("expand O0001.nct --to wl4");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "gcx: error: --to wl4 from a nct program is a translation between dialects: "
                   "gcx translate --to wl4 writes its motion with the codes' meaning\n");
  write("P1.wl4", "%P1\nG4 E1.5\nM30\n%\n");
  r = gcx("expand P1.wl4 --to nct");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "gcx: error: --to nct from a wl4 program is a translation between dialects: "
                   "gcx translate --to nct writes its motion with the codes' meaning\n");
}

} // namespace
} // namespace gcx::test
