#include "scene/lexer.h"

#include <cstdio>

namespace prt {
namespace {

bool isDelimiter(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' || c == '{' ||
         c == '}' || c == '"' || c == '#';
}
bool isLetter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isControl(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7f;
}

std::string hexByte(char c) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "0x%02X",
                static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buffer;
}

class Lexer {
 public:
  explicit Lexer(const SourceText& source) : source_(source), text_(source.text()) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    int endLine = 1;
    int endColumn = 1;
    while (skipSpaceAndComments()) {
      tokens.push_back(next());
      endLine = line_;
      endColumn = column();
    }
    tokens.push_back(Token{TokenKind::End, {}, endLine, endColumn});
    return tokens;
  }

 private:
  int column() const { return static_cast<int>(pos_ - lineStart_) + 1; }

  void advance() {
    if (endsLine(text_, pos_)) {
      ++line_;
      lineStart_ = pos_ + 1;
    }
    ++pos_;
  }

  // Returns false at the end of the text.
  bool skipSpaceAndComments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') advance();
      } else if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        advance();
      } else {
        return true;
      }
    }
    return false;
  }

  Token next() {
    Token token{TokenKind::End, {}, line_, column()};
    const char c = text_[pos_];
    if (c == '{' || c == '}') {
      token.kind = c == '{' ? TokenKind::LeftBrace : TokenKind::RightBrace;
      token.text = std::string(1, c);
      advance();
    } else if (c == '"') {
      readString(token);
    } else if (isLetter(c) || isDigit(c) || c == '+' || c == '-' || c == '.') {
      readBare(token);
    } else if (isControl(c)) {
      fail(token, "unexpected control character " + hexByte(c) + "; is this a text file?");
    } else if (static_cast<unsigned char>(c) >= 0x80) {
      fail(token,
           "unexpected non-ASCII character; outside comments and quoted strings a "
           "scene uses only ASCII names, numbers and braces");
    } else {
      fail(token, std::string("unexpected character '") + c +
                      "'; expected a name, a number, a quoted string, '{' or '}'");
    }
    return token;
  }

  void readBare(Token& token) {
    const size_t begin = pos_;
    while (pos_ < text_.size() && !isDelimiter(text_[pos_])) advance();
    token.text = std::string(text_.substr(begin, pos_ - begin));
    token.kind = isLetter(token.text[0]) ? TokenKind::Word : TokenKind::Number;
  }

  void readString(Token& token) {
    token.kind = TokenKind::String;
    advance();  // opening quote
    while (true) {
      if (pos_ >= text_.size() || text_[pos_] == '\n' || text_[pos_] == '\r') {
        fail(token, "unterminated string: the closing '\"' is missing on this line");
      }
      const char c = text_[pos_];
      if (c == '"') {
        advance();
        return;
      }
      if (c == '\\') {
        const Token escape{TokenKind::String, {}, line_, column()};
        advance();
        const char escaped = pos_ < text_.size() ? text_[pos_] : '\0';
        if (escaped != '"' && escaped != '\\') {
          fail(escape, "unknown escape in string; only \\\" and \\\\ are allowed");
        }
        token.text += escaped;
        advance();
        continue;
      }
      if (isControl(c) && c != '\t') {
        fail(Token{TokenKind::String, {}, line_, column()},
             "control character " + hexByte(c) + " inside a string");
      }
      token.text += c;
      advance();
    }
  }

  [[noreturn]] void fail(const Token& at, const std::string& message) const {
    source_.fail(at.line, at.column, message);
  }

  const SourceText& source_;
  std::string_view text_;
  size_t pos_ = 0;
  size_t lineStart_ = 0;
  int line_ = 1;
};

}  // namespace

std::string describe(const Token& token) {
  // A token of thousands of characters (a run-away name, a generated line) is shown cut.
  constexpr size_t kShown = 60;
  std::string text = token.text;
  if (text.size() > kShown) {
    size_t cut = kShown;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text = text.substr(0, cut) + "... (" + std::to_string(token.text.size()) + " characters)";
  }
  switch (token.kind) {
    case TokenKind::String:
      return "the string \"" + text + "\"";
    case TokenKind::End:
      return "the end of the file";
    default:
      return "'" + text + "'";
  }
}

std::string lineAndColumn(const Token& token) {
  return "line " + std::to_string(token.line) + ", column " + std::to_string(token.column);
}

std::vector<Token> tokenize(const SourceText& source) {
  return Lexer(source).run();
}

}  // namespace prt
