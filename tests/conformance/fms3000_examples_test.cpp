// Every decoded example of fms3000.md §7 (cleaned as the spec says: OCR `1`/`|` = I, `O` = 0,
// `2` = Z) is read by the FMS-3000 front end without an error and written back by `gcx fmt`
// word for word. General forms (`G81 U_ Z_ ...`) are written with sample values; E44 is a
// computation, not a program: here the G162 blocks that use it, and its motion is checked in
// fms3000_multipass_test.cpp (FmsSpec_5_3_G162.E44TaperPitchAlongTheLongerTravelAndTheRunOut).
#include <gtest/gtest.h>

#include "support/fms3000_support.h"

namespace gcx::test {
namespace {

using V = std::vector<std::string>;

struct Example {
  const char* id;
  const char* lines; // seed lines
  const char* code;  // blocks separated by '|'
  V printed;         // as gcx fmt writes them
};

const Example kExamples[] = {
    {"E1",
     "001:238-246",
     "N1 G1 X10 Y20 F100 S500 M3|N2 F100 G1 X10 Y20 M3 S500",
     {"N1 G1 X10 Y20 F100 S500 M3", "N2 F100 G1 X10 Y20 M3 S500"}},
    {"E2", "001:354-356", "G1X100F200", {"G1 X100 F200"}},
    {"E3", "001:358-375", "G25 L3|G1X10F100|M25", {"G25 L3", "G1 X10 F100", "M25"}},
    {"E4", "001:536-540", "G36X10Y10", {"G36 X10 Y10"}},
    {"E5",
     "001:561-571",
     "N100G0I20A30|N100G1I20A30|N100G2I20A180R20",
     {"N100 G0 I20 A30", "N100 G1 I20 A30", "N100 G2 I20 A180 R20"}},
    {"E6", "001:580-595", "N100G37X10Y20A30|N100G37A0.", {"N100 G37 X10 Y20 A30", "N100 G37 A0."}},
    {"E7", "001:611-619", "N G90 X40 Y70|N G91 X-60 Y40", {"G90 X40 Y70", "G91 X-60 Y40"}},
    {"E8", "001:638-646", "G69X2.5Y1.7|G69X1Y1.", {"G69 X2.5 Y1.7", "G69 X1 Y1."}},
    {"E9", "001:692-696", "F1000", {"F1000"}},
    {"E10",
     "001:906-925",
     "G01X10|X20|Y30|Z40|G00Y50",
     {"G01 X10", "X20", "Y30", "Z40", "G00 Y50"}},
    {"E11", "001:1099-1105", "G17Z5|G20Y0U0", {"G17 Z5", "G20 Y0 U0"}},
    {"E12", "001:1129-1131", "G00X10Y20Z30B40", {"G00 X10 Y20 Z30 B40"}},
    {"E13",
     "001:1207-1237",
     "G60X10Y20Z30|G91G60X+5|G91G60X-5|G91G60X0",
     {"G60 X10 Y20 Z30", "G91 G60 X+5", "G91 G60 X-5", "G91 G60 X0"}},
    {"E14",
     "001:1254-1266",
     "G90G01X10Y20Z30B40U50W60F100|N G90 G1 X40 Y30 F100",
     {"G90 G01 X10 Y20 Z30 B40 U50 W60 F100", "G90 G1 X40 Y30 F100"}},
    {"E15",
     "001:1282-1294",
     "G17G02X10Y10I5J5F100|G18G03Z10X10K5I5F100|G19G02Y10Z10J5K5R7F100|G20U0X0|G02U10X10I5J5F100",
     {"G17 G02 X10 Y10 I5 J5 F100", "G18 G03 Z10 X10 K5 I5 F100", "G19 G02 Y10 Z10 J5 K5 R7 F100",
      "G20 U0 X0", "G02 U10 X10 I5 J5 F100"}},
    {"E16",
     "001:1345-1400",
     "G90G17G03 X140 Y100 I-60 F300|G02X120 Y60 I-50|G91G17G03 X-60 Y60 I140 J40 F300|G02X-20 Y-40 "
     "I90 J100",
     {"G90 G17 G03 X140 Y100 I-60 F300", "G02 X120 Y60 I-50", "G91 G17 G03 X-60 Y60 I140 J40 F300",
      "G02 X-20 Y-40 I90 J100"}},
    {"E17",
     "001:1441, 1457-1462",
     "G19G02G10Y10Z10J5K2X5F100I1|G91G2G10X-50Y50I-50Z40K160",
     {"G19 G02 G10 Y10 Z10 J5 K2 X5 F100 I1", "G91 G2 G10 X-50 Y50 I-50 Z40 K160"}},
    {"E18",
     "001:1470-1508",
     "G1G91X10G47|G1G91Y10G47|G1G91X10G48|G1G91Y-10G47|G2G91X10G47|G2G91X-10G48|G2G91Y-10G48|"
     "G2G91X-10G47|G2G91Y10G48",
     {"G1 G91 X10 G47", "G1 G91 Y10 G47", "G1 G91 X10 G48", "G1 G91 Y-10 G47", "G2 G91 X10 G47",
      "G2 G91 X-10 G48", "G2 G91 Y-10 G48", "G2 G91 X-10 G47", "G2 G91 Y10 G48"}},
    {"E19", "001:1527-1530", "N100G91G1Z-10G33F1.6", {"N100 G91 G1 Z-10 G33 F1.6"}},
    {"E20",
     "001:1553-1578",
     "NG27X0Y0Z20B0|G28X0Y0Z0|G30X0Y0Z0|G31X0Y0Z0",
     {"G27 X0 Y0 Z20 B0", "G28 X0 Y0 Z0", "G30 X0 Y0 Z0", "G31 X0 Y0 Z0"}},
    {"E21", "001:1614-1620", "G04E25", {"G04 E25"}},
    {"E22", "001:1734-1744", "G90G55G00X100Y50Z20", {"G90 G55 G00 X100 Y50 Z20"}},
    {"E23", "001:1785-1815", "G92X10Y20Z30|G92X100Y50", {"G92 X10 Y20 Z30", "G92 X100 Y50"}},
    {"E24", "001:1862-1866", "G41 D34", {"G41 D34"}},
    {"E25", "001:1890-1893", "G43 H1|G44 H1", {"G43 H1", "G44 H1"}},
    {"E26",
     "001:1978-2001",
     "N100 G92 X0 Y0 Z0|N1  G90 G17 G01 G41 D07 X250 Y550 F150|N2  Y900|N3  X450|N4  G03 X500 "
     "Y1150 I-600 J250|N5  G02 X900 I200 J150|N6  G03 X950 Y900 I650|N7  G01 X1150|N8  Y550|N9  "
     "X700 Y650|N10 X250 Y550|N11 G00 G40 X0 Y0",
     {"N100 G92 X0 Y0 Z0", "N1 G90 G17 G01 G41 D07 X250 Y550 F150", "N2 Y900", "N3 X450",
      "N4 G03 X500 Y1150 I-600 J250", "N5 G02 X900 I200 J150", "N6 G03 X950 Y900 I650",
      "N7 G01 X1150", "N8 Y550", "N9 X700 Y650", "N10 X250 Y550", "N11 G00 G40 X0 Y0"}},
    {"E27",
     "001:2191-2195",
     "N10G1X100Y100|N11G40Y50|N11G40",
     {"N10 G1 X100 Y100", "N11 G40 Y50", "N11 G40"}},
    {"E28",
     "001:2260-2280",
     "N1 G1 G90 G143 D1 DR2 X100 Y150 Z-100 DX-0.112234 DY-0.604727 DZ0.788485 F1000|N2 X101.2 "
     "Z-150.98 DX-0.209643 DY-0.977779|N3 X105 Y155|N4 Y158.7 Z-155 DX-0.109744 DY-0.732243 "
     "DZ0.672143|N5 G40 X160 Y161 DX-0.0008202 DY-0.951633 DZ0.307235|N6 M30",
     {"N1 G1 G90 G143 D1 DR2 X100 Y150 Z-100 DX-0.112234 DY-0.604727 DZ0.788485 F1000",
      "N2 X101.2 Z-150.98 DX-0.209643 DY-0.977779", "N3 X105 Y155",
      "N4 Y158.7 Z-155 DX-0.109744 DY-0.732243 DZ0.672143",
      "N5 G40 X160 Y161 DX-0.0008202 DY-0.951633 DZ0.307235", "N6 M30"}},
    {"E29",
     "001:2338-2369",
     "N1 G67 X100|N2 G90 G1 F100 X110 G41 D01|N3 X140 Y15|N4 G2 X180 I20 J0|G68X0.",
     {"N1 G67 X100", "N2 G90 G1 F100 X110 G41 D01", "N3 X140 Y15", "N4 G2 X180 I20 J0", "G68 X0."}},
    {"E30",
     "001:2438-2448",
     "G81U2Z-10W1V4I5F100E5M1H50X0Y0|G81U2Z-10I5F100E5",
     {"G81 U2 Z-10 W1 V4 I5 F100 E5 M1 H50 X0 Y0", "G81 U2 Z-10 I5 F100 E5"}},
    {"E31",
     "001:2515, 2619, 2647, 2667",
     "G81Z-10U2I5F100E5|G82U2Z-10I5F100E5H50|G83Z-10U2V4W1I5F100E5|G84U5Z-20I5F300E5M1",
     {"G81 Z-10 U2 I5 F100 E5", "G82 U2 Z-10 I5 F100 E5 H50", "G83 Z-10 U2 V4 W1 I5 F100 E5",
      "G84 U5 Z-20 I5 F300 E5 M1"}},
    {"E32",
     "001:2535-2542",
     "N1 G54 G0 G90 X10 Z10|N2 G81 U0.5 Z-15.5 F100|N3 X30 G81 U-9.5 I-4.|N4 X45 G81 U-4.5 I0.5|N5 "
     "X65 G81 U0.5 Z-10 I10|N6 G80",
     {"N1 G54 G0 G90 X10 Z10", "N2 G81 U0.5 Z-15.5 F100", "N3 X30 G81 U-9.5 I-4.",
      "N4 X45 G81 U-4.5 I0.5", "N5 X65 G81 U0.5 Z-10 I10", "N6 G80"}},
    {"E33",
     "001:2766-3209",
     "G150X20Z-30P10Q25F100G0|G154U1Z-20V8W1I1F50X10|G155U10X5V2W1I10F50Z5|G157U10X5V2W1P0.8Q0."
     "5I10F50Z5|G158X10Z-20Q5F100G0|G160U1Z-20V8W1I1F50X10|G163Z-20F1.5X10M5I1",
     {"G150 X20 Z-30 P10 Q25 F100 G0", "G154 U1 Z-20 V8 W1 I1 F50 X10",
      "G155 U10 X5 V2 W1 I10 F50 Z5", "G157 U10 X5 V2 W1 P0.8 Q0.5 I10 F50 Z5",
      "G158 X10 Z-20 Q5 F100 G0", "G160 U1 Z-20 V8 W1 I1 F50 X10", "G163 Z-20 F1.5 X10 M5 I1"}},
    {"E34",
     "001:3253-3352",
     "N10 G0 Z5|N20 X100|N30 G164 Q1.5 F0.5 G0 P1 D0.5|N40 G1 Z-100|N50 X80 Z-90|N60 G3 X40 Z-70 "
     "R20|N70 G1 Z-50|N80 X35|N90 G2 X15 Z-40 R10|N100 G1 X10 Z0|endcont|rem finishing pass|N110 "
     "G0 X10|N120 G1 Z0 F0.5|N130 X15 Z-40|N140 G3 X35 Z-50 R10|N150 G1 X40|N160 Z-70|N170 G2 X80 "
     "Z-90 R20|N180 G1 X100 Z-100|N190 G0 Z5",
     {"N10 G0 Z5",
      "N20 X100",
      "N30 G164 Q1.5 F0.5 G0 P1 D0.5",
      "N40 G1 Z-100",
      "N50 X80 Z-90",
      "N60 G3 X40 Z-70 R20",
      "N70 G1 Z-50",
      "N80 X35",
      "N90 G2 X15 Z-40 R10",
      "N100 G1 X10 Z0",
      "endcont",
      "rem finishing pass",
      "N110 G0 X10",
      "N120 G1 Z0 F0.5",
      "N130 X15 Z-40",
      "N140 G3 X35 Z-50 R10",
      "N150 G1 X40",
      "N160 Z-70",
      "N170 G2 X80 Z-90 R20",
      "N180 G1 X100 Z-100",
      "N190 G0 Z5"}},
    {"E35",
     "001:3361-3366",
     "G165Q1V1W0.5F0.5G0D0.5P1|G1X10|G1X5Z-10|endcont",
     {"G165 Q1 V1 W0.5 F0.5 G0 D0.5 P1", "G1 X10", "G1 X5 Z-10", "endcont"}},
    {"E36",
     "001:3446-3450",
     "N1G0Z-170|N2G1X100F1.2|N3G166Z-70R-3|N4G166X50R5|N5G166Z0R-2",
     {"N1 G0 Z-170", "N2 G1 X100 F1.2", "N3 G166 Z-70 R-3", "N4 G166 X50 R5", "N5 G166 Z0 R-2"}},
    {"E37",
     "001:3508-3512",
     "N1G0Z-170|N2G1X100F1.2|N3G167Z-70R-4|N4G167X50R7|N5G167Z0R-5",
     {"N1 G0 Z-170", "N2 G1 X100 F1.2", "N3 G167 Z-70 R-4", "N4 G167 X50 R7", "N5 G167 Z0 R-5"}},
    {"E38",
     "001:3527-3546",
     "G90X100G81U5Z-10I10F50|X150|X200|G80|X250G81U5Z-10F50|X300|X350|X400|G80",
     {"G90 X100 G81 U5 Z-10 I10 F50", "X150", "X200", "G80", "X250 G81 U5 Z-10 F50", "X300", "X350",
      "X400", "G80"}},
    {"E39",
     "001:3569-3621",
     "S1000|N1M3S100|N2X50|N3G96S150|N4X25|N5G97|N3 G96 S150 LIMS1100",
     {"S1000", "N1 M3 S100", "N2 X50", "N3 G96 S150", "N4 X25", "N5 G97", "N3 G96 S150 LIMS1100"}},
    {"E40", "001:3645-3647", "T39", {"T39"}},
    {"E41", "001:3746-3755", "P19|X1000P19", {"P19", "X1000 P19"}},
    {"E42",
     "001:3776-3782",
     "N100G1X100Y100|N100GG1X100Y100",
     {"N100 G1 X100 Y100", "N100 GG1 X100 Y100"}},
    {"E43", "001:331-334", "GG0|GG2|GG17", {"GG0", "GG2", "GG17"}},
    {"E44",
     "001:3181-3199",
     "G162X30Z-48H500W-20V2F1.961|G162X24Z-20H300P1.3Q0.5A-30F2",
     {"G162 X30 Z-48 H500 W-20 V2 F1.961", "G162 X24 Z-20 H300 P1.3 Q0.5 A-30 F2"}},
};

std::string crlf(std::string code) {
  std::string out;
  for (char c : code)
    out += c == '|' ? std::string("\r\n") : std::string(1, c);
  return out + "\r\n";
}

class Fms3000Examples_7 : public testing::TestWithParam<Example> {};

TEST_P(Fms3000Examples_7, ParsesAndPrintsBackWordForWord) {
  const Example& e = GetParam();
  const Parsed p = parseFms(crlf(e.code));
  EXPECT_EQ(p.errors(), V{}) << e.id << " (" << e.lines << ")\n" << p.rendered();
  EXPECT_EQ(printedFms(p), e.printed) << e.id;
  // and the printed text reads back to the same blocks
  std::string again;
  for (const std::string& line : e.printed)
    again += line + "\r\n";
  const Parsed q = parseFms(again);
  EXPECT_EQ(printedFms(q), e.printed) << e.id;
}

INSTANTIATE_TEST_SUITE_P(Manual, Fms3000Examples_7, testing::ValuesIn(kExamples),
                         [](const testing::TestParamInfo<Example>& example) {
                           return std::string(example.param.id);
                         });

} // namespace
} // namespace gcx::test
