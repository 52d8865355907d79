#include "dialects/nct/system_variable_map.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace gcx::nct::sysvar {

namespace {

bool in(int n, int lo, int hi) {
  return n >= lo && n <= hi;
}

// #4101-#4130 items §2.9.4 lists: A B C (1-3), D E F (7-9), H (11), M N O (13-15), S T (19, 20),
// G54.1 P (30)
bool listedModalWord(int item) {
  static constexpr int items[] = {1, 2, 3, 7, 8, 9, 11, 13, 14, 15, 19, 20, 30};
  return std::find(std::begin(items), std::end(items), item) != std::end(items);
}

std::optional<Ref> decodeModal(int n) {
  for (int slot : {Buffered, Active, Interrupted}) {
    const int base = 4000 + 200 * slot;
    if (in(n, base + 1, base + 39)) return Ref{Kind::ModalGroup, n - base, slot};
    if (in(n, base + 101, base + 130) && listedModalWord(n - base - 100))
      return Ref{Kind::ModalWord, n - base - 100, slot};
  }
  return std::nullopt;
}

// §2.9.5, §2.9.7 short forms (axes 1-20)
std::optional<Ref> decodeShortAxes(int n) {
  if (in(n, 5001, 5120)) return Ref{Kind::Position, (n - 5001) % 20 + 1, (n - 5001) / 20};
  if (in(n, 5181, 5200)) return Ref{Kind::Position, n - 5180, DistanceToGo};
  if (in(n, 5201, 5340)) return Ref{Kind::WorkOffset, (n - 5201) % 20 + 1, (n - 5201) / 20};
  if (n == 5500) return Ref{Kind::DynamicOffsetActive, 0, 0};
  if (in(n, 5501, 5520)) return Ref{Kind::DynamicOffsetActive, n - 5500, 0};
  if (in(n, 5521, 5680)) return Ref{Kind::DynamicOffset, (n - 5501) % 20 + 1, (n - 5501) / 20};
  if (in(n, 7001, 7960)) return Ref{Kind::WorkOffset, (n - 7001) % 20 + 1, 101 + (n - 7001) / 20};
  return std::nullopt;
}

// §2.9.5, §2.9.7 long forms (axes 1-50) and basic rotations
std::optional<Ref> decodeLongAxes(int n) {
  if (in(n, 100001, 100300)) return Ref{Kind::Position, (n - 100001) % 50 + 1, (n - 100001) / 50};
  if (in(n, 100301, 100650)) return Ref{Kind::WorkOffset, (n - 100301) % 50 + 1, (n - 100301) / 50};
  if (in(n, 100651, 100700)) return Ref{Kind::Position, n - 100650, Handwheel};
  if (in(n, 100801, 100850)) return Ref{Kind::Position, n - 100800, DistanceToGo};
  if (in(n, 101001, 101000 + 50 * kMaxExtendedOffset))
    return Ref{Kind::WorkOffset, (n - 101001) % 50 + 1, 101 + (n - 101001) / 50};
  if (n == 117000) return Ref{Kind::DynamicOffsetActive, 0, 0};
  if (in(n, 117001, 117050)) return Ref{Kind::DynamicOffsetActive, n - 117000, 0};
  if (in(n, 117051, 117450))
    return Ref{Kind::DynamicOffset, (n - 117001) % 50 + 1, (n - 117001) / 50};
  const int plane = (n - 120001) % 10 + 1; // #120001 + 10 j + (k - 1), k = 1..3
  if (in(n, 120001, 120060) && plane <= 3)
    return Ref{Kind::BasicRotation, plane, 1 + (n - 120001) / 10};
  if (in(n, 120061, 120060 + 10 * kMaxExtendedOffset) && plane <= 3)
    return Ref{Kind::BasicRotation, plane, 101 + (n - 120061) / 10};
  return std::nullopt;
}

std::optional<Ref> decodeTools(int n) {
  static constexpr int bases[] = {10000, 11000, 12000, 13000, 21000, 22000};
  for (int t = 0; t < 6; ++t)
    if (in(n, bases[t] + 1, bases[t] + 999)) return Ref{Kind::ToolOffset, n - bases[t], t};
  if (in(n, 8400, 8414) || in(n, 8431, 8450) || in(n, 8500, 8505) || in(n, 8531, 8534))
    return Ref{Kind::ToolData, n, 0};
  return std::nullopt;
}

struct Indexed {
  const char* name;
  int base; // number = base + index
  int lo, hi;
};

// symbols with an index whose number is base + index (§2.9.1-§2.9.7)
constexpr Indexed kIndexed[] = {
    {"UI", 1000, 0, 31},      {"UIL", 1032, 0, 3},        {"UO", 1100, 0, 31},
    {"UOL", 1132, 0, 3},      {"BUFG", 4000, 1, 39},      {"ACTG", 4200, 1, 39},
    {"INTG", 4400, 1, 39},    {"ABSIO", 100000, 1, 50},   {"ABSMT", 100050, 1, 50},
    {"ABSOT", 100100, 1, 50}, {"ABSKP", 100150, 1, 50},   {"TOFS", 100200, 1, 50},
    {"SVERR", 100250, 1, 50}, {"MIRTP", 100650, 1, 50},   {"DIST", 100800, 1, 50},
    {"OFSHG", 10000, 1, 999}, {"OFSHW", 11000, 1, 999},   {"OFSDG", 12000, 1, 999},
    {"OFSDW", 13000, 1, 999}, {"CORR_G", 21000, 1, 999},  {"CORR_W", 22000, 1, 999},
    {"WZCMN", 100300, 1, 50}, {"WZG54", 100350, 1, 50},   {"WZG55", 100400, 1, 50},
    {"WZG56", 100450, 1, 50}, {"WZG57", 100500, 1, 50},   {"WZG58", 100550, 1, 50},
    {"WZG59", 100600, 1, 50}, {"FOFSVAL", 117000, 1, 50}, {"WRG54", 120000, 1, 3},
    {"WRG55", 120010, 1, 3},  {"WRG56", 120020, 1, 3},    {"WRG57", 120030, 1, 3},
    {"WRG58", 120040, 1, 3},  {"WRG59", 120050, 1, 3},
};

struct Plain {
  const char* name;
  int number;
};

constexpr Plain kPlain[] = {
    {"EMPTY", 0},     {"PI", 3101},     {"E", 3102},      {"ALM", 3000},    {"MSGSTP", 3006},
    {"MSG", 3106},    {"MSGBOX", 3107}, {"CLOCK1", 3001}, {"CLOCK2", 3002}, {"DATE", 3011},
    {"TIME", 3012},   {"PRTSA", 3901},  {"PRTSN", 3902},  {"CNTL1", 3003},  {"CNTL2", 3004},
    {"MIRIMG", 3007}, {"MAINO", 4000},  {"FOFSP", 5500},
};

// #_BUFx / #_ACTx / #_INTx letters and their item numbers (#4100 + item)
std::optional<int> modalWordNumber(const std::string& name) {
  static constexpr const char* prefixes[] = {"BUF", "ACT", "INT"};
  static constexpr Plain items[] = {{"A", 1},  {"B", 2},  {"C", 3},   {"D", 7},  {"E", 8},
                                    {"F", 9},  {"H", 11}, {"M", 13},  {"N", 14}, {"O", 15},
                                    {"S", 19}, {"T", 20}, {"WZP", 30}};
  for (int slot = 0; slot < 3; ++slot) {
    if (name.rfind(prefixes[slot], 0) != 0) continue;
    const std::string rest = name.substr(3);
    for (const Plain& it : items)
      if (rest == it.name) return 4100 + 200 * slot + it.number;
  }
  return std::nullopt;
}

// "WZP12" -> 12 for prefix "WZP"; nullopt when the rest is not a number 1..max
std::optional<int> suffixNumber(const std::string& name, const char* prefix, int max) {
  const std::size_t len = std::strlen(prefix);
  if (name.size() <= len || name.size() > len + 3 || name.compare(0, len, prefix) != 0)
    return std::nullopt;
  int p = 0;
  for (std::size_t i = len; i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) return std::nullopt;
    p = p * 10 + (name[i] - '0');
  }
  if (p < 1 || p > max) return std::nullopt;
  return p;
}

} // namespace

std::optional<Ref> decode(int n) {
  if (n == 0 || n == 3100) return Ref{Kind::Vacant};
  if (n == 3101) return Ref{Kind::Pi};
  if (n == 3102) return Ref{Kind::E};
  if (in(n, 1000, 1035)) return Ref{Kind::PlcInput, n - 1000};
  if (in(n, 1100, 1135)) return Ref{Kind::PlcOutput, n - 1100};
  switch (n) {
  case 3000:
  case 3006:
  case 3106:
    return Ref{Kind::Message, n};
  case 3107:
    return Ref{Kind::MessageBox};
  case 3001:
  case 3002:
    return Ref{Kind::Clock, n - 3000};
  case 3003:
  case 3004:
    return Ref{Kind::Control, n - 3002};
  case 3007:
    return Ref{Kind::Mirror};
  case 3011:
    return Ref{Kind::Date};
  case 3012:
    return Ref{Kind::Time};
  case 3901:
  case 3902:
    return Ref{Kind::Parts, n - 3900};
  case 4000:
    return Ref{Kind::MainProgram};
  default:
    break;
  }
  if (auto r = decodeModal(n)) return r;
  if (auto r = decodeShortAxes(n)) return r;
  if (auto r = decodeLongAxes(n)) return r;
  return decodeTools(n);
}

std::optional<int> numberOf(const std::string& rawName, std::optional<int> index) {
  std::string name = rawName;
  for (char& c : name)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (index) {
    for (const Indexed& x : kIndexed)
      if (name == x.name) {
        if (*index < x.lo || *index > x.hi) return std::nullopt;
        return x.base + *index;
      }
    if (*index < 1) return std::nullopt;
    // G54.1 Pp: long form #101001 + 50(p-1) + (n-1) (§2.9.7)
    if (auto p = suffixNumber(name, "WZP", kMaxExtendedOffset); p && *index <= 50)
      return 101000 + 50 * (*p - 1) + *index;
    if (auto p = suffixNumber(name, "FOFS", 8); p && *index <= 50) return 117000 + 50 * *p + *index;
    if (auto p = suffixNumber(name, "WRP", kMaxExtendedOffset); p && *index <= 3)
      return 120060 + 10 * (*p - 1) + *index;
    return std::nullopt;
  }
  for (const Plain& x : kPlain)
    if (name == x.name) return x.number;
  return modalWordNumber(name);
}

std::optional<Ref> decodeNamed(const std::string& rawName, std::optional<int> index) {
  std::string name = rawName;
  for (char& c : name)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (!index) { // symbols without a number of their own (§2.9.3, §2.7 A3)
    static constexpr Plain bits[] = {{"M_SBK", 10}, {"M_FHD", 20}, {"M_OV", 21}, {"M_EST", 22}};
    for (const Plain& b : bits)
      if (name == b.name) return Ref{Kind::ControlBit, b.number / 10, b.number % 10};
    static constexpr Plain states[] = {{"CNTBS", -1}, {"BSEARCH", 0}, {"TEST", 1}, {"MCHLOCK", 2}};
    for (const Plain& s : states)
      if (name == s.name) return Ref{Kind::RunState, 0, s.number};
  }
  if (auto n = numberOf(name, index)) return decode(*n);
  return std::nullopt;
}

} // namespace gcx::nct::sysvar
