#include "dialects/wl4/tree_builder.h"

#include <fmt/format.h>
#include <limits>

#include "WL4Lexer.h"
#include "WL4Parser.h"
#include "diag/codes.h"
#include "dialects/wl4/block_items.h"
#include "front/antlr_block_parser.h"
#include "front/decimal_text.h"

namespace gcx::wl4 {

using P = wl4gen::WL4Parser;
using antlr4::ParserRuleContext;
using antlr4::Token;
using antlr4::tree::ParseTree;
using antlr4::tree::TerminalNode;

namespace {

Token* symbolOf(ParseTree* t) {
  auto* n = dynamic_cast<TerminalNode*>(t);
  return n ? n->getSymbol() : nullptr;
}

/// The token child k of c stands for, or null: error recovery may add tokens further on, so the
/// children are read by place, not by the accessors that search them.
Token* tokenAt(ParserRuleContext* c, std::size_t k) {
  return c && k < c->children.size() ? symbolOf(c->children[k]) : nullptr;
}

bool adjacent(const Token* a, const Token* b) {
  return a && b && a->getStopIndex() + 1 == b->getStartIndex();
}

bool isNumberToken(std::size_t type) {
  return type == P::DIGITS || type == P::DECIMAL || type == P::FRACTION;
}

bool isLetterRun(std::size_t type) {
  return type == P::ADDRESS || type == P::N || type == P::L || type == P::WORD || type == P::IF ||
         type == P::MOD || type == P::AND || type == P::OR || type == P::XOR || type == P::ATAN ||
         type == P::FUNCTION;
}

/// Turns a parse tree into the hand parser's IR. A tree with a syntax error at `limit` is walked
/// up to there: an error the hand parser finds before that point (an N out of range, a blank
/// after '#', an expression too deep) is the block's first error.
class TreeToIr {
public:
  TreeToIr(const front::RawBlock& raw, std::size_t textSize, ir::Block& out, diag::Engine& diags,
           std::size_t limit)
      : raw_(raw), textSize_(textSize), out_(out), diags_(diags), limit_(limit) {}

  bool line(P::LineContext* c);
  bool reported() const { return reported_; }

private:
  /// A shared rule may report at `pos` only before the syntax error.
  bool before(std::size_t pos) const { return pos < limit_; }
  bool failed(bool wasReported) {
    reported_ = reported_ || wasReported;
    return false;
  }
  bool syntax(std::size_t pos, std::size_t len, std::string message) {
    if (!before(pos)) return false;
    diags_.error(diag::code::Wl4Syntax, rangeOf(raw_, pos, len), std::move(message));
    return failed(true);
  }
  SourceRange rangeFrom(std::size_t pos, ParserRuleContext* c) const {
    const Token* stop = c ? c->getStop() : nullptr;
    const std::size_t end = stop && stop->getType() != Token::EOF ? stop->getStopIndex() + 1 : pos;
    return rangeOf(raw_, pos, end > pos ? end - pos : 1);
  }
  ir::Expr node(ir::ExprKind kind, std::size_t at, ParserRuleContext* c,
                std::vector<ir::Expr> args) const {
    ir::Expr e;
    e.kind = kind;
    e.args = std::move(args);
    e.range = rangeFrom(at, c);
    return e;
  }

  bool programStart(P::ProgramStartContext* c);
  /// N (first: the block number; later: a jump) with its digits written right after it.
  bool nWord(Token* n, Token* digits, bool first);
  bool item(P::ItemContext* c);
  bool word(P::ItemContext* c);
  bool guard(P::ItemContext* c);

  std::optional<ir::Expr> expr(P::ExprContext* c);
  std::optional<ir::Expr> term(P::TermContext* c);
  std::optional<ir::Expr> factor(P::FactorContext* c);
  std::optional<ir::Expr> primary(P::PrimaryContext* c);
  std::optional<ir::Expr> variable(P::VariableContext* c);
  std::optional<ir::Expr> assignedVariable(P::VariableContext* v, TerminalNode* assign,
                                           P::FactorContext* f, ParserRuleContext* c);
  /// `(` expr `)`: the expression itself, or wrapped as a Bracket node.
  std::optional<ir::Expr> parenthesised(TerminalNode* open, P::ExprContext* e, bool keepBracket);
  std::optional<ir::Expr> chain(ParserRuleContext* c, int level);

  const front::RawBlock& raw_;
  std::size_t textSize_;
  ir::Block& out_;
  diag::Engine& diags_;
  std::size_t limit_;
  int depth_ = 0;
  bool reported_ = false;
};

bool TreeToIr::line(P::LineContext* c) {
  startBlock(raw_, out_);
  if (!c) return false;
  if (auto* ps = c->programStart()) return programStart(ps);
  if (c->programEnd()) {
    out_.kind = ir::BlockKind::ProgramEnd;
    addLineComment(raw_, out_);
    return true;
  }
  if (c->SLASH()) out_.skipLevel = 1; // one level, before N (§1.7)
  if (auto* n = c->blockNumber())
    if (!nWord(tokenAt(n, 0), tokenAt(n, 1), true)) return false;
  for (P::ItemContext* it : c->item())
    if (!item(it)) return false;
  if (auto* m = c->message()) addMessage(raw_, out_, m->getStart()->getStartIndex(), textSize_);
  addLineComment(raw_, out_);
  finishBlock(out_);
  return true;
}

bool TreeToIr::programStart(P::ProgramStartContext* c) {
  Token* prev = c->PERCENT() ? c->PERCENT()->getSymbol() : nullptr;
  if (!prev) return false;
  const std::size_t nameAt = prev->getStartIndex() + 1;
  std::string name;
  for (std::size_t k = 1; k < c->children.size(); ++k) {
    auto* rule = dynamic_cast<ParserRuleContext*>(c->children[k]);
    Token* t = rule ? rule->getStart() : symbolOf(c->children[k]);
    if (!t) return false;
    if (!adjacent(prev, t))
      return syntax(t->getStartIndex(), 1,
                    fmt::format("'{}' after the program name: a name is letters, digits and '_'",
                                t->getText().substr(0, 1)));
    name += t->getText();
    prev = t;
  }
  if (!before(nameAt)) return false;
  if (!checkProgramName(raw_, nameAt, name, diags_)) return failed(true);
  out_.kind = ir::BlockKind::ProgramStart;
  out_.programName = name;
  addLineComment(raw_, out_);
  return true;
}

bool TreeToIr::nWord(Token* n, Token* digits, bool first) {
  if (!n) return false;
  const std::size_t at = n->getStartIndex();
  if (!adjacent(n, digits) || digits->getType() != P::DIGITS)
    return syntax(at, 2, "'N' takes digits written right after it");
  const std::size_t end = digits->getStopIndex() + 1;
  if (!before(at)) return false;
  const auto value = nValue(raw_, at, end, digits->getText(), diags_);
  if (!value) return failed(true);
  if (first)
    setSequence(raw_, out_, at, end, digits->getText(), *value);
  else
    addJump(raw_, out_, at, end, digits->getText(), *value);
  return true;
}

bool TreeToIr::item(P::ItemContext* c) {
  Token* first = c && !c->children.empty() ? symbolOf(c->children[0]) : nullptr;
  if (first && first->getType() == P::N) return nWord(first, tokenAt(c, 1), false);
  if (first && first->getType() == P::L) {
    Token* digits = tokenAt(c, 1);
    const std::size_t at = first->getStartIndex();
    if (!adjacent(first, digits) || digits->getType() != P::DIGITS)
      return syntax(at, 2, "'L' takes digits written right after it");
    if (!before(at)) return false;
    return addCall(raw_, out_, at, digits->getStopIndex() + 1, digits->getText(), diags_) ||
           failed(true);
  }
  if (first && first->getType() == P::IF) return guard(c);
  if (first && first->getType() == P::ADDRESS) return word(c);
  if (!c || !c->variable()) return false;
  // #n = expr: a statement anywhere in the block (§6.4)
  auto target = variable(c->variable());
  if (!target || !c->ASSIGN()) return false;
  auto value = expr(c->expr());
  if (!value) return false;
  const std::size_t at = c->getStart()->getStartIndex();
  ir::Stmt s;
  s.kind = ir::StmtKind::Assign;
  s.target = std::move(*target);
  s.value = std::move(*value);
  s.range = rangeFrom(at, c);
  s.order = static_cast<std::uint32_t>(at);
  out_.stmts.push_back(std::move(s));
  return true;
}

bool TreeToIr::guard(P::ItemContext* c) {
  Token* keyword = tokenAt(c, 0);
  const std::size_t at = keyword->getStartIndex();
  ir::Stmt s;
  s.kind = ir::StmtKind::Guard;
  if (Token* digits = tokenAt(c, 1); digits && digits->getType() == P::DIGITS) { // IF<p> (§6.5)
    if (!adjacent(keyword, digits))
      return syntax(digits->getStartIndex(), 1, "IF needs '(' condition ')'");
    if (!before(digits->getStartIndex())) return false;
    const auto precision = guardPrecision(raw_, digits->getStartIndex(), digits->getText(), diags_);
    if (!precision) return failed(true);
    s.precision = *precision;
  }
  auto cond = parenthesised(c->LPAREN(), c->expr(), true);
  if (!cond) return false;
  s.value = std::move(*cond);
  s.range = rangeFrom(at, c);
  s.order = static_cast<std::uint32_t>(at);
  out_.stmts.push_back(std::move(s));
  return true;
}

bool TreeToIr::word(P::ItemContext* c) {
  Token* address = c->ADDRESS()->getSymbol();
  const std::size_t at = address->getStartIndex();
  P::ValueContext* v = c->value();
  if (!v) return false;
  ir::Word w;
  w.address = address->getText();
  w.order = static_cast<std::uint32_t>(at);
  const char sign = v->sign() ? v->sign()->getText()[0] : 0;
  if (P::NumberContext* n = v->number()) {
    setLiteral(w, sign, n->getText());
  } else {
    std::optional<ir::Expr> e;
    if (v->variable())
      e = assignedVariable(v->variable(), v->ASSIGN(), v->factor(), v); // X#1=(e) (§6.4)
    else
      e = parenthesised(v->LPAREN(), v->expr(), true);
    if (!e) return false;
    if (sign) {
      ir::Expr u = node(ir::ExprKind::Unary, v->sign()->getStart()->getStartIndex(), v, {*e});
      u.op = sign == '-' ? ir::Op::Neg : ir::Op::Plus;
      e = std::move(u);
    }
    w.kind = ir::ValueKind::Expression;
    w.expr = std::move(*e);
  }
  w.range = rangeFrom(at, c);
  out_.words.push_back(std::move(w));
  return true;
}

// ---------------------------------------------------------------- expressions

std::optional<ir::Expr> TreeToIr::expr(P::ExprContext* c) {
  if (!c || !c->getStart()) return std::nullopt;
  const std::size_t at = c->getStart()->getStartIndex();
  if (++depth_ > kMaxExpressionDepth) {
    if (before(at)) {
      reportTooDeep(raw_, at, diags_);
      failed(true);
    }
    return std::nullopt;
  }
  auto e = chain(c, 2);
  --depth_;
  return e;
}

std::optional<ir::Expr> TreeToIr::term(P::TermContext* c) {
  return chain(c, 1);
}

// operand (op operand)*, left to right: terms joined by level-2 operators, or factors by level 1
std::optional<ir::Expr> TreeToIr::chain(ParserRuleContext* c, int level) {
  if (!c || c->children.empty() || !c->getStart()) return std::nullopt;
  const std::size_t at = c->getStart()->getStartIndex();
  auto operand = [&](ParseTree* t) -> std::optional<ir::Expr> {
    if (level == 2) return term(dynamic_cast<P::TermContext*>(t));
    return factor(dynamic_cast<P::FactorContext*>(t));
  };
  auto lhs = operand(c->children[0]);
  for (std::size_t k = 1; lhs && k + 1 < c->children.size(); k += 2) {
    const auto op = operatorAt(c->children[k]->getText(), level);
    auto rhs = operand(c->children[k + 1]);
    if (!op || !rhs) return std::nullopt;
    ir::Expr b = node(ir::ExprKind::Binary, at, c, {std::move(*lhs), std::move(*rhs)});
    b.op = op->second;
    lhs = std::move(b);
  }
  return lhs;
}

std::optional<ir::Expr> TreeToIr::factor(P::FactorContext* c) {
  if (!c) return std::nullopt;
  if (!c->sign()) return primary(c->primary());
  const std::size_t at = c->sign()->getStart()->getStartIndex();
  if (++depth_ > kMaxExpressionDepth) {
    if (before(at)) {
      reportTooDeep(raw_, at, diags_);
      failed(true);
    }
    return std::nullopt;
  }
  auto e = primary(c->primary());
  --depth_;
  if (!e) return std::nullopt;
  ir::Expr u = node(ir::ExprKind::Unary, at, c, {std::move(*e)});
  u.op = c->sign()->MINUS() ? ir::Op::Neg : ir::Op::Plus;
  return u;
}

std::optional<ir::Expr> TreeToIr::primary(P::PrimaryContext* c) {
  if (!c || !c->getStart()) return std::nullopt;
  const std::size_t at = c->getStart()->getStartIndex();
  if (P::NumberContext* n = c->number())
    return ir::Expr::literal(front::decimalValue(n->getText()), rangeFrom(at, c));
  if (c->variable() && c->ASSIGN()) { // a chain #1=#2=... nests like brackets
    if (++depth_ > kMaxExpressionDepth) {
      if (before(at)) {
        reportTooDeep(raw_, at, diags_);
        failed(true);
      }
      return std::nullopt;
    }
    auto e = assignedVariable(c->variable(), c->ASSIGN(), c->factor(), c);
    --depth_;
    return e;
  }
  if (c->variable()) return assignedVariable(c->variable(), c->ASSIGN(), c->factor(), c);
  const auto parens = c->LPAREN();
  const auto exprs = c->expr();
  if (parens.empty() || exprs.empty()) return std::nullopt;
  if (!c->ATAN() && !c->FUNCTION()) return parenthesised(parens[0], exprs[0], true);
  auto a = parenthesised(parens[0], exprs[0], false);
  if (!a) return std::nullopt;
  std::vector<ir::Expr> args{std::move(*a)};
  ir::Func func = ir::Func::Atan;
  if (c->FUNCTION()) {
    const ir::Func* f = functionNamed(c->FUNCTION()->getText());
    if (!f) return std::nullopt;
    func = *f;
  } else if (exprs.size() == 2) { // ATAN(a)/(b): the angle of (b, a) (§6.3)
    auto b = parenthesised(parens.size() > 1 ? parens[1] : nullptr, exprs[1], false);
    if (!b) return std::nullopt;
    args.push_back(std::move(*b));
    func = ir::Func::Atan2;
  }
  ir::Expr e = node(ir::ExprKind::Call, at, c, std::move(args));
  e.func = func;
  return e;
}

std::optional<ir::Expr> TreeToIr::assignedVariable(P::VariableContext* v, TerminalNode* assign,
                                                   P::FactorContext* f, ParserRuleContext* c) {
  auto var = variable(v);
  if (!var || !assign) return var;
  auto value = factor(f); // #n=factor binds tighter than any operator (§6.4)
  if (!value) return std::nullopt;
  return node(ir::ExprKind::Assign, v->getStart()->getStartIndex(), c,
              {std::move(*var), std::move(*value)});
}

std::optional<ir::Expr> TreeToIr::variable(P::VariableContext* c) {
  Token* hash = tokenAt(c, 0);
  Token* next = tokenAt(c, 1);
  if (!hash || !next) return std::nullopt;
  const std::size_t at = hash->getStartIndex();
  if (!adjacent(hash, next)) {
    syntax(at, 1, "'#' takes a number or '(' expression ')' written right after it");
    return std::nullopt;
  }
  if (next->getType() == P::DIGITS)
    return ir::Expr::variable(front::decimalValue(next->getText()), rangeFrom(at, c));
  auto e = parenthesised(c->LPAREN(), c->expr(), false); // #(e): the variable e names
  if (!e) return std::nullopt;
  return node(ir::ExprKind::Indirect, at, c, {std::move(*e)});
}

std::optional<ir::Expr> TreeToIr::parenthesised(TerminalNode* open, P::ExprContext* e,
                                                bool keepBracket) {
  if (!open) return std::nullopt;
  auto inner = expr(e);
  if (!inner || !keepBracket) return inner;
  const std::size_t at = open->getSymbol()->getStartIndex();
  ir::Expr b = node(ir::ExprKind::Bracket, at, nullptr, {std::move(*inner)});
  if (e && e->getStop()) b.range = rangeOf(raw_, at, e->getStop()->getStopIndex() + 2 - at);
  return b;
}

} // namespace

struct GrammarParser::Impl : front::AntlrBlockParser<wl4gen::WL4Lexer, P> {
  /// The first syntax error, located where the hand parser finds it.
  void report(const front::RawBlock& raw, std::size_t textSize, diag::Engine& diags);
  /// Past this many open parentheses the hand parser has surely stopped (each opens an
  /// expression): the text is cut after the next token, so the tree stays shallow.
  std::size_t cutForDepth();
};

void GrammarParser::Impl::report(const front::RawBlock& raw, std::size_t textSize,
                                 diag::Engine& diags) {
  const std::vector<Token*> toks = visibleTokens();
  Token* off = first.token;
  std::size_t k = 0;
  while (k < toks.size() && toks[k] != off)
    ++k;
  if (!off || k == toks.size()) {
    diags.error(diag::code::Wl4Syntax, rangeOf(raw, first.pos, 1), "unexpected text");
    return;
  }
  const std::size_t type = off->getType();
  const std::size_t pos = type == Token::EOF ? textSize : off->getStartIndex();
  const std::string found =
      type == Token::EOF ? "the end of the block" : fmt::format("'{}'", off->getText());
  Token* prev = k >= 1 ? toks[k - 1] : nullptr;
  Token* prev2 = k >= 2 ? toks[k - 2] : nullptr;
  auto typeOf = [](const Token* t) { return t ? t->getType() : Token::INVALID_TYPE; };
  auto at = [&](const Token* t, std::string message) {
    diags.error(diag::code::Wl4Syntax, rangeOf(raw, t->getStartIndex(), 1), std::move(message));
  };
  if (typeOf(toks[0]) == P::PERCENT) { // a program line: where the name stops (`%A1.5`: at '.')
    const std::size_t stop = type == P::DECIMAL ? pos + off->getText().find('.') : pos;
    diags.error(diag::code::Wl4Syntax, rangeOf(raw, stop, 1),
                fmt::format("{} after the program name: a name is letters, digits and '_'", found));
    return;
  }
  // N, L and # take whole digits (or '#' a parenthesis) right after them, IF<p> whole digits
  if (typeOf(prev) == P::N || typeOf(prev) == P::L || typeOf(prev) == P::HASH ||
      (typeOf(prev) == P::IF && type == P::DECIMAL))
    return at(prev, fmt::format("'{}' takes whole digits, found {}", prev->getText(), found));
  // an address without a value: a word or '.' is named where it stands, anything else at the
  // address
  const bool signed_ = typeOf(prev) == P::PLUS || typeOf(prev) == P::MINUS;
  Token* address = typeOf(prev) == P::ADDRESS               ? prev
                   : signed_ && typeOf(prev2) == P::ADDRESS ? prev2
                                                            : nullptr;
  if (address && !isLetterRun(type) && type != P::DOT)
    return at(address, fmt::format("address {} without a value", address->getText()));
  // a blank inside a number (wl4.md §1.3); the digits of N, L, # and IF<p> are no number
  if (isNumberToken(type) && off->getText()[0] != '.' && isNumberToken(typeOf(prev)) &&
      prev->getStopIndex() + 2 == off->getStartIndex() && typeOf(prev2) != P::N &&
      typeOf(prev2) != P::L && typeOf(prev2) != P::HASH && typeOf(prev2) != P::IF)
    return at(prev, "a space inside a number (wl4.md §1.3)");
  // `(` where a word would start (the parser was between items): a Fanuc comment? (§1.6, §9)
  if (type == P::LPAREN && first.rule == P::RuleLine) {
    diags.warning(diag::code::Wl4FanucComment, rangeOf(raw, pos, 1),
                  "`( )` is no comment in WL4: comments start with $ (a Fanuc comment?)");
    return at(off, "'(' where a word would start: `(` opens an expression after an address");
  }
  diags.error(diag::code::Wl4Syntax, rangeOf(raw, pos, 1), fmt::format("unexpected {}", found));
}

std::size_t GrammarParser::Impl::cutForDepth() {
  const std::vector<Token*> toks = visibleTokens();
  // brackets nest, and so does a chain of assignments #1=#2=#3... (each '=' right after the
  // variable the previous '=' assigned)
  int open = 0, chain = 0;
  std::size_t lastAssign = 0;
  for (std::size_t k = 0; k + 1 < toks.size(); ++k) {
    const std::size_t type = toks[k]->getType();
    open += type == P::LPAREN ? 1 : type == P::RPAREN ? -1 : 0;
    if (type == P::ASSIGN) {
      const bool chained = chain > 0 && k == lastAssign + 3 && toks[k - 2]->getType() == P::HASH &&
                           toks[k - 1]->getType() == P::DIGITS;
      chain = chained ? chain + 1 : 1;
      lastAssign = k;
    }
    if (open + chain > kMaxExpressionDepth + 1 && toks[k + 1]->getType() != Token::EOF)
      return toks[k + 1]->getStopIndex() + 1;
  }
  return std::string::npos;
}

GrammarParser::GrammarParser() : impl_(std::make_unique<Impl>()) {}
GrammarParser::~GrammarParser() = default;

bool GrammarParser::parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  Impl& m = *impl_;
  std::string text = raw.lexText.substr(0, raw.lineCommentAt); // the `$` comment is the reader's
  m.reset(text);
  m.tokens.fill();
  if (const std::size_t cut = m.cutForDepth(); cut != std::string::npos) {
    text.resize(cut);
    m.reset(text);
    m.tokens.fill();
  }
  P::LineContext* tree = m.parser.line();
  const std::size_t limit =
      m.first.set
          ? (m.first.token && m.first.token->getType() == Token::EOF ? text.size() : m.first.pos)
          : std::numeric_limits<std::size_t>::max();
  TreeToIr builder(raw, text.size(), out, diags, limit);
  const bool ok = builder.line(tree);
  if (builder.reported()) return false;
  if (m.first.set) {
    m.report(raw, text.size(), diags);
    return false;
  }
  return ok;
}

} // namespace gcx::wl4
