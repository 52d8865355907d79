#include "dialects/nct/tree_builder.h"

#include <climits>
#include <fmt/format.h>

#include "NCTLexer.h"
#include "NCTParser.h"
#include "antlr4-runtime.h"
#include "diag/codes.h"
#include "front/antlr_block_parser.h"

namespace gcx::nct {

using P = nctgen::NCTParser;
using antlr4::Token;

namespace {

// Cancels the first (fast, SLL) attempt at the first error; the second attempt runs full LL.
class Cancel : public antlr4::BaseErrorListener {
public:
  bool hit = false;
  void syntaxError(antlr4::Recognizer*, Token*, std::size_t, std::size_t, const std::string&,
                   std::exception_ptr) override {
    hit = true;
  }
};

ir::Op opOf(std::size_t tokenType) {
  switch (tokenType) {
  case P::PLUS:
    return ir::Op::Add;
  case P::MINUS:
    return ir::Op::Sub;
  case P::OR:
    return ir::Op::Or;
  case P::XOR:
    return ir::Op::Xor;
  case P::STAR:
    return ir::Op::Mul;
  case P::SLASH:
    return ir::Op::Div;
  case P::AND:
    return ir::Op::And;
  case P::MOD:
    return ir::Op::Mod;
  }
  return ir::Op::Add;
}

ir::Func funcOf(std::size_t tokenType) {
  switch (tokenType) {
  case P::SIN:
    return ir::Func::Sin;
  case P::COS:
    return ir::Func::Cos;
  case P::TAN:
    return ir::Func::Tan;
  case P::ASIN:
    return ir::Func::Asin;
  case P::ACOS:
    return ir::Func::Acos;
  case P::ATAN:
    return ir::Func::Atan;
  case P::SQRT:
    return ir::Func::Sqrt;
  case P::EXP:
    return ir::Func::Exp;
  case P::LN:
    return ir::Func::Ln;
  case P::ABS:
    return ir::Func::Abs;
  case P::FIX:
    return ir::Func::Fix;
  }
  return ir::Func::Fup;
}

ir::RelOp relOf(std::size_t tokenType) {
  switch (tokenType) {
  case P::EQ:
    return ir::RelOp::Eq;
  case P::NE:
    return ir::RelOp::Ne;
  case P::GT:
    return ir::RelOp::Gt;
  case P::GE:
    return ir::RelOp::Ge;
  case P::LT:
    return ir::RelOp::Lt;
  }
  return ir::RelOp::Le;
}

bool isMessageVariable(const ir::Expr& target) {
  if (target.kind == ir::ExprKind::Variable)
    return target.number == 3000 || target.number == 3006 || target.number == 3106 ||
           target.number == 3107;
  if (target.kind == ir::ExprKind::Named)
    return target.name == "ALM" || target.name == "MSGSTP" || target.name == "MSG" ||
           target.name == "MSGBOX";
  return false;
}

// Turns a parse tree into IR through the shared BlockBuilder.
class TreeToIr {
public:
  explicit TreeToIr(BlockBuilder& b) : b_(b) {}

  void block(P::BlockContext* ctx) {
    if (auto* ps = ctx->programStart()) {
      b_.programStart(ps->getStart()->getStartIndex(), ps->NUMBER() ? ps->NUMBER()->getText() : "");
      return;
    }
    if (auto* sk = ctx->blockSkip())
      b_.skip(start(sk), length(sk), sk->NUMBER() ? sk->NUMBER()->getText() : std::string());
    if (auto* sq = ctx->sequenceNumber())
      b_.sequence(start(sq), length(sq), sq->NUMBER()->getText());
    auto* body = ctx->body();
    if (auto* st = body->statement()) {
      statement(st);
      return;
    }
    for (auto* w : body->word())
      word(w);
    // `N#1`, `O#1`: a variable where a block or program number stands (macro B2, 000:11857)
    for (const ir::Word& w : b_.block().words) {
      const bool blockNumber = w.is('N') && !ctx->sequenceNumber() && &w == &b_.block().words[0];
      if ((blockNumber || w.is('O')) && w.kind != ir::ValueKind::Number) {
        b_.diags().error(diag::code::VariableNotAllowed, w.range,
                         fmt::format("{} must be a literal number, not a variable or expression",
                                     w.is('O') ? "a program number" : "a block number"));
        b_.fail();
        break;
      }
    }
  }

private:
  static std::size_t start(antlr4::ParserRuleContext* c) { return c->getStart()->getStartIndex(); }
  static std::size_t length(antlr4::ParserRuleContext* c) {
    return c->getStop()->getStopIndex() + 1 - c->getStart()->getStartIndex();
  }
  static std::size_t start(antlr4::tree::TerminalNode* t) {
    return t->getSymbol()->getStartIndex();
  }
  SourceRange range(antlr4::ParserRuleContext* c) const { return b_.range(start(c), length(c)); }
  SourceRange span(antlr4::tree::TerminalNode* from, antlr4::tree::TerminalNode* to) const {
    return b_.range(start(from), to->getSymbol()->getStopIndex() + 1 - start(from));
  }

  void word(P::WordContext* w) {
    if (auto* aw = dynamic_cast<P::AddressWordContext*>(w)) {
      value(aw->address()->getText(), start(aw), length(aw), aw->I() != nullptr, aw->value());
    } else if (auto* cw = dynamic_cast<P::CommaWordContext*>(w)) {
      value(std::string(",").append(cw->address()->getText()), start(cw), length(cw), false,
            cw->value());
    } else if (auto* xw = dynamic_cast<P::AxisNumberWordContext*>(w)) {
      value("AX", start(xw), length(xw), xw->I() != nullptr, xw->value());
      b_.block().words.back().axisIndex.push_back(expr(xw->expr()));
    } else if (auto* pw = dynamic_cast<P::PathWordContext*>(w)) {
      ir::Word& word = b_.newWord(ir::kPathAddress, start(pw), length(pw));
      word.kind = ir::ValueKind::Path;
      const std::size_t p = start(pw); // the path keeps its case
      word.text = b_.raw().text.substr(p + 1, pw->PATH()->getText().size() - 2);
    }
  }

  void value(const std::string& address, std::size_t pos, std::size_t len, bool incremental,
             P::ValueContext* v) {
    if (auto* nv = dynamic_cast<P::NumberValueContext*>(v)) {
      const char sign = !nv->sign() ? 0 : nv->sign()->MINUS() ? '-' : '+';
      b_.literalWord(address, pos, len, incremental, sign, nv->NUMBER()->getText());
      return;
    }
    ir::Word& w = b_.newWord(address, pos, len);
    w.incremental = incremental;
    w.kind = ir::ValueKind::Expression;
    P::SignContext* sign = nullptr;
    ir::Expr e;
    if (auto* vv = dynamic_cast<P::VariableValueContext*>(v)) {
      sign = vv->sign();
      e = variable(vv->variable());
    } else if (auto* bv = dynamic_cast<P::BracketValueContext*>(v)) {
      sign = bv->sign();
      e.kind = ir::ExprKind::Bracket;
      e.range = b_.range(start(bv->LBRACK()),
                         bv->RBRACK()->getSymbol()->getStopIndex() + 1 - start(bv->LBRACK()));
      e.args.push_back(expr(bv->expr()));
    }
    if (sign) {
      ir::Expr u;
      u.kind = ir::ExprKind::Unary;
      u.op = sign->MINUS() ? ir::Op::Neg : ir::Op::Plus;
      u.range = range(v);
      u.args.push_back(std::move(e));
      e = std::move(u);
    }
    w.expr = std::move(e);
  }

  ir::Expr variable(P::VariableContext* v) {
    ir::Expr e;
    e.range = range(v);
    if (auto* nv = dynamic_cast<P::NumberedVariableContext*>(v)) {
      std::int64_t n = 0;
      const std::string digits = nv->NUMBER()->getText();
      if (!wholeNumber(digits, n)) {
        const auto dot = digits.find('.');
        if (dot == std::string::npos || digits.find_first_not_of('0', dot + 1) == std::string::npos)
          b_.diags().error(diag::code::UndefinedVariable, e.range,
                           fmt::format("#{} does not exist: variable numbers have at most 12 "
                                       "digits",
                                       digits));
        else
          b_.diags().error(diag::code::SyntaxError, e.range,
                           fmt::format("variable number '{}' must be a whole number", digits));
        b_.fail();
      }
      e.kind = ir::ExprKind::Variable;
      e.number = static_cast<double>(n);
    } else if (auto* iv = dynamic_cast<P::IndirectVariableContext*>(v)) {
      e.kind = ir::ExprKind::Indirect;
      e.args.push_back(expr(iv->expr()));
    } else if (auto* sv = dynamic_cast<P::NamedVariableContext*>(v)) {
      e.kind = ir::ExprKind::Named;
      e.name = sv->SYSTEM_NAME()->getText().substr(2);
      if (sv->expr()) e.args.push_back(expr(sv->expr()));
    }
    return e;
  }

  ir::Expr binary(ir::Op op, ir::Expr lhs, ir::Expr rhs) {
    ir::Expr e;
    e.kind = ir::ExprKind::Binary;
    e.op = op;
    e.range = lhs.range;
    const auto end = rhs.range.begin.offset + rhs.range.length;
    e.range.length = static_cast<std::uint32_t>(end - lhs.range.begin.offset);
    e.args.push_back(std::move(lhs));
    e.args.push_back(std::move(rhs));
    return e;
  }

  ir::Expr expr(P::ExprContext* c) {
    auto terms = c->term();
    auto ops = c->addOp();
    ir::Expr e = term(terms[0]);
    for (std::size_t i = 0; i < ops.size(); ++i)
      e = binary(opOf(ops[i]->getStart()->getType()), std::move(e), term(terms[i + 1]));
    return e;
  }

  ir::Expr term(P::TermContext* c) {
    auto us = c->unary();
    auto ops = c->mulOp();
    ir::Expr e = unary(us[0]);
    for (std::size_t i = 0; i < ops.size(); ++i) {
      ir::Expr rhs = unary(us[i + 1]);
      const ir::Op op = opOf(ops[i]->getStart()->getType());
      // ATAN[a]/[b] is ATAN[a] divided by b in NCT, not Fanuc's two-argument arctangent
      if (op == ir::Op::Div && e.kind == ir::ExprKind::Call && e.func == ir::Func::Atan &&
          rhs.kind == ir::ExprKind::Bracket)
        b_.diags().warning(diag::code::AtanTwoArgs, e.range,
                           "ATAN[a]/[b] divides ATAN[a] by b: NCT has no two-argument ATAN "
                           "(nct-macro.md §3.1)");
      e = binary(op, std::move(e), std::move(rhs));
    }
    return e;
  }

  ir::Expr unary(P::UnaryContext* c) {
    if (c->primary()) return primary(c->primary());
    ir::Expr e;
    e.kind = ir::ExprKind::Unary;
    e.op = c->MINUS() ? ir::Op::Neg : ir::Op::Plus;
    e.range = range(c);
    e.args.push_back(unary(c->unary()));
    return e;
  }

  ir::Expr primary(P::PrimaryContext* c) {
    ir::Expr e;
    e.range = range(c);
    if (auto* n = dynamic_cast<P::NumberPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::Number;
      e.number = b_.number(n->NUMBER()->getText(), start(n));
    } else if (auto* v = dynamic_cast<P::VariablePrimaryContext*>(c)) {
      e = variable(v->variable());
    } else if (auto* br = dynamic_cast<P::BracketPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::Bracket;
      e.args.push_back(expr(br->expr()));
    } else if (auto* call = dynamic_cast<P::CallPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::Call;
      e.func = funcOf(call->function()->getStart()->getType());
      e.args.push_back(primary(call->primary()));
    } else if (auto* nt = dynamic_cast<P::NotPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::Unary;
      e.op = ir::Op::Not;
      e.args.push_back(primary(nt->primary()));
    } else if (auto* ax = dynamic_cast<P::AxnumPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::AxisNumber;
      e.name = ax->address()->getText();
    } else if (auto* prm = dynamic_cast<P::PrmPrimaryContext*>(c)) {
      e.kind = ir::ExprKind::Parameter;
      auto args = prm->expr();
      e.prmHasBit = prm->COMMA() != nullptr;
      e.prmHasIndex = prm->SLASH() != nullptr;
      for (auto* a : args)
        e.args.push_back(expr(a));
      if (!prmAllowed_) {
        b_.diags().error(diag::code::ForbiddenAddress, e.range,
                         "PRM may only stand as the whole right side of an assignment "
                         "(nct-macro.md §9.2)");
        b_.fail();
      }
    }
    return e;
  }

  ir::Stmt& newStmt(P::StatementContext* c, ir::StmtKind kind) {
    return b_.newStmt(kind, start(c), length(c));
  }

  void assignment(ir::Stmt& s, P::AssignmentContext* a) {
    s.target = variable(a->variable());
    auto* rhs = a->expr();
    // PRM[...] is allowed only as the whole right side
    auto* t = rhs->term().size() == 1 && rhs->addOp().empty() ? rhs->term(0) : nullptr;
    auto* u = t && t->unary().size() == 1 ? t->unary(0) : nullptr;
    prmAllowed_ = u && u->primary() && dynamic_cast<P::PrmPrimaryContext*>(u->primary());
    s.value = expr(rhs);
    prmAllowed_ = false;
  }

  void condition(ir::Stmt& s, P::ConditionContext* c) {
    ir::Condition cond;
    cond.lhs = expr(c->expr(0));
    cond.op = relOf(c->relation()->getStart()->getType());
    cond.rhs = expr(c->expr(1));
    s.cond = std::move(cond);
  }

  int loopId(antlr4::tree::TerminalNode* number) {
    std::int64_t n = 0;
    if (!wholeNumber(number->getText(), n)) {
      b_.diags().error(diag::code::SyntaxError, b_.range(start(number), number->getText().size()),
                       "a loop number must be a whole number");
      b_.fail();
    }
    return static_cast<int>(std::min<std::int64_t>(n, INT_MAX)); // the checker reports > 3
  }

  std::optional<double> optionalNumber(antlr4::tree::TerminalNode* t) {
    if (!t) return std::nullopt;
    return b_.number(t->getText(), start(t));
  }

  void statement(P::StatementContext* st) {
    if (auto* a = dynamic_cast<P::AssignStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::Assign);
      assignment(s, a->assignment());
      attachMessage(s);
    } else if (auto* g = dynamic_cast<P::GotoStatementContext*>(st)) {
      newStmt(st, ir::StmtKind::Goto).value = expr(g->expr());
    } else if (auto* ig = dynamic_cast<P::IfGotoStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::IfGoto);
      condition(s, ig->condition());
      s.value = expr(ig->expr());
    } else if (auto* it = dynamic_cast<P::IfThenStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::IfThen);
      condition(s, it->condition());
      assignment(s, it->assignment());
      attachMessage(s);
    } else if (auto* wh = dynamic_cast<P::WhileStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::While);
      condition(s, wh->condition());
      s.loopId = loopId(wh->NUMBER());
      s.loopRange = span(wh->DO(), wh->NUMBER());
    } else if (auto* d = dynamic_cast<P::DoStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::Do);
      s.loopId = loopId(d->NUMBER());
      s.loopRange = span(d->DO(), d->NUMBER());
    } else if (auto* en = dynamic_cast<P::EndStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::End);
      s.loopId = loopId(en->NUMBER());
      s.loopRange = span(en->END(), en->NUMBER());
    } else if (auto* pr = dynamic_cast<P::PrintStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::Print);
      printItems(s, pr->PRINT_COMMAND());
    } else if (auto* po = dynamic_cast<P::PopenStatementContext*>(st)) {
      newStmt(st, ir::StmtKind::Popen).device = optionalNumber(po->NUMBER());
    } else if (auto* pc = dynamic_cast<P::PclosStatementContext*>(st)) {
      newStmt(st, ir::StmtKind::Pclos).device = optionalNumber(pc->NUMBER());
    } else if (auto* fo = dynamic_cast<P::FopenStatementContext*>(st)) {
      ir::Stmt& s = newStmt(st, ir::StmtKind::Fopen);
      auto nums = fo->NUMBER();
      s.device = optionalNumber(nums[0]);
      if (nums.size() > 1) s.program = optionalNumber(nums[1]);
      if (fo->PATH()) {
        const std::size_t p = start(fo->PATH());
        s.path = b_.raw().text.substr(p + 1, fo->PATH()->getText().size() - 2);
      }
    } else if (dynamic_cast<P::FclosStatementContext*>(st)) {
      newStmt(st, ir::StmtKind::Fclos);
    }
  }

  // `#3000=1(TOOL BROKEN)`: the comment is the message (nct-macro.md L4)
  void attachMessage(ir::Stmt& s) {
    if (isMessageVariable(s.target) && !b_.block().comments.empty())
      s.message = b_.block().comments.front().text;
  }

  // DPRNT[X#100[53] Y#101[53]]: text, and variables with a format of integer and fraction digits
  void printItems(ir::Stmt& s, antlr4::tree::TerminalNode* node) {
    const std::string text = node->getText();
    s.binaryPrint = text[0] == 'B';
    const std::size_t open = text.find('[');
    const std::string inner = text.substr(open + 1, text.size() - open - 2);
    std::string pending;
    auto flush = [&] {
      if (pending.empty()) return;
      ir::PrintItem item;
      item.text = std::move(pending);
      s.items.push_back(std::move(item));
      pending.clear();
    };
    for (std::size_t i = 0; i < inner.size(); ++i) {
      if (inner[i] != '#') {
        pending.push_back(inner[i]);
        continue;
      }
      flush();
      ir::PrintItem item;
      item.isVariable = true;
      std::size_t j = i + 1;
      while (j < inner.size() && std::isdigit(static_cast<unsigned char>(inner[j])))
        item.variable = item.variable * 10 + (inner[j++] - '0');
      if (j < inner.size() && inner[j] == '[') {
        std::size_t close = inner.find(']', j);
        std::string fmtDigits = inner.substr(j + 1, close - j - 1);
        // #v[cd]: c integer and d fraction digits, 0 < c+d < 16 (nct-macro.md §6)
        const bool sane =
            fmtDigits.size() <= 3 &&
            fmtDigits.find_first_not_of("0123456789") == std::string::npos &&
            (fmtDigits.size() < 2 || std::atoi(fmtDigits.substr(0, fmtDigits.size() - 1).c_str()) +
                                             (fmtDigits.back() - '0') <
                                         16);
        if (!sane) {
          b_.diags().error(
              diag::code::DataOutOfRange, b_.range(start(node) + open + 1 + j, close - j + 1),
              fmt::format("print format [{}]: c integer and d fraction digits need 0 < c+d < 16",
                          fmtDigits));
          b_.fail();
          return;
        }
        if (!fmtDigits.empty()) {
          item.intDigits = std::atoi(fmtDigits.substr(0, fmtDigits.size() - 1).c_str());
          item.fracDigits = fmtDigits.back() - '0';
          if (fmtDigits.size() == 1) item.intDigits = item.fracDigits, item.fracDigits = 0;
        }
        j = close + 1;
      }
      s.items.push_back(std::move(item));
      i = j - 1;
    }
    flush();
  }

  BlockBuilder& b_;
  bool prmAllowed_ = false;
};

// Brackets are checked before the grammar so the two alarms of nct-macro.md §3.4 come out exactly:
// a ']' without '[' is 2064, a '[' never closed is 2121.
bool checkBrackets(const front::RawBlock& raw, diag::Engine& diags) {
  const std::string& s = raw.lexText;
  std::vector<std::size_t> open;
  bool comment = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (comment) {
      comment = c != ')';
      continue;
    }
    if (c == '(')
      comment = true;
    else if (c == '<') { // a file path may hold anything
      auto close = s.find('>', i);
      if (close != std::string::npos) i = close;
    } else if (c == '[')
      open.push_back(i);
    else if (c == ']') {
      if (open.empty()) {
        diags.error(diag::code::SyntaxError, raw.rangeAt(i, 1), "']' without a matching '['");
        return false;
      }
      open.pop_back();
    }
  }
  if (!open.empty()) {
    diags.error(diag::code::RightBracketNotFound, raw.rangeAt(open.front(), 1),
                "'[' is not closed by ']'");
    return false;
  }
  return true;
}

// The grammar recurses once per bracket, sign, function and NOT of an expression; a block
// nested deeper than kMaxExpressionDepth is refused before the parser sees it, so no input can
// exhaust the stack (of the parser, the IR builder or the evaluator, all bounded by the same
// depth). A run of prefix operators counts one level each; a bracket adds the run before it.
// A chain of binary operators parses flat but becomes a left-deep tree, one level per operator,
// so a block holds at most kMaxOperators operators.
constexpr int kMaxExpressionDepth = 64;
constexpr int kMaxOperators = 1000;

bool checkNestingDepth(const front::RawBlock& raw, const std::vector<Token*>& tokens,
                       diag::Engine& diags) {
  std::vector<int> outer; // the depth outside each open bracket
  int depth = 0, prefixRun = 0, operators = 0;
  for (Token* t : tokens) {
    if (t->getChannel() != Token::DEFAULT_CHANNEL) continue;
    const auto type = t->getType();
    const bool prefix = type == P::PLUS || type == P::MINUS || type == P::NOT || type == P::HASH ||
                        type == P::SIN || type == P::COS || type == P::TAN || type == P::ASIN ||
                        type == P::ACOS || type == P::ATAN || type == P::SQRT || type == P::EXP ||
                        type == P::LN || type == P::ABS || type == P::FIX || type == P::FUP;
    const bool binary = type == P::STAR || type == P::SLASH || type == P::AND || type == P::MOD ||
                        type == P::OR || type == P::XOR;
    if (((prefix && type != P::HASH) || binary) && ++operators > kMaxOperators) {
      diags.error(diag::code::ExpressionTooDeep, raw.rangeAt(t->getStartIndex(), 1),
                  fmt::format("more than {} operators in one block", kMaxOperators));
      return false;
    }
    if (type == P::LBRACK) {
      outer.push_back(depth);
      depth += prefixRun + 1;
      prefixRun = 0;
    } else if (type == P::RBRACK) {
      depth = outer.empty() ? 0 : outer.back();
      if (!outer.empty()) outer.pop_back();
      prefixRun = 0;
    } else if (prefix) {
      ++prefixRun;
    } else {
      prefixRun = 0;
    }
    if (depth + prefixRun > kMaxExpressionDepth) {
      diags.error(diag::code::ExpressionTooDeep, raw.rangeAt(t->getStartIndex(), 1),
                  fmt::format("expression nested deeper than {} levels (brackets, signs, "
                              "functions)",
                              kMaxExpressionDepth));
      return false;
    }
  }
  return true;
}

} // namespace

struct GrammarParser::Impl : front::AntlrBlockParser<nctgen::NCTLexer, nctgen::NCTParser> {
  Cancel cancel;

  void report(const front::RawBlock& raw, diag::Engine& diags);
};

GrammarParser::GrammarParser() = default;
GrammarParser::~GrammarParser() = default;

void GrammarParser::Impl::report(const front::RawBlock& raw, diag::Engine& diags) {
  const std::string& s = raw.lexText;
  if (first.lexer) {
    diags.error(diag::code::SyntaxError, raw.rangeAt(first.pos, 1),
                fmt::format("unexpected character '{}'", raw.text.substr(first.pos, 1)));
    return;
  }
  // Explain the common mistakes in the manual's terms before falling back to "unexpected".
  const std::vector<Token*> toks = visibleTokens();
  auto at = [&](Token* t) {
    return raw.rangeAt(t->getStartIndex(), t->getStopIndex() + 1 - t->getStartIndex());
  };
  for (std::size_t k = 0; k < toks.size(); ++k) {
    if (toks[k]->getType() == P::WHILE) {
      bool hasDo = false, hasAssign = false;
      for (std::size_t m = k; m < toks.size(); ++m) {
        hasDo |= toks[m]->getType() == P::DO;
        if (toks[m]->getType() == P::ASSIGN && !hasAssign) {
          hasAssign = true;
          diags.error(diag::code::RightBracketNotFound, at(toks[m]),
                      "wrong terminator '=' after WHILE[...] (expected DOm)");
          return;
        }
      }
      if (!hasDo) {
        diags.error(diag::code::WhileWithoutDo, at(toks[k]), "WHILE without DO in the same block");
        return;
      }
    }
  }
  // `/#1`: the skip level must be a literal (macro B2)
  if (toks.size() >= 2 && toks[0]->getType() == P::SLASH && toks[1]->getType() == P::HASH) {
    diags.error(diag::code::VariableNotAllowed, at(toks[0]),
                "a block skip level must be a literal number, not a variable");
    return;
  }
  Token* off = first.token;
  for (std::size_t k = 1; off && k < toks.size(); ++k) {
    if (toks[k] != off || toks[k - 1]->getType() != P::HASH) continue;
    if (off->getType() == P::HASH) // `##120`
      diags.error(diag::code::SyntaxError, at(off),
                  "'##' is not allowed: write #[#n] for indirection");
    else
      diags.error(diag::code::SyntaxError, at(toks[k - 1]),
                  "'#' must be followed by a variable number, '[expression]' or '_NAME'");
    return;
  }
  if (!off || off->getType() == Token::EOF) {
    // the block ended too early: name what is missing
    if (!toks.empty() && toks.size() >= 2) {
      Token* last = toks[toks.size() - 2]; // before EOF
      const auto type = last->getType();
      if (type >= P::A && type <= P::Z) {
        diags.error(diag::code::MissingData, at(last),
                    fmt::format("address '{}' has no value", last->getText()));
        return;
      }
    }
    const std::size_t end = s.empty() ? 0 : s.size() - 1;
    diags.error(diag::code::SyntaxError, raw.rangeAt(end, 1), "unexpected end of block");
    return;
  }
  // an address directly followed by another address: the first one has no value
  for (std::size_t k = 1; k < toks.size(); ++k) {
    if (toks[k] != off) continue;
    const auto prev = toks[k - 1]->getType();
    if (prev >= P::A && prev <= P::Z && off->getType() >= P::A && off->getType() <= P::Z) {
      Token* from = k >= 2 && toks[k - 2]->getType() == P::COMMA ? toks[k - 2] : toks[k - 1];
      const std::size_t len = toks[k - 1]->getStopIndex() + 1 - from->getStartIndex();
      diags.error(
          diag::code::MissingData, raw.rangeAt(from->getStartIndex(), len),
          fmt::format("address '{}' has no value", raw.lexText.substr(from->getStartIndex(), len)));
      return;
    }
  }
  diags.error(diag::code::SyntaxError, at(off),
              fmt::format("unexpected '{}'",
                          raw.text.substr(off->getStartIndex(),
                                          off->getStopIndex() + 1 - off->getStartIndex())));
}

bool GrammarParser::parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  if (!checkBrackets(raw, diags)) return false;
  // Made on the first block that needs the grammar: plain CAM output never pays for the ATNs.
  if (!impl_) impl_ = std::make_unique<Impl>();
  Impl& m = *impl_;
  m.reset(raw.lexText);

  // 1st attempt: SLL prediction, bail at the first error (the fast, common case).
  m.parser.removeErrorListeners();
  m.cancel.hit = false;
  m.parser.addErrorListener(&m.cancel);
  m.parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(
      antlr4::atn::PredictionMode::SLL);
  m.parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
  m.tokens.fill(); // the lexer does not recurse; the depth is checked before the parser does
  // A lexer error is reported without parsing: the parser would recurse through tokens the
  // depth check has not seen.
  if (m.first.set) {
    m.report(raw, diags);
    return false;
  }
  if (!checkNestingDepth(raw, m.tokens.getTokens(), diags)) return false;
  P::BlockContext* tree = nullptr;
  try {
    tree = m.parser.block();
  } catch (const antlr4::ParseCancellationException&) {
    tree = nullptr;
  }
  if (!tree || m.cancel.hit) {
    // 2nd attempt: full LL with error reporting, for a correct verdict and a located error.
    m.reset(raw.lexText);
    m.parser.removeErrorListeners();
    m.parser.addErrorListener(&m.collector);
    m.parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(
        antlr4::atn::PredictionMode::LL);
    m.parser.setErrorHandler(std::make_shared<antlr4::DefaultErrorStrategy>());
    tree = m.parser.block();
    if (m.first.set) {
      m.report(raw, diags);
      return false;
    }
  }

  BlockBuilder b(raw, out, diags);
  // comments live on the hidden channel; collect them in source order
  for (Token* t : m.tokens.getTokens())
    if (t->getType() == P::COMMENT)
      b.comment(t->getStartIndex(), t->getStopIndex() + 1 - t->getStartIndex());
  TreeToIr(b).block(tree);
  return b.ok();
}

} // namespace gcx::nct
