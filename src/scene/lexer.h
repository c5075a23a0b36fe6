#pragma once
// The lexer of the .scene format: splits the text into words, numbers, quoted strings and
// braces, each tagged with its line and column. '#' starts a comment to the end of the line.
//
// A word or number is a maximal run of characters other than white space, braces, '"' and
// '#'. Its content is checked only by the parser, which knows what it expects there: so
// "3.5" is reported as "not a whole number" for an image width, and an unquoted fig.png as
// "needs a quoted string" for an output, rather than as generic lexical errors.

#include <string>
#include <vector>

#include "scene/source_text.h"

namespace prt {

enum class TokenKind {
  Word,        // text starting with a letter or '_': a name, or a misspelt something
  Number,      // text starting with a digit, '+', '-' or '.'; validated by the parser
  String,      // "quoted"; `text` holds the content with escapes resolved
  LeftBrace,   // {
  RightBrace,  // }
  End,         // end of the text, placed just after the last token
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string text;  // as written (strings: the decoded content)
  int line = 1;      // 1-based
  int column = 1;    // 1-based, in bytes
};

// How a token reads in an error message: 'radius', '1.5', "out.png", '{', end of file.
std::string describe(const Token& token);

// Where a token is, for messages that point elsewhere: "line 3, column 7".
std::string lineAndColumn(const Token& token);

// The whole text as tokens, always ending with one End token. Throws InputError at the
// culprit for an unexpected character or a bad string.
std::vector<Token> tokenize(const SourceText& source);

}  // namespace prt
