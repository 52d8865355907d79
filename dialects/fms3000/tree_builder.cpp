#include "dialects/fms3000/tree_builder.h"

#include <charconv>
#include <fmt/format.h>

#include "FMS3000Lexer.h"
#include "FMS3000Parser.h"
#include "antlr4-runtime.h"
#include "diag/codes.h"
#include "front/antlr_block_parser.h"
#include "front/decimal_text.h"

namespace gcx::fms3000 {

using P = fmsgen::FMS3000Parser;
using antlr4::Token;

namespace {

double numberOf(const std::string& digits) {
  return front::decimalValue(digits);
}

bool isAddressToken(std::size_t type) {
  return (type >= P::LIMS && type <= P::Z);
}

} // namespace

struct GrammarParser::Impl : front::AntlrBlockParser<fmsgen::FMS3000Lexer, P> {
  void report(const front::RawBlock& raw, diag::Engine& diags);
};

GrammarParser::GrammarParser() = default;
GrammarParser::~GrammarParser() = default;

void GrammarParser::Impl::report(const front::RawBlock& raw, diag::Engine& diags) {
  if (first.lexer) {
    diags.error(diag::code::SyntaxError, raw.rangeAt(first.pos, 1),
                fmt::format("unexpected character '{}'", raw.text.substr(first.pos, 1)));
    return;
  }
  const std::vector<Token*> toks = visibleTokens();
  auto at = [&](Token* t) {
    const std::size_t len =
        t->getType() == Token::EOF ? 1 : t->getStopIndex() + 1 - t->getStartIndex();
    return raw.rangeAt(t->getType() == Token::EOF ? raw.text.size() : t->getStartIndex(), len);
  };
  Token* off = first.token;
  for (std::size_t k = 1; off && k < toks.size(); ++k) {
    if (toks[k] != off) continue;
    Token* prev = toks[k - 1];
    if (isAddressToken(prev->getType()) && prev->getType() != P::N) {
      diags.error(diag::code::MissingData, at(prev),
                  fmt::format("address '{}' has no value", prev->getText()));
      return;
    }
    if (prev->getType() == P::PLUS || prev->getType() == P::MINUS) {
      diags.error(diag::code::MissingData, at(prev),
                  fmt::format("sign '{}' without a number", prev->getText()));
      return;
    }
  }
  if (off && off->getType() == P::N) {
    diags.error(diag::code::SyntaxError, at(off),
                "N (the block number) may only begin the block (fms3000.md §6.3)");
    return;
  }
  if (off && off->getType() == P::NUMBER && off->getText().front() == '.') {
    for (std::size_t k = 1; k < toks.size(); ++k)
      if (toks[k] == off && toks[k - 1]->getType() == P::NUMBER &&
          toks[k - 1]->getStopIndex() + 1 == off->getStartIndex()) {
        diags.error(diag::code::SyntaxError, at(toks[k - 1]),
                    fmt::format("number '{}{}' has two decimal points", toks[k - 1]->getText(),
                                off->getText()));
        return;
      }
  }
  if (off && off->getType() == P::NUMBER) {
    diags.error(diag::code::SyntaxError, at(off),
                fmt::format("number '{}' without an address (a blank inside a number is not "
                            "allowed, fms3000.md §1.1)",
                            off->getText()));
    return;
  }
  if (!off || off->getType() == Token::EOF) {
    diags.error(diag::code::SyntaxError, raw.rangeAt(raw.text.empty() ? 0 : raw.text.size() - 1, 1),
                "unexpected end of block");
    return;
  }
  diags.error(diag::code::SyntaxError, at(off), fmt::format("unexpected '{}'", off->getText()));
}

bool GrammarParser::parse(const front::RawBlock& raw, ir::Block& out, diag::Engine& diags) {
  // Made on the first block that needs the grammar: plain CAM output never pays for the ATNs.
  if (!impl_) impl_ = std::make_unique<Impl>();
  Impl& m = *impl_;
  m.reset(raw.lexText);
  m.tokens.fill();
  if (m.first.set) {
    m.report(raw, diags);
    return false;
  }
  P::BlockContext* tree = m.parser.block();
  if (m.first.set) {
    m.report(raw, diags);
    return false;
  }
  if (auto* n = tree->sequenceNumber()) {
    const std::size_t pos = n->getStart()->getStartIndex();
    const std::string digits = n->NUMBER() ? n->NUMBER()->getText() : "";
    out.sequenceText = digits;
    out.sequenceRange = raw.rangeAt(pos, 1 + digits.size());
    if (!digits.empty()) {
      if (digits.find('.') != std::string::npos || digits.size() > 7) {
        diags.error(diag::code::DataOutOfRange, out.sequenceRange,
                    fmt::format("block number 'N{}' must be a whole number of at most 7 digits "
                                "(001:344-356)",
                                digits));
        return false;
      }
      out.sequence = static_cast<std::int64_t>(numberOf(digits));
    }
  }
  for (P::WordContext* w : tree->word()) {
    const std::size_t pos = w->getStart()->getStartIndex();
    const std::size_t end = w->getStop()->getStopIndex() + 1;
    ir::Word& word = out.words.emplace_back();
    word.address = w->address()->getText();
    word.range = raw.rangeAt(pos, end - pos);
    word.order = static_cast<std::uint32_t>(pos);
    word.kind = ir::ValueKind::Number;
    const std::string digits = w->NUMBER()->getText();
    const bool negative = w->sign() && w->sign()->MINUS();
    if (w->sign()) word.text = w->sign()->getText();
    word.text += digits;
    const double v = numberOf(digits);
    word.number = negative ? -v : v;
  }
  return true;
}

} // namespace gcx::fms3000
