// The ANTLR plumbing every dialect's grammar path shares: one lexer and one parser reused for every
// block (a whole-file tree would cost gigabytes, DESIGN.md), their console listeners replaced by
// one that keeps the first syntax error and where it stands.
#pragma once
#include <string>
#include <vector>

#include "antlr4-runtime.h"

namespace gcx::front {

/// The first syntax error of a block: a token the parser refused, or a character the lexer could
/// not read (lexer = true, token = null).
struct FirstSyntaxError {
  bool set = false;
  bool lexer = false;
  std::size_t pos = 0;
  std::size_t len = 1;
  antlr4::Token* token = nullptr;
  std::size_t rule = 0; // the grammar rule the parser was in (a parser error only)
};

class FirstErrorListener : public antlr4::BaseErrorListener {
public:
  FirstErrorListener(FirstSyntaxError& err, antlr4::Lexer& lexer) : err_(err), lexer_(lexer) {}

  void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offending, std::size_t,
                   std::size_t, const std::string&, std::exception_ptr) override {
    if (err_.set) return;
    err_.set = true;
    if (auto* parser = dynamic_cast<antlr4::Parser*>(recognizer); parser && parser->getContext())
      err_.rule = parser->getContext()->getRuleIndex();
    if (offending) {
      err_.token = offending;
      err_.pos = offending->getStartIndex();
      err_.len = offending->getType() == antlr4::Token::EOF
                     ? 1
                     : offending->getStopIndex() - offending->getStartIndex() + 1;
    } else {
      err_.lexer = true;
      err_.pos = lexer_.tokenStartCharIndex;
    }
  }

private:
  FirstSyntaxError& err_;
  antlr4::Lexer& lexer_;
};

/// A generated lexer and parser wired for one block at a time: `reset` loads the next block's
/// text and forgets the last error; both report to `collector` until a caller says otherwise.
template <class Lexer, class Parser> struct AntlrBlockParser {
  antlr4::ANTLRInputStream input;
  Lexer lexer{&input};
  antlr4::CommonTokenStream tokens{&lexer};
  Parser parser{&tokens};
  FirstSyntaxError first;
  FirstErrorListener collector{first, lexer};

  AntlrBlockParser() {
    lexer.removeErrorListeners();
    parser.removeErrorListeners();
    lexer.addErrorListener(&collector);
    parser.addErrorListener(&collector);
  }
  AntlrBlockParser(const AntlrBlockParser&) = delete;
  AntlrBlockParser& operator=(const AntlrBlockParser&) = delete;

  void reset(const std::string& text) {
    first = FirstSyntaxError{};
    input.load(text);
    lexer.setInputStream(&input);
    tokens.setTokenSource(&lexer);
    parser.setTokenStream(&tokens);
  }

  /// The tokens the parser sees (hidden channels left out), EOF last; call after tokens.fill().
  std::vector<antlr4::Token*> visibleTokens() {
    std::vector<antlr4::Token*> out;
    for (antlr4::Token* t : tokens.getTokens())
      if (t->getChannel() == antlr4::Token::DEFAULT_CHANNEL) out.push_back(t);
    return out;
  }
};

} // namespace gcx::front
