// A recursive-descent parser of one WL4 block, written from grammar/WL4.g4 (wl4.md §6.8). It
// reads the reader's ASCII text (lexText: sign aliases replaced, `$` comment located) and
// builds IR v2 directly: words, assignments, guards, jumps and calls in source order.
#include "dialects/wl4/block_parser.h"

#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <string_view>

#include "diag/codes.h"
#include "dialects/wl4/block_items.h"
#include "front/decimal_text.h"

namespace gcx::wl4 {

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isLetter(char c) {
  return c >= 'A' && c <= 'Z';
}

class Parser {
public:
  Parser(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags)
      : raw_(raw), out_(out), diags_(diags) {
    const std::size_t end =
        raw.lineCommentAt == std::string::npos ? raw.lexText.size() : raw.lineCommentAt;
    t_ = std::string_view(raw.lexText).substr(0, end);
  }

  bool block();

private:
  // ---- characters
  void spaces() {
    while (p_ < t_.size() && t_[p_] == ' ')
      ++p_;
  }
  char peek() {
    spaces();
    return p_ < t_.size() ? t_[p_] : '\0';
  }
  bool peek2(std::string_view two) {
    spaces();
    return t_.substr(p_, two.size()) == two;
  }
  std::string_view letters(std::size_t at) const {
    std::size_t e = at;
    while (e < t_.size() && isLetter(t_[e]))
      ++e;
    return t_.substr(at, e - at);
  }
  SourceRange range(std::size_t pos, std::size_t len) const { return rangeOf(raw_, pos, len); }
  /// The result of a shared item rule (block_items.h), which has reported its own error.
  bool checked(bool ok) {
    ok_ = ok_ && ok;
    return ok;
  }
  bool fail(const char* code, std::size_t pos, std::size_t len, std::string message) {
    if (ok_) diags_.error(code, range(pos, len), std::move(message));
    ok_ = false;
    return false;
  }
  bool syntax(std::size_t pos, std::size_t len, std::string message) {
    return fail(diag::code::Wl4Syntax, pos, len, std::move(message));
  }
  std::string found() const {
    return p_ < t_.size() ? fmt::format("'{}'", t_[p_]) : std::string("the end of the block");
  }

  // ---- block level
  bool programLine(std::size_t at);
  bool sequenceNumber(std::size_t at);
  /// N and its digits: the digits as written and their value, range-checked.
  std::optional<std::pair<std::string, long long>> nDigits(std::size_t at);
  bool item();
  bool addressWord(char letter, std::size_t at);
  bool jumpWord(std::size_t at);
  bool callWord(std::size_t at);
  bool guard(std::size_t at, std::size_t keywordEnd);
  bool assignment(std::size_t at);
  std::optional<std::string> digits(std::size_t at);

  // ---- values and expressions
  std::optional<std::string> number(); // digits [. digits] | . digits
  std::optional<ir::Expr> variable();  // # digits | #( expr )
  std::optional<ir::Expr> expr();
  std::optional<ir::Expr> term();
  std::optional<ir::Expr> factor();
  std::optional<ir::Expr> primary();
  std::optional<ir::Expr> parenthesised(std::size_t at);
  std::optional<ir::Expr> function(std::size_t at, std::string_view name);
  std::optional<ir::Op> binaryOp(int level);
  ir::Expr node(ir::ExprKind kind, std::size_t at, std::vector<ir::Expr> args) const {
    ir::Expr e;
    e.kind = kind;
    e.args = std::move(args);
    e.range = range(at, p_ - at);
    return e;
  }
  bool deeper(std::size_t at) {
    if (++depth_ <= kMaxExpressionDepth) return true;
    if (ok_) reportTooDeep(raw_, at, diags_);
    ok_ = false;
    return false;
  }

  const front::RawBlock& raw_;
  ir::Block& out_;
  diag::Engine& diags_;
  std::string_view t_;
  std::size_t p_ = 0;
  int depth_ = 0;
  bool ok_ = true;
};

bool Parser::block() {
  startBlock(raw_, out_);
  if (peek() == '%') return programLine(p_);
  if (peek() == '/') { // block skip: one level, before N (§1.7)
    out_.skipLevel = 1;
    ++p_;
  }
  if (peek() == 'N' && !isLetter(p_ + 1 < t_.size() ? t_[p_ + 1] : ' ') && !sequenceNumber(p_))
    return false;
  while (ok_ && peek() != '\0')
    if (!item()) return false;
  addLineComment(raw_, out_);
  finishBlock(out_);
  return ok_;
}

bool Parser::programLine(std::size_t at) {
  ++p_;
  const std::size_t nameAt = p_;
  while (p_ < t_.size() && (isLetter(t_[p_]) || isDigit(t_[p_]) || t_[p_] == '_'))
    ++p_;
  const std::string_view name = t_.substr(nameAt, p_ - nameAt);
  if (peek() != '\0')
    return syntax(
        p_, 1,
        fmt::format("{} after the program name: a name is letters, digits and '_'", found()));
  if (!checked(checkProgramName(raw_, nameAt, name, diags_))) return false;
  out_.kind = name.empty() ? ir::BlockKind::ProgramEnd : ir::BlockKind::ProgramStart;
  out_.programName = std::string(name);
  (void)at;
  addLineComment(raw_, out_);
  return true;
}

std::optional<std::string> Parser::digits(std::size_t at) {
  std::size_t e = p_;
  while (e < t_.size() && isDigit(t_[e]))
    ++e;
  if (e == p_) {
    syntax(at, p_ - at + 1, fmt::format("'{}' takes digits, found {}", t_[at], found()));
    return std::nullopt;
  }
  std::string d(t_.substr(p_, e - p_));
  if (e < t_.size() && t_[e] == '.') { // N10.5, L07.5, #1.5, IF3.5: a typo, not a message
    syntax(at, e - at + 1, fmt::format("'{}' takes whole digits, found '{}.'", t_[at], d));
    return std::nullopt;
  }
  p_ = e;
  return d;
}

std::optional<std::pair<std::string, long long>> Parser::nDigits(std::size_t at) {
  ++p_;
  auto d = digits(at);
  if (!d) return std::nullopt;
  const auto n = nValue(raw_, at, p_, *d, diags_);
  if (!checked(n.has_value())) return std::nullopt;
  return std::pair{*d, *n};
}

bool Parser::sequenceNumber(std::size_t at) {
  auto number = nDigits(at);
  if (!number) return false;
  setSequence(raw_, out_, at, p_, number->first, number->second);
  return true;
}

bool Parser::item() {
  const std::size_t at = p_;
  const char c = t_[p_];
  if (c == '.') { // a message where a word would start, to the end of the line (§1.6)
    addMessage(raw_, out_, at, t_.size());
    p_ = t_.size();
    return true;
  }
  if (c == '#') return assignment(at);
  if (c == '(') { // a Fanuc comment? In WL4 `(` only opens an expression (§1.6, §9)
    diags_.warning(diag::code::Wl4FanucComment, range(at, 1),
                   "`( )` is no comment in WL4: comments start with $ (a Fanuc comment?)");
    return syntax(at, 1, "'(' where a word would start: `(` opens an expression after an address");
  }
  if (!isLetter(c))
    return syntax(at, 1,
                  fmt::format("unexpected {}: a word starts with an address letter", found()));
  const std::string_view run = letters(at);
  if (run.size() > 1) {
    if (run == "IF") return guard(at, at + 2);
    return syntax(at, run.size(),
                  fmt::format("unknown word '{}': an address is one letter; a function as a value "
                              "is written in parentheses, X(ABS(#1))",
                              run));
  }
  if (c == 'N') return jumpWord(at);
  if (c == 'L') return callWord(at);
  return addressWord(c, at);
}

bool Parser::jumpWord(std::size_t at) {
  // an N that is not first: after the block, continue at label N0.. (§6.6)
  auto number = nDigits(at);
  if (!number) return false;
  addJump(raw_, out_, at, p_, number->first, number->second);
  return true;
}

bool Parser::callWord(std::size_t at) {
  // L nn: program %nn once; L nnpp: pp times (§6.7)
  ++p_;
  auto d = digits(at);
  if (!d) return false;
  return checked(addCall(raw_, out_, at, p_, *d, diags_));
}

bool Parser::guard(std::size_t at, std::size_t keywordEnd) {
  p_ = keywordEnd;
  ir::Stmt s;
  s.kind = ir::StmtKind::Guard;
  if (p_ < t_.size() && isDigit(t_[p_])) { // IF<p>: compare at p decimals (§6.5)
    auto d = digits(at);
    if (!d) return false;
    const auto precision = guardPrecision(raw_, keywordEnd, *d, diags_);
    if (!checked(precision.has_value())) return false;
    s.precision = *precision;
  }
  if (peek() != '(')
    return syntax(p_, 1, fmt::format("IF needs '(' condition ')', found {}", found()));
  auto cond = parenthesised(p_);
  if (!cond) return false;
  s.value = std::move(*cond);
  s.range = range(at, p_ - at);
  s.order = static_cast<std::uint32_t>(at);
  out_.stmts.push_back(std::move(s));
  return true;
}

bool Parser::assignment(std::size_t at) {
  // #n = expr: a statement anywhere in the block; the right side may go on with operators
  auto target = variable();
  if (!target) return false;
  if (peek() != '=' || peek2("=="))
    return syntax(p_, 1, fmt::format("a variable standing as a word needs '=', found {}", found()));
  ++p_;
  auto value = expr();
  if (!value) return false;
  ir::Stmt s;
  s.kind = ir::StmtKind::Assign;
  s.target = std::move(*target);
  s.value = std::move(*value);
  s.range = range(at, p_ - at);
  s.order = static_cast<std::uint32_t>(at);
  out_.stmts.push_back(std::move(s));
  return true;
}

bool Parser::addressWord(char letter, std::size_t at) {
  ++p_;
  ir::Word w;
  w.address = std::string(1, letter);
  w.order = static_cast<std::uint32_t>(at);
  // value = [+|-] (number | varref ["=" factor] | "(" expr ")")
  char sign = 0;
  const std::size_t signAt = p_ < t_.size() && t_[p_] == ' ' ? (spaces(), p_) : p_;
  if (peek() == '-' || peek() == '+') sign = t_[p_++];
  const char c = peek();
  if (isDigit(c) || c == '.') {
    if (sign) spaces();
    auto n = number();
    if (!n) return false;
    setLiteral(w, sign, *n);
  } else {
    std::optional<ir::Expr> e;
    const std::size_t valueAt = p_;
    if (c == '#') {
      e = variable();
      if (e && peek() == '=' && !peek2("==")) { // X#1=(e): assign and use (§6.4)
        ++p_;
        auto f = factor();
        if (!f) return false;
        e = node(ir::ExprKind::Assign, valueAt, {std::move(*e), std::move(*f)});
      }
    } else if (c == '(') {
      e = parenthesised(p_);
    } else if (isLetter(c)) {
      return syntax(p_, letters(p_).size(),
                    fmt::format("{}{}: a function as a value is written in parentheses, "
                                "{}({}(...))",
                                letter, letters(p_), letter, letters(p_)));
    } else {
      return syntax(at, 1, fmt::format("address {} without a value", letter));
    }
    if (!e) return false;
    if (sign) {
      ir::Expr u = node(ir::ExprKind::Unary, signAt, {std::move(*e)});
      u.op = sign == '-' ? ir::Op::Neg : ir::Op::Plus;
      e = std::move(u);
    }
    w.kind = ir::ValueKind::Expression;
    w.expr = std::move(*e);
  }
  w.range = range(at, p_ - at);
  out_.words.push_back(std::move(w));
  return true;
}

// ---------------------------------------------------------------- expressions

std::optional<std::string> Parser::number() {
  const std::size_t at = p_;
  while (p_ < t_.size() && isDigit(t_[p_]))
    ++p_;
  if (p_ < t_.size() && t_[p_] == '.') {
    ++p_;
    while (p_ < t_.size() && isDigit(t_[p_]))
      ++p_;
  }
  const std::string_view n = t_.substr(at, p_ - at);
  if (n == ".") {
    syntax(at, 1, "'.' without digits");
    return std::nullopt;
  }
  if (p_ < t_.size() && t_[p_] == ' ' && p_ + 1 < t_.size() && isDigit(t_[p_ + 1])) {
    syntax(at, p_ - at + 2, "a space inside a number (wl4.md §1.3)");
    return std::nullopt;
  }
  return std::string(n);
}

std::optional<ir::Expr> Parser::variable() {
  const std::size_t at = p_;
  ++p_;                                  // '#'
  if (p_ < t_.size() && t_[p_] == '(') { // #(e): the variable the value names
    auto e = parenthesised(p_);
    if (!e) return std::nullopt;
    return node(ir::ExprKind::Indirect, at, {std::move(e->args[0])});
  }
  if (p_ >= t_.size() || !isDigit(t_[p_])) {
    syntax(at, 1, fmt::format("'#' takes a number or '(' expression ')', found {}", found()));
    return std::nullopt;
  }
  auto d = digits(at);
  if (!d) return std::nullopt;
  ir::Expr v = ir::Expr::variable(front::decimalValue(*d));
  v.range = range(at, p_ - at);
  return v;
}

std::optional<ir::Op> Parser::binaryOp(int level) {
  spaces();
  const auto found = operatorAt(t_.substr(p_), level);
  if (!found) return std::nullopt;
  p_ += found->first;
  return found->second;
}

// two levels, each left to right: `** * / MOD`, then `+ - relational AND OR XOR` (§6.3)
std::optional<ir::Expr> Parser::expr() {
  spaces();
  const std::size_t at = p_;
  if (!deeper(at)) return std::nullopt;
  auto lhs = term();
  while (lhs) {
    const std::size_t before = p_;
    auto op = binaryOp(2);
    if (!op) break;
    auto rhs = term();
    if (!rhs) return std::nullopt;
    (void)before;
    ir::Expr b = node(ir::ExprKind::Binary, at, {std::move(*lhs), std::move(*rhs)});
    b.op = *op;
    lhs = std::move(b);
  }
  --depth_;
  return lhs;
}

std::optional<ir::Expr> Parser::term() {
  spaces();
  const std::size_t at = p_;
  auto lhs = factor();
  while (lhs) {
    auto op = binaryOp(1);
    if (!op) break;
    auto rhs = factor();
    if (!rhs) return std::nullopt;
    ir::Expr b = node(ir::ExprKind::Binary, at, {std::move(*lhs), std::move(*rhs)});
    b.op = *op;
    lhs = std::move(b);
  }
  return lhs;
}

std::optional<ir::Expr> Parser::factor() {
  const char c = peek();
  const std::size_t at = p_;
  if (c != '-' && c != '+') return primary();
  ++p_;
  if (!deeper(at)) return std::nullopt;
  auto e = primary();
  --depth_;
  if (!e) return std::nullopt;
  ir::Expr u = node(ir::ExprKind::Unary, at, {std::move(*e)});
  u.op = c == '-' ? ir::Op::Neg : ir::Op::Plus;
  return u;
}

std::optional<ir::Expr> Parser::primary() {
  const char c = peek();
  const std::size_t at = p_;
  if (isDigit(c) || c == '.') {
    auto n = number();
    if (!n) return std::nullopt;
    return ir::Expr::literal(front::decimalValue(*n), range(at, p_ - at));
  }
  if (c == '#') {
    auto v = variable();
    if (!v) return std::nullopt;
    if (peek() == '=' && !peek2("==")) {    // #n=factor binds tighter than any operator (§6.4)
      if (!deeper(at)) return std::nullopt; // a chain #1=#2=... nests like brackets
      ++p_;
      auto f = factor();
      --depth_;
      if (!f) return std::nullopt;
      return node(ir::ExprKind::Assign, at, {std::move(*v), std::move(*f)});
    }
    return v;
  }
  if (c == '(') return parenthesised(at);
  if (isLetter(c)) return function(at, letters(at));
  syntax(at, 1, fmt::format("expected a number, a variable or '(', found {}", found()));
  return std::nullopt;
}

std::optional<ir::Expr> Parser::parenthesised(std::size_t at) {
  ++p_; // '('
  auto e = expr();
  if (!e) return std::nullopt;
  if (peek() != ')') {
    syntax(p_, 1,
           fmt::format("expected ')' to close the '(' at column {}, found {}",
                       range(at, 1).begin.col, found()));
    return std::nullopt;
  }
  ++p_;
  return node(ir::ExprKind::Bracket, at, {std::move(*e)});
}

std::optional<ir::Expr> Parser::function(std::size_t at, std::string_view name) {
  const ir::Func* f = functionNamed(name);
  if (!f) {
    syntax(at, name.size(), fmt::format("unknown function '{}'", name));
    return std::nullopt;
  }
  p_ = at + name.size();
  if (peek() != '(') {
    syntax(p_, 1, fmt::format("{} needs its operand in parentheses, {}(...)", name, name));
    return std::nullopt;
  }
  auto a = parenthesised(p_);
  if (!a) return std::nullopt;
  std::vector<ir::Expr> args{std::move(a->args[0])};
  ir::Func func = *f;
  if (func == ir::Func::Atan && peek2("/")) { // ATAN(a)/(b): the angle of (b, a) (§6.3)
    const std::size_t slash = p_;
    ++p_;
    if (peek() == '(') {
      auto b = parenthesised(p_);
      if (!b) return std::nullopt;
      args.push_back(std::move(b->args[0]));
      func = ir::Func::Atan2;
    } else {
      p_ = slash; // ATAN(a)/2: a division
    }
  }
  ir::Expr e = node(ir::ExprKind::Call, at, std::move(args));
  e.func = func;
  return e;
}

} // namespace

bool parseBlock(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  Parser p(raw, out, diags);
  return p.block();
}

} // namespace gcx::wl4
