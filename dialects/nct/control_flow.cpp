#include "dialects/nct/control_flow.h"

#include <charconv>
#include <fmt/format.h>

#include "dialects/nct/arguments.h"
#include "dialects/nct/configured_calls.h"
#include "dialects/nct/system_variables.h"
#include "dialects/nct/word_value_rules.h"

namespace gcx::nct {

namespace {

// A program name of digits (an optional sign) as its number: "12" -> 12.
std::optional<std::int64_t> programNumber(const std::string& unit) {
  std::int64_t n = 0;
  const char* end = unit.data() + unit.size();
  auto [p, ec] = std::from_chars(unit.data(), end, n);
  if (ec != std::errc() || p != end) return std::nullopt;
  return n;
}

// `M98 P12` looks for O0012 then O00000012 with the caller's extension (nct.md §5.1)
std::vector<std::string> programFiles(const std::string& unit, const std::string& ext) {
  std::vector<std::string> names;
  const auto n = programNumber(unit);
  if (!n) return names;
  if (*n >= 0 && *n <= 9999) names.push_back(fmt::format("O{:04}{}", *n, ext));
  if (*n >= 0 && *n <= 99999999) names.push_back(fmt::format("O{:08}{}", *n, ext));
  return names;
}

std::string programLabel(const std::string& unit) {
  const auto n = programNumber(unit);
  return n ? fmt::format("O{:04}", *n) : unit;
}

// #3000 alarm 4000 + n, #3006 stop with a message, #3106 / #3107 messages (§2.9.2)
std::optional<MessageRule> messageVariable(int number) {
  switch (number) {
  case 3000:
    return MessageRule{MessageRule::Alarm, 4000, 999};
  case 3006:
    return MessageRule{MessageRule::Stop, 0, 999};
  case 3106:
  case 3107:
    return MessageRule{MessageRule::Note, 0, 999};
  default:
    return std::nullopt;
  }
}

// Every NCT call and return takes its program (or return block) from P and its count from L.
Remap call(const char* address, double code, FlowAction action) {
  Remap r;
  r.address = address;
  r.code = code;
  r.action = action;
  r.programWord = 'P';
  r.repeatWord = 'L';
  r.programWordIsNumber = true;
  r.spec = "nct-macro.md §5";
  return r;
}

} // namespace

RemapTable remapTable(const std::vector<CycleMacro>& cycleMacros) {
  RemapTable t;
  // G65 P<n> L<k>: a macro call with arguments (§5.3); a system cycle's P is checked first
  Remap g65 = call("G", 65, FlowAction::CallMacro);
  g65.program = ProgramSource::Word;
  g65.frame = LocalFrame::Arguments;
  g65.fileWord = true;
  for (const CycleMacro& c : cycleMacros) {
    Remap cycle = g65;
    cycle.action = FlowAction::CallCycle;
    cycle.onlyProgram = static_cast<double>(c.program);
    cycle.spec = c.spec;
    t.rows.push_back(cycle);
  }
  t.rows.push_back(g65);
  // G66 P L: a modal call after every motion block; G66.1 after every block (§5.5-§5.7)
  Remap g66 = g65;
  g66.code = 66;
  g66.action = FlowAction::ModalCall;
  g66.fileWord = false;
  g66.modalGroup = 12;
  g66.modalCode10 = 660;
  t.rows.push_back(g66);
  Remap g661 = g66;
  g661.code = 66.1;
  g661.action = FlowAction::ModalCallEveryBlock;
  g661.programWordIsNumber = false; // P of G66.1 <expression> keeps its fraction as before
  g661.modalCode10 = 661;
  t.rows.push_back(g661);
  Remap g67 = call("G", 67, FlowAction::ModalCancel);
  g67.programWordIsNumber = false;
  g67.modalGroup = 12;
  g67.modalCode10 = 670;
  t.rows.push_back(g67);
  // M98 P L: the caller's locals (§5.2 V2), L at least 1; M99 P L returns (§5.2 R4-R6)
  Remap m98 = call("M", 98, FlowAction::CallSubprogram);
  m98.program = ProgramSource::Word;
  m98.fileWord = true;
  m98.repeatBelowOneRule = "nct.md Q6";
  t.rows.push_back(m98);
  Remap m99 = call("M", 99, FlowAction::Return);
  m99.spec = "nct-macro.md §5.2 R7"; // a called program ends with M99
  t.rows.push_back(m99);
  return t;
}

const ControlFlow& controlFlow(const std::vector<CycleMacro>& cycleMacros) {
  static const ControlFlow flow = [&] {
    ControlFlow f;
    f.remaps = remapTable(cycleMacros);
    f.variables = VariableSpace{1, 33, 100, 999}; // §2.1
    f.wordValues = wordValueRules();              // §2.6
    f.channelAxes = "XYZABC";                     // AX[1]..AX[6] (§2.6)
    // G70.7-G73.7 read their contour blocks by N number, as jumps do
    f.expansionMarkers = {"M98", "M99",   "G65",   "G66",   "GOTO",  "WHILE", "DO",    "END",
                          "IF",  "DPRNT", "BPRNT", "POPEN", "G70.7", "G71.7", "G72.7", "G73.7"};
    f.messageVariable = messageVariable;
    f.bindArguments = bindCall;
    f.systemVariables = [](machine::Interpreter& machine, diag::Engine& diags) {
      return std::unique_ptr<macro::SystemVariableStore>(new SystemVariables(machine, diags));
    };
    f.configuredCall = configuredCall;
    f.writeProtected = [](int number, const ParameterLookup& param) -> std::optional<std::string> {
      const double low = param("N1702", 0), high = param("N1703", 0);
      if (number >= 500 && low > 0 && number >= low && number <= high)
        return fmt::format("#{} is write-protected by N1702/N1703", number);
      return std::nullopt;
    };
    f.parameterKey = [](int id, std::optional<int> bit) {
      std::string key = fmt::format("N{:04}", id);
      if (bit) key += fmt::format(".{}", *bit);
      return key;
    };
    f.printOmitsSign = [](const ParameterLookup& param) { // N1757 #0 PNT (§6)
      return param("N1757.PNT", 0) == 1 || param("N1757.0", 0) == 1;
    };
    f.programFiles = programFiles;
    f.programLabel = programLabel;
    return f;
  }();
  return flow;
}

} // namespace gcx::nct
