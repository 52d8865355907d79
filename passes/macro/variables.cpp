// Variables as the dialect lays them out (ControlFlow::variables): the local frame, the
// commons, and above them the dialect's system variables; writes that are messages or alarms
// (ControlFlow::messageVariable); PRM[] parameters and axis numbers.
#include <fmt/format.h>

#include "diag/codes.h"
#include "emit/number.h"
#include "passes/macro/expander.h"

namespace gcx::macro {

std::optional<Value> Expander::read(int number, const SourceRange& where) {
  const VariableSpace& v = flow_.variables;
  // without a vacant state a variable never written reads 0 (WL4, wl4.md §6.1)
  const Value unset = v.vacant ? Value::empty() : Value::of(0);
  if (number == 0 && v.vacant) return Value::empty();
  if (number >= v.localFirst && number <= v.localLast) {
    const Value x = locals()[number];
    return x.vacant ? unset : x;
  }
  if (number >= v.commonFirst && number <= v.commonLast) {
    auto it = commons_.find(number);
    return it == commons_.end() ? unset : it->second;
  }
  if (number < v.commonFirst || !system_) {
    diags_.error(diag::code::UndefinedVariable, where, fmt::format("#{} does not exist", number));
    return std::nullopt;
  }
  return system_->read(number, where);
}

std::optional<Value> Expander::readNamed(const std::string& name, std::optional<int> index,
                                         const SourceRange& where) {
  if (!system_) {
    diags_.error(diag::code::UndefinedVariable, where, fmt::format("#_{} does not exist", name));
    return std::nullopt;
  }
  return system_->readNamed(name, index, where);
}

bool Expander::assign(const ir::Stmt& s) {
  auto v = eval_.value(s.value);
  if (!v) return false;
  if (s.target.kind == ir::ExprKind::Named) {
    std::optional<int> index;
    if (!s.target.args.empty()) {
      index = eval_.index(s.target.args[0]);
      if (!index) return false;
    }
    if (!system_)
      return fail(diag::code::UndefinedVariable, s.target.range,
                  fmt::format("#_{} does not exist", s.target.name));
    const auto number = system_->numberOf(s.target.name, index);
    if (number && flow_.messageVariable)
      if (auto rule = flow_.messageVariable(*number))
        return message(s, *rule, *number, *v); // #_ALM=, #_MSG= ... carry a message
    return system_->writeNamed(s.target.name, index, *v, s.target.range);
  }
  auto n = eval_.variableNumber(s.target);
  if (!n) return false;
  return write(*n, *v, s);
}

bool Expander::write(int number, const Value& v, const ir::Stmt& s) {
  if (flow_.messageVariable)
    if (auto rule = flow_.messageVariable(number)) return message(s, *rule, number, v);
  return store(number, v, s.target.range);
}

bool Expander::write(int number, const Value& v, const SourceRange& where) {
  return store(number, v, where); // an assignment inside an expression (wl4.md §6.4)
}

bool Expander::store(int number, const Value& v, const SourceRange& where) {
  const VariableSpace& space = flow_.variables;
  if (number >= space.localFirst && number <= space.localLast) {
    locals()[number] = v;
    return true;
  }
  if (number >= space.commonFirst && number <= space.commonLast) {
    if (flow_.writeProtected)
      if (auto why = flow_.writeProtected(number, parameters()))
        return fail(diag::code::WriteProtected, where, *why);
    commons_[number] = v;
    return true;
  }
  if (number == 0 && space.vacant)
    return fail(diag::code::ReadOnlyVariable, where, "#0 is read-only (always vacant)");
  if (number < space.commonFirst || !system_)
    return fail(diag::code::UndefinedVariable, where, fmt::format("#{} does not exist", number));
  return system_->write(number, v, where);
}

bool Expander::message(const ir::Stmt& s, const MessageRule& rule, int variable, const Value& v) {
  // the message number has a fixed range (nct-macro.md §2.9.2: alarm 4000 + nnn)
  if (!v.vacant && !(roundHalfAway(v.number) >= 0 && roundHalfAway(v.number) <= rule.maxNumber))
    return fail(diag::code::DataOutOfRange, s.target.range,
                fmt::format("#{} = {} is out of range: a message number is 0-{}", variable,
                            emit::formatNumber(v.number), rule.maxNumber));
  const int n = v.vacant ? 0 : static_cast<int>(roundHalfAway(v.number));
  const motion::Provenance from = provenance(ir::Block{});
  if (rule.kind == MessageRule::Alarm) { // alarm: execution stops
    const int code = rule.alarmBase + n;
    diags_.report(diag::Diagnostic{diag::Severity::Error,
                                   fmt::format("{}", code),
                                   fmt::format("alarm {}: {}", code, s.message),
                                   s.range,
                                   {}});
    return false;
  }
  machine_.message(fmt::format("MSG{}: {}", n, s.message), from, rule.kind == MessageRule::Stop);
  return true;
}

std::optional<double> Expander::parameter(int id, std::optional<int> bit, std::optional<int> index,
                                          const SourceRange& where) {
  const std::string key = flow_.parameterKey ? flow_.parameterKey(id, bit) : fmt::format("{}", id);
  (void)index; // one channel, parameters per axis/spindle are not modelled
  const double missing = -1.234e300;
  const double v = machine_.parameter(key, missing);
  if (v == missing) {
    diags_.error(diag::code::ParameterMissing, where,
                 fmt::format("parameter {} is not in the setup", key));
    return std::nullopt;
  }
  return v;
}

std::optional<int> Expander::axisNumber(char letter, const SourceRange& where) {
  const auto pos = flow_.channelAxes.find(letter);
  if (pos == std::string::npos) {
    diags_.error(diag::code::ForbiddenAddress, where,
                 fmt::format("no axis {} in this channel", letter));
    return std::nullopt;
  }
  return static_cast<int>(pos) + 1;
}

} // namespace gcx::macro
