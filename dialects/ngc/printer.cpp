#include "dialects/ngc/printer.h"

#include "dialects/ngc/expression.h"
#include "emit/number.h"

namespace gcx::ngc {

namespace {

// Parameters are the target's numbers already (translate/variable_plan.h).
std::string parameter(int n, std::string&) {
  return "#" + std::to_string(n);
}

std::string loop(int id) {
  return "o<l" + std::to_string(id) + ">";
}

std::string condition(const ir::Condition& c) {
  std::string out, why;
  conditionText(c, &parameter, out, why);
  return out;
}

std::string statement(const ir::Stmt& s) {
  std::string out, why;
  switch (s.kind) {
  case ir::StmtKind::Assign:
    expressionText(s.target, &parameter, out, why);
    out += " = ";
    expressionText(s.value, &parameter, out, why);
    return out;
  case ir::StmtKind::While:
    return loop(s.loopId) + " while " + condition(*s.cond);
  case ir::StmtKind::Do:
    return loop(s.loopId) + " do";
  case ir::StmtKind::End: // a do loop ends with its condition
    return s.cond ? loop(s.loopId) + " while " + condition(*s.cond) : loop(s.loopId) + " endwhile";
  case ir::StmtKind::Call:
    return "o<" + s.callee + "> call";
  default:
    return {};
  }
}

void append(std::string& out, const std::string& item) {
  if (item.empty()) return;
  if (!out.empty()) out += ' ';
  out += item;
}

class Emitter : public emit::ProgramEmitter {
public:
  explicit Emitter(std::ostream& out) : out_(out) {}
  emit::Capabilities capabilities() const override {
    using emit::Construct;
    return {Construct::CannedCycles, Construct::Subprograms, Construct::Loops,
            Construct::Variables};
  }
  void beginProgram(const emit::ProgramUnit&) override {}
  void block(const ir::Block& b) override {
    const std::string line = printBlock(b);
    if (!line.empty()) out_ << line << '\n';
  }
  void endProgram() override {}

private:
  std::ostream& out_;
};

} // namespace

std::string commentText(const std::string& text) {
  std::string t;
  for (char c : text)
    if (c != '(' && c != ')') t += c;
  std::string lower;
  for (char c : t)
    if (c != ' ') lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* command : {"msg,", "debug,", "print,", "log", "probe", "abort,"})
    if (lower.rfind(command, 0) == 0) return "(- " + t + ")";
  return "(" + t + ")";
}

std::string printBlock(const ir::Block& b) {
  if (b.kind == ir::BlockKind::ProgramStart) return "o<" + b.programName + "> sub";
  if (b.kind == ir::BlockKind::ProgramEnd) return "o<" + b.programName + "> endsub";
  std::string out;
  if (b.sequence) append(out, "N" + std::to_string(*b.sequence));
  for (const ir::Stmt& s : b.stmts)
    append(out, statement(s));
  for (const ir::Word& w : b.words) {
    std::string v, why;
    if (w.isLiteral())
      v = emit::formatNumber(w.number);
    else
      wordValueText(w, &parameter, v, why);
    append(out, w.address + v);
  }
  for (const ir::Comment& c : b.comments)
    append(out, commentText(c.text));
  return out;
}

std::unique_ptr<emit::ProgramEmitter> makeEmitter(std::ostream& out) {
  return std::make_unique<Emitter>(out);
}

} // namespace gcx::ngc
