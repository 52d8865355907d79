#include "ir/dump.h"

namespace gcx::ir {

namespace {

const char* kindName(ExprKind k) {
  static const char* const names[] = {"number", "variable", "indirect", "named", "bracket", "unary",
                                      "binary", "call",     "axnum",    "prm",   "assign"};
  return names[static_cast<int>(k)];
}

const char* stmtName(StmtKind k) {
  static const char* const names[] = {"assign", "goto",  "if-goto", "if-then",   "while", "do",
                                      "end",    "print", "popen",   "pclos",     "fopen", "fclos",
                                      "guard",  "jump",  "call",    "cycle-call"};
  return names[static_cast<int>(k)];
}

void location(nlohmann::json& j, const SourceRange& r, bool with) {
  if (!with || !r.begin.valid()) return;
  j["at"] = {r.begin.line, r.begin.col};
}

const char* blockKindName(BlockKind k) {
  static const char* const names[] = {"normal",      "program-start", "data",
                                      "program-end", "comment-line",  "contour-end"};
  return names[static_cast<int>(k)];
}

// The located form also shows how a literal was written (`text`): the spelling carries meaning
// in some dialects (FMS P07 is not P7), while the structural identity compares values only.
nlohmann::json wordJson(const Word& w, bool with) {
  nlohmann::json wj;
  wj["address"] = w.address;
  if (w.incremental) wj["incremental"] = true;
  switch (w.kind) {
  case ValueKind::Number:
    wj["value"] = w.number;
    if (with && !w.text.empty()) wj["text"] = w.text;
    break;
  case ValueKind::Expression:
    wj["expr"] = toJson(w.expr, with);
    break;
  case ValueKind::Path:
    wj["path"] = w.text;
    break;
  }
  if (!w.axisIndex.empty()) wj["axis"] = toJson(w.axisIndex.front(), with);
  location(wj, w.range, with);
  return wj;
}

nlohmann::json stmtJson(const Stmt& s, bool with) {
  nlohmann::json sj;
  sj["kind"] = stmtName(s.kind);
  if (s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen)
    sj["target"] = toJson(s.target, with);
  if (s.kind == StmtKind::Assign || s.kind == StmtKind::IfThen || s.kind == StmtKind::Goto ||
      s.kind == StmtKind::IfGoto || s.kind == StmtKind::Guard || s.kind == StmtKind::Jump ||
      s.kind == StmtKind::Call)
    sj["value"] = toJson(s.value, with);
  if (s.cond) {
    sj["cond"] = {{"lhs", toJson(s.cond->lhs, with)},
                  {"op", spelling(s.cond->op)},
                  {"rhs", toJson(s.cond->rhs, with)}};
  }
  if (s.kind == StmtKind::While || s.kind == StmtKind::Do || s.kind == StmtKind::End)
    sj["loop"] = s.loopId;
  if (s.kind == StmtKind::Print) {
    sj["binary"] = s.binaryPrint;
    auto& items = sj["items"] = nlohmann::json::array();
    for (const PrintItem& it : s.items) {
      if (it.isVariable)
        items.push_back({{"var", it.variable}, {"int", it.intDigits}, {"frac", it.fracDigits}});
      else
        items.push_back({{"text", it.text}});
    }
  }
  if (s.device) sj["device"] = *s.device;
  if (s.program) sj["program"] = *s.program;
  if (!s.path.empty()) sj["path"] = s.path;
  if (!s.message.empty()) sj["message"] = s.message;
  if (s.precision) sj["precision"] = *s.precision;
  if (!s.label.empty()) sj["label"] = s.label;
  if (!s.callee.empty()) sj["callee"] = s.callee;
  if (!s.args.empty()) {
    auto& as = sj["args"] = nlohmann::json::array();
    for (const Word& w : s.args)
      as.push_back(wordJson(w, with));
  }
  location(sj, s.range, with);
  return sj;
}

} // namespace

nlohmann::json toJson(const Expr& e, bool with) {
  nlohmann::json j;
  j["kind"] = kindName(e.kind);
  switch (e.kind) {
  case ExprKind::Number:
  case ExprKind::Variable:
    j["value"] = e.number;
    break;
  case ExprKind::Named:
  case ExprKind::AxisNumber:
    j["name"] = e.name;
    break;
  case ExprKind::Unary:
  case ExprKind::Binary:
    j["op"] = spelling(e.op);
    break;
  case ExprKind::Call:
    j["func"] = spelling(e.func);
    break;
  case ExprKind::Parameter:
    j["bit"] = e.prmHasBit;
    j["index"] = e.prmHasIndex;
    break;
  default:
    break;
  }
  if (!e.args.empty()) {
    auto& a = j["args"] = nlohmann::json::array();
    for (const Expr& x : e.args)
      a.push_back(toJson(x, with));
  }
  location(j, e.range, with);
  return j;
}

nlohmann::json toJson(const Block& b, bool with) {
  nlohmann::json j;
  if (b.kind != BlockKind::Normal) j["kind"] = blockKindName(b.kind);
  if (!b.programName.empty()) j["program"] = b.programName;
  if (b.skipLevel) j["skip"] = b.skipLevel;
  if (b.sequence) j["n"] = *b.sequence;
  if (with && !b.sequenceText.empty()) j["n_text"] = b.sequenceText;
  if (!b.words.empty()) {
    auto& ws = j["words"] = nlohmann::json::array();
    for (const Word& w : b.words)
      ws.push_back(wordJson(w, with));
  }
  // one statement (every NCT statement block) as "stmt", several as "stmts"
  if (b.stmts.size() == 1) j["stmt"] = stmtJson(b.stmts.front(), with);
  if (b.stmts.size() > 1) {
    auto& ss = j["stmts"] = nlohmann::json::array();
    for (const Stmt& s : b.stmts)
      ss.push_back(stmtJson(s, with));
  }
  if (!b.comments.empty()) {
    auto& cs = j["comments"] = nlohmann::json::array();
    for (const Comment& c : b.comments) {
      if (c.kind == CommentKind::Inline)
        cs.push_back(c.text);
      else
        cs.push_back({{c.kind == CommentKind::Message ? "message" : "to-line-end", c.text}});
    }
  }
  if (with && b.range.begin.valid()) {
    j["line"] = b.range.begin.line;
    if (b.lastLine != b.range.begin.line) j["last_line"] = b.lastLine;
  }
  return j;
}

} // namespace gcx::ir
