#include "dialects/nct/system_variables.h"

#include <filesystem>

#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "diag/codes.h"
#include "emit/number.h"

namespace gcx::nct {

using emit::formatNumber;
using sysvar::Kind;
using sysvar::Ref;

namespace {

constexpr double kMmPerInch = 25.4;
constexpr const char* kTables = "nct-macro.md §2.9";

std::string numberLabel(int n) {
  return fmt::format("#{}", n);
}

std::string nameLabel(const std::string& name, std::optional<int> index) {
  std::string s = "#_";
  for (char c : name)
    s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return index ? fmt::format("{}[{}]", s, *index) : s;
}

// §2.9.4: a G code with a decimal has its decimal digit written in front: G51.1 -> 151,
// G84.2 -> 284; plain codes are the code itself (G17 -> 17).
double modalNumber(int code10) {
  return code10 % 10 == 0 ? code10 / 10 : (code10 % 10) * 100 + code10 / 10;
}

// the interpreter's work offset keys for WorkOffset::sub
std::string workOffsetKey(int sub) {
  if (sub == 0) return "common";
  if (sub <= 6) return fmt::format("G{}", 53 + sub);
  return fmt::format("G54.1 P{}", sub - 100);
}

} // namespace

SystemVariables::SystemVariables(machine::Interpreter& machine, diag::Engine& diags)
    : machine_(machine), diags_(diags) {}

void SystemVariables::startMain(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  if (stem.size() > 1 && (stem[0] == 'O' || stem[0] == 'o') &&
      stem.find_first_not_of("0123456789", 1) == std::string::npos && stem.size() <= 9)
    setMainProgramNumber(std::stoi(stem.substr(1)));
}

bool SystemVariables::fail(const char* code, const SourceRange& where, std::string message) {
  diags_.error(code, where, std::move(message));
  return false;
}

double SystemVariables::toUnits(double mm) const {
  return machine_.state().inch ? mm / kMmPerInch : mm;
}

double SystemVariables::toMm(double v) const {
  return machine_.state().inch ? v * kMmPerInch : v;
}

// ---------------------------------------------------------------- entry points

std::optional<Value> SystemVariables::read(int number, const SourceRange& where) {
  const std::string label = numberLabel(number);
  if (auto r = sysvar::decode(number)) return read(*r, label, where);
  fail(diag::code::UndefinedVariable, where,
       fmt::format("{} is not a variable of the NCT control ({})", label, kTables));
  return std::nullopt;
}

bool SystemVariables::write(int number, const Value& v, const SourceRange& where) {
  const std::string label = numberLabel(number);
  if (auto r = sysvar::decode(number)) return write(*r, label, v, where);
  return fail(diag::code::UndefinedVariable, where,
              fmt::format("{} is not a variable of the NCT control ({}, §2.7 A5)", label, kTables));
}

std::optional<Value> SystemVariables::readNamed(const std::string& name, std::optional<int> index,
                                                const SourceRange& where) {
  const std::string label = nameLabel(name, index);
  if (auto r = sysvar::decodeNamed(name, index)) return read(*r, label, where);
  fail(diag::code::UndefinedVariable, where,
       fmt::format("{} is not a system variable of the NCT control, or its index is out of "
                   "range ({})",
                   label, kTables));
  return std::nullopt;
}

bool SystemVariables::writeNamed(const std::string& name, std::optional<int> index, const Value& v,
                                 const SourceRange& where) {
  const std::string label = nameLabel(name, index);
  if (auto r = sysvar::decodeNamed(name, index)) return write(*r, label, v, where);
  return fail(diag::code::UndefinedVariable, where,
              fmt::format("{} is not a system variable of the NCT control, or its index is out "
                          "of range ({}, §2.7 A5)",
                          label, kTables));
}

// ---------------------------------------------------------------- reading

Value SystemVariables::runtime(const Ref& r, const std::string& label, const SourceRange& where,
                               double stub, const char* what) {
  if (warned_.insert(r).second)
    diags_.warning(diag::code::RuntimeOnlyVariable, where,
                   fmt::format("{} is {}, known only while the machine runs; gcx uses {} "
                               "(nct-macro.md §2.8)",
                               label, what, formatNumber(stub)));
  return Value::of(stub);
}

std::optional<Value> SystemVariables::read(const Ref& r, const std::string& label,
                                           const SourceRange& where) {
  switch (r.kind) {
  case Kind::Vacant:
    return Value::empty();
  case Kind::Pi:
    return Value::of(std::numbers::pi);
  case Kind::E:
    return Value::of(std::numbers::e);
  case Kind::PlcInput:
    return runtime(r, label, where, 0, "a PLC input (the setup has no PLC signals)");
  case Kind::PlcOutput:
    if (r.index < 32) return Value::of((outputBits_ >> r.index) & 1u);
    if (r.index == 32) return Value::of(outputBits_);
    return Value::of(outputs_[r.index - 33]);
  case Kind::Message:
    fail(diag::code::UndefinedVariable, where,
         fmt::format("{} is write-only: it issues a message (nct-macro.md §2.9.2)", label));
    return std::nullopt;
  case Kind::MessageBox:
    return runtime(r, label, where, 1, "the operator's reply to a message box");
  case Kind::Clock:
    return runtime(r, label, where, clocks_[r.index - 1], "a clock");
  case Kind::Date:
    return runtime(r, label, where, 20000101, "the date");
  case Kind::Time:
    return runtime(r, label, where, 0, "the time of day");
  case Kind::Control:
    return Value::of(control_[r.index - 1]);
  case Kind::ControlBit:
    return Value::of((control_[r.index - 1] >> r.sub) & 1u);
  case Kind::RunState:
    return runtime(r, label, where, 0, "a run mode (block search, test, machine lock)");
  case Kind::Mirror: // bit k-1 = axis k (§2.9.3); programmable mirror G51.1 on X Y Z
    return Value::of(machine_.transforms().mirrorAxes());
  case Kind::Parts:
    return Value::of(parts_[r.index - 1]);
  case Kind::MainProgram:
    return Value::of(mainProgram_);
  case Kind::ModalGroup:
  case Kind::ModalWord:
    return modal(r, label, where);
  case Kind::Position:
    return position(r, label, where);
  case Kind::WorkOffset:
    if (r.index > 3) return Value::of(0); // offsets of A B C are not modelled (always 0)
    return Value::of(toUnits(machine_.setup().workOffset(workOffsetKey(r.sub))[r.index - 1]));
  case Kind::BasicRotation:
    return Value::of(machine_.workRotation(workOffsetKey(r.sub), r.index));
  case Kind::DynamicOffset: {
    auto it = dynamicOffsets_.find({r.sub, r.index});
    const double v = it == dynamicOffsets_.end() ? 0.0 : it->second;
    return Value::of(r.index <= 3 ? toUnits(v) : v);
  }
  case Kind::DynamicOffsetActive:
    return Value::of(0); // G54.2 is not modelled, so none is active
  case Kind::ToolOffset:
    return toolOffset(r);
  case Kind::ToolData:
    fail(diag::code::NotImplemented, where,
         fmt::format("{}: tool and pallet data need a magazine model, which gcx does not have "
                     "(nct-macro.md §2.9.8)",
                     label));
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<Value> SystemVariables::modal(const Ref& r, const std::string& label,
                                            const SourceRange& where) {
  if (r.sub == sysvar::Interrupted)
    return runtime(r, label, where, 0, "the state of a block an interrupt macro interrupted");
  // §4.6: without look-ahead the buffered (#40xx) and executing (#42xx) items are the same
  if (r.kind == Kind::ModalGroup) return Value::of(modalNumber(machine_.modalCode(r.index)));
  const machine::ModalState& s = machine_.state();
  switch (r.index) {
  case 7:
    return Value::of(s.lastD);
  case 8:
    return Value::of(s.lastE);
  case 9:
    return Value::of(toUnits(s.feed));
  case 11:
    return Value::of(s.lastH);
  case 13:
    return Value::of(s.lastM);
  case 14:
    return Value::of(static_cast<double>(s.lastN));
  case 15:
    return Value::of(s.lastO);
  case 19:
    return Value::of(s.lastS);
  case 20:
    return Value::of(s.selectedTool);
  case 30:
    return Value::of(s.workOffset > 100 ? s.workOffset - 100 : 0);
  default: // 1-3: A B C on the addresses N1333-N1335 choose
    fail(diag::code::NotImplemented, where,
         fmt::format("{}: the address it reports is chosen by parameters N1333-N1335, which "
                     "gcx does not model (nct-macro.md §2.9.4)",
                     label));
    return std::nullopt;
  }
}

std::optional<Value> SystemVariables::position(const Ref& r, const std::string& label,
                                               const SourceRange& where) {
  // axes 1-3 = X Y Z (program units), 4-6 = A B C (degrees); the channel has no others
  const int axis = r.index;
  auto on = [&](const machine::Vec3& linear) {
    if (axis <= 3) return toUnits(linear[axis - 1]);
    if (axis <= 6) return machine_.extraPosition()[axis - 4];
    return 0.0;
  };
  switch (r.sub) {
  case sysvar::EndPoint: // work coordinates, no compensation, before transforms
    return Value::of(on(machine_.programPosition()));
  case sysvar::Machine:
    return Value::of(on(machine_.machinePosition()));
  case sysvar::Current: // the machine position less all offsets and the active length
    return Value::of(on(machine_.machinePosition() - machine_.workOrigin()));
  case sysvar::Probe: // no probe signal: the programmed end point (000:12888-12889)
    return runtime(r, label, where, on(machine_.programPosition()), "a probe position");
  case sysvar::LengthOffset: // N1416 ZAX: the length acts along Z
    return Value::of(axis == 3 ? toUnits(machine_.lengthOffset()) : 0.0);
  case sysvar::ServoLag:
    return runtime(r, label, where, 0, "a servo lag");
  case sysvar::Handwheel:
    return runtime(r, label, where, 0, "a handwheel shift");
  default: // DistanceToGo: between blocks nothing remains (§2.8)
    return Value::of(0);
  }
}

std::optional<Value> SystemVariables::toolOffset(const Ref& r) const {
  const int reg = r.index;
  const auto& tools = machine_.setup().tools;
  auto it = tools.find(reg);
  const machine::ToolData t = it == tools.end() ? machine::ToolData{} : it->second;
  switch (r.sub) {
  case sysvar::LengthGeometry:
    return Value::of(toUnits(t.length - machine_.toolWear(reg, false)));
  case sysvar::LengthWear:
    return Value::of(toUnits(machine_.toolWear(reg, false)));
  case sysvar::RadiusGeometry:
    return Value::of(toUnits(t.radius - machine_.toolWear(reg, true)));
  case sysvar::RadiusWear:
    return Value::of(toUnits(machine_.toolWear(reg, true)));
  default: { // corner radius: stored here, the motion model does not use it
    auto c = cornerRadius_.find({reg, r.sub - sysvar::CornerGeometry});
    return Value::of(c == cornerRadius_.end() ? 0.0 : toUnits(c->second));
  }
  }
}

// ---------------------------------------------------------------- writing

bool SystemVariables::isWritable(const Ref& r) const {
  switch (r.kind) {
  case Kind::PlcOutput:
  case Kind::Message: // W (§2.9.2)
  case Kind::MessageBox:
  case Kind::Clock:
  case Kind::Control:
  case Kind::ControlBit:
  case Kind::Parts:
  case Kind::WorkOffset:
  case Kind::BasicRotation:
  case Kind::DynamicOffset:
  case Kind::ToolOffset:
    return true;
  case Kind::ToolData: // #8400, #8500 select a magazine / place (§2.9.8)
    return r.index == 8400 || r.index == 8500;
  default:
    return false;
  }
}

std::optional<int> SystemVariables::bit(double v, const std::string& label,
                                        const SourceRange& where) {
  if (v < 0 || v > 1) {
    fail(diag::code::BitValueRange, where,
         fmt::format("value limit exceeded: {} is a bit, {} is outside 0..1 (nct-macro.md §2.7 "
                     "A3)",
                     label, formatNumber(v)));
    return std::nullopt;
  }
  return v == 0 ? 0 : 1;
}

bool SystemVariables::write(const Ref& r, const std::string& label, const Value& v,
                            const SourceRange& where) {
  if (!isWritable(r))
    return fail(diag::code::ReadOnlyVariable, where,
                fmt::format("{} macro variable is read-only (nct-macro.md §2.7 A2)", label));
  if (v.vacant)
    return fail(diag::code::VacantToSystem, where,
                fmt::format("{} is a system variable and cannot be made vacant (nct-macro.md "
                            "§2.7 A4)",
                            label));
  const double x = v.number;
  switch (r.kind) {
  case Kind::PlcOutput:
    if (r.index < 32) {
      auto b = bit(x, label, where);
      if (!b) return false;
      outputBits_ = *b ? outputBits_ | (1u << r.index) : outputBits_ & ~(1u << r.index);
    } else if (r.index == 32) { // the 32 bits as one integer; bitwise results may be signed
      if (x < -2147483648.0 || x > 4294967295.0)
        return fail(diag::code::BitValueRange, where,
                    fmt::format("value limit exceeded: {} holds 32 bits, {} is outside "
                                "-2147483648..4294967295",
                                label, formatNumber(x)));
      outputBits_ = static_cast<std::uint32_t>(static_cast<std::int64_t>(std::trunc(x)));
    } else {
      outputs_[r.index - 33] = x;
    }
    return true;
  case Kind::Clock:
    clocks_[r.index - 1] = x;
    return true;
  case Kind::Control: { // #3003: bit 0 only; #3004: bits 0-2 (values 0-7)
    const double max = r.index == 1 ? 1 : 7;
    if (x < 0 || x > max)
      return fail(diag::code::BitValueRange, where,
                  fmt::format("value limit exceeded: {} takes 0..{}, not {} (nct-macro.md "
                              "§2.9.3)",
                              label, formatNumber(max), formatNumber(x)));
    control_[r.index - 1] = static_cast<unsigned>(std::round(x));
    return true;
  }
  case Kind::ControlBit: {
    auto b = bit(x, label, where);
    if (!b) return false;
    unsigned& word = control_[r.index - 1];
    word = *b ? word | (1u << r.sub) : word & ~(1u << r.sub);
    return true;
  }
  case Kind::Parts:
    parts_[r.index - 1] = x;
    return true;
  case Kind::WorkOffset:
    return writeWorkOffset(r, label, x, where);
  case Kind::BasicRotation:
    machine_.setWorkRotation(workOffsetKey(r.sub), r.index, x);
    return true;
  case Kind::DynamicOffset:
    dynamicOffsets_[{r.sub, r.index}] = r.index <= 3 ? toMm(x) : x;
    return true;
  case Kind::ToolOffset:
    return writeToolOffset(r, x);
  default: // messages (the expander issues them), #8400 / #8500
    return fail(diag::code::NotImplemented, where,
                fmt::format("{} cannot be written here: {}", label,
                            r.kind == Kind::ToolData
                                ? "gcx has no magazine or pallet model (nct-macro.md §2.9.8)"
                                : "messages are issued by the macro expansion pass"));
  }
}

bool SystemVariables::writeWorkOffset(const Ref& r, const std::string& label, double v,
                                      const SourceRange& where) {
  if (r.index > 3) {
    if (v == 0) return true;
    return fail(
        diag::code::NotImplemented, where,
        fmt::format("{}: work offsets of axes other than X Y Z are not implemented yet", label));
  }
  const std::string key = workOffsetKey(r.sub);
  auto o = machine_.setup().workOffset(key);
  o[r.index - 1] = toMm(v);
  machine_.setWorkOffset(key, machine::Vec3(o[0], o[1], o[2]));
  return true;
}

bool SystemVariables::writeToolOffset(const Ref& r, double v) {
  const int reg = r.index;
  const double mm = toMm(v);
  switch (r.sub) {
  case sysvar::LengthGeometry: // keeps the wear: register = geometry + wear
    machine_.setToolLength(reg, mm + machine_.toolWear(reg, false));
    return true;
  case sysvar::LengthWear:
    machine_.setToolWear(reg, false, mm);
    return true;
  case sysvar::RadiusGeometry:
    machine_.setToolRadius(reg, mm + machine_.toolWear(reg, true));
    return true;
  case sysvar::RadiusWear:
    machine_.setToolWear(reg, true, mm);
    return true;
  default:
    cornerRadius_[{reg, r.sub - sysvar::CornerGeometry}] = mm;
    return true;
  }
}

} // namespace gcx::nct
