#pragma once
// TokenStream: the tokens of one scene text, read front to back by the parser, with helpers
// to report an error at any token.

#include <string>
#include <string_view>
#include <vector>

#include "scene/lexer.h"
#include "scene/source_text.h"

namespace prt {

class TokenStream {
 public:
  explicit TokenStream(const SourceText& source) : source_(source), tokens_(tokenize(source)) {}

  const SourceText& source() const { return source_; }

  // The next token without consuming it; at the end this is the End token, repeatedly.
  const Token& peek() const { return tokens_[index_]; }
  const Token& next() {
    const Token& token = tokens_[index_];
    if (token.kind != TokenKind::End) ++index_;
    return token;
  }
  bool atEnd() const { return peek().kind == TokenKind::End; }

  // Tokens stay put while parsing, so callers may keep references and index arithmetic on
  // them (the y component of a vector is the token after its x).
  size_t position() const { return index_; }
  const Token& at(size_t index) const { return tokens_[index]; }

  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    source_.fail(at.line, at.column, message);
  }

 private:
  const SourceText& source_;
  std::vector<Token> tokens_;
  size_t index_ = 0;
};

}  // namespace prt
