// Builds IR by hand, as a front end would, for dialects whose front ends do not exist yet: each
// item gets the next place in the block's source order.
#pragma once
#include <optional>
#include <ostream>
#include <string>
#include <utility>

#include "ir/block.h"
#include "ir/items.h"

namespace gcx::ir {
/// Readable item lists in test failures.
inline void PrintTo(const ItemRef& r, std::ostream* os) {
  static const char* const kinds[] = {"word", "stmt", "comment"};
  *os << kinds[static_cast<int>(r.kind)] << '#' << r.index;
}
} // namespace gcx::ir

namespace gcx::test::hand {

inline ir::Expr num(double v) {
  return ir::Expr::literal(v);
}
inline ir::Expr var(double n) {
  return ir::Expr::variable(n);
}
inline ir::Expr node(ir::ExprKind kind, std::vector<ir::Expr> args) {
  ir::Expr e;
  e.kind = kind;
  e.args = std::move(args);
  return e;
}
/// `#(e)`
inline ir::Expr indirect(ir::Expr e) {
  return node(ir::ExprKind::Indirect, {std::move(e)});
}
/// `(e)`: WL4 parentheses, kept like NCT brackets
inline ir::Expr paren(ir::Expr e) {
  return node(ir::ExprKind::Bracket, {std::move(e)});
}
inline ir::Expr unary(ir::Op op, ir::Expr e) {
  ir::Expr u = node(ir::ExprKind::Unary, {std::move(e)});
  u.op = op;
  return u;
}
inline ir::Expr bin(ir::Op op, ir::Expr a, ir::Expr b) {
  ir::Expr e = node(ir::ExprKind::Binary, {std::move(a), std::move(b)});
  e.op = op;
  return e;
}
inline ir::Expr call(ir::Func f, ir::Expr a) {
  ir::Expr e = node(ir::ExprKind::Call, {std::move(a)});
  e.func = f;
  return e;
}
/// WL4 `ATAN(a)/(b)`
inline ir::Expr atan2(ir::Expr a, ir::Expr b) {
  ir::Expr e = node(ir::ExprKind::Call, {std::move(a), std::move(b)});
  e.func = ir::Func::Atan2;
  return e;
}
/// `#n=e` inside an expression
inline ir::Expr assign(ir::Expr target, ir::Expr value) {
  return node(ir::ExprKind::Assign, {std::move(target), std::move(value)});
}

/// A literal word as a front end reads it: the text as written, the value from it.
inline ir::Word word(std::string address, std::string text) {
  ir::Word w;
  w.address = std::move(address);
  w.number = std::stod(text); // strtod reads every FMS and WL4 literal: "-.5", "100.", "0703"
  w.text = std::move(text);
  return w;
}
inline ir::Word word(std::string address, ir::Expr e) {
  ir::Word w;
  w.address = std::move(address);
  w.kind = ir::ValueKind::Expression;
  w.expr = std::move(e);
  return w;
}

inline ir::Stmt stmt(ir::StmtKind kind) {
  ir::Stmt s;
  s.kind = kind;
  return s;
}
/// Statement `#n=e`
inline ir::Stmt assignment(ir::Expr target, ir::Expr value) {
  ir::Stmt s = stmt(ir::StmtKind::Assign);
  s.target = std::move(target);
  s.value = std::move(value);
  return s;
}

/// WL4 `IF<p> (cond)`: the items after it run only when cond holds
inline ir::Stmt guard(ir::Expr cond, std::optional<int> precision = {}) {
  ir::Stmt s = stmt(ir::StmtKind::Guard);
  s.value = std::move(cond);
  s.precision = precision;
  return s;
}
/// WL4 `N17` that is not first: continue at label 17 (`N017`) after the block
inline ir::Stmt jump(std::string label) {
  ir::Stmt s = stmt(ir::StmtKind::Jump);
  s.value = num(std::stod(label));
  s.label = std::move(label);
  return s;
}
/// WL4 `L0703`: program "07" three times after the block
inline ir::Stmt callUnit(std::string unit, double times) {
  ir::Stmt s = stmt(ir::StmtKind::Call);
  s.callee = std::move(unit);
  s.value = num(times);
  return s;
}

/// Appends items to a block in source order.
class Block {
public:
  explicit Block(ir::BlockKind kind = ir::BlockKind::Normal) { b_.kind = kind; }
  Block& skip() {
    b_.skipLevel = 1;
    return *this;
  }
  /// The first N, with its digits as written ("" for a bare N).
  Block& sequence(std::string digits) {
    if (!digits.empty()) b_.sequence = std::stoll(digits);
    b_.sequenceText = std::move(digits);
    return *this;
  }
  Block& add(ir::Word w) {
    w.order = next_++;
    b_.words.push_back(std::move(w));
    return *this;
  }
  Block& add(std::string address, std::string text) {
    return add(word(std::move(address), std::move(text)));
  }
  Block& add(ir::Stmt s) {
    s.order = next_++;
    b_.stmts.push_back(std::move(s));
    return *this;
  }
  Block& comment(ir::CommentKind kind, std::string text) {
    ir::Comment c;
    c.kind = kind;
    c.text = std::move(text);
    c.order = next_++;
    b_.comments.push_back(std::move(c));
    return *this;
  }
  Block& name(std::string programName) {
    b_.programName = std::move(programName);
    return *this;
  }
  ir::Block done() const { return b_; }

private:
  ir::Block b_;
  std::uint32_t next_ = 0;
};

} // namespace gcx::test::hand
