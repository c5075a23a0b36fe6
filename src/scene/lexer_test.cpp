#include "scene/lexer.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

std::vector<Token> lex(std::string_view text) {
  const SourceText source(text, "test.scene");
  return tokenize(source);
}

InputError lexError(std::string_view text) {
  try {
    lex(text);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for: " << text;
  return InputError("none");
}

TEST(Lexer, SplitsWordsNumbersStringsAndBracesWithPositions) {
  const auto tokens = lex("sphere {\n  radius -1.5e3 \"a b.png\"}");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[0].kind, TokenKind::Word);
  EXPECT_EQ(tokens[0].text, "sphere");
  EXPECT_EQ(tokens[1].kind, TokenKind::LeftBrace);
  EXPECT_EQ(tokens[1].column, 8);
  EXPECT_EQ(tokens[2].text, "radius");
  EXPECT_EQ(tokens[2].line, 2);
  EXPECT_EQ(tokens[2].column, 3);
  EXPECT_EQ(tokens[3].kind, TokenKind::Number);
  EXPECT_EQ(tokens[3].text, "-1.5e3");
  EXPECT_EQ(tokens[4].kind, TokenKind::String);
  EXPECT_EQ(tokens[4].text, "a b.png");
  EXPECT_EQ(tokens[4].column, 17);
  EXPECT_EQ(tokens[5].kind, TokenKind::RightBrace);
  EXPECT_EQ(tokens[5].column, 26);
  EXPECT_EQ(tokens[6].kind, TokenKind::End);
}

TEST(Lexer, SkipsCommentsAndAllWhiteSpace) {
  const auto tokens = lex("# heading { \"not a string\n\tbox\r\n{ # trailing }\n}  # end");
  ASSERT_EQ(tokens.size(), 4u);
  EXPECT_EQ(tokens[0].text, "box");
  EXPECT_EQ(tokens[0].line, 2);
  EXPECT_EQ(tokens[0].column, 2);
  EXPECT_EQ(tokens[1].kind, TokenKind::LeftBrace);
  EXPECT_EQ(tokens[1].line, 3);
  EXPECT_EQ(tokens[2].kind, TokenKind::RightBrace);
  EXPECT_EQ(tokens[2].line, 4);
}

TEST(Lexer, EndTokenSitsJustAfterTheLastToken) {
  const auto tokens = lex("camera {\n  eye 1   \n\n# only a comment\n");
  EXPECT_EQ(tokens.back().kind, TokenKind::End);
  EXPECT_EQ(tokens.back().line, 2);
  EXPECT_EQ(tokens.back().column, 8);
  const auto empty = lex("");
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty[0].line, 1);
  EXPECT_EQ(empty[0].column, 1);
}

TEST(Lexer, BracesNeedNoSpaceAround) {
  const auto tokens = lex("image{width 2}");
  ASSERT_EQ(tokens.size(), 6u);
  EXPECT_EQ(tokens[0].text, "image");
  EXPECT_EQ(tokens[3].text, "2");
  EXPECT_EQ(tokens[4].kind, TokenKind::RightBrace);
}

TEST(Lexer, ResolvesStringEscapes) {
  const auto tokens = lex(R"("a\"b\\c")");
  EXPECT_EQ(tokens[0].text, "a\"b\\c");
}

TEST(Lexer, RejectsUnexpectedCharacter) {
  const InputError error = lexError("box {\n  min = 1 }");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 7);
  EXPECT_EQ(error.where().lineText, "  min = 1 }");
  EXPECT_NE(std::string(error.what()).find("unexpected character '='"), std::string::npos);
}

TEST(Lexer, RejectsNonAsciiOutsideStringsAndComments) {
  const InputError error = lexError("# caf\xC3\xA9 is fine here\nbox \xC3\xA9");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 5);
  EXPECT_NE(std::string(error.what()).find("non-ASCII"), std::string::npos);
}

TEST(Lexer, RejectsUnterminatedStringAtItsOpeningQuote) {
  const InputError error = lexError("image {\n  output \"fig.png\n}");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 10);
  EXPECT_NE(std::string(error.what()).find("unterminated string"), std::string::npos);
  EXPECT_EQ(lexError("output \"abc").where().column, 8);
}

TEST(Lexer, RejectsUnknownEscape) {
  const InputError error = lexError(R"(output "C:\out.png")");
  EXPECT_EQ(error.where().column, 11);
  EXPECT_NE(std::string(error.what()).find("unknown escape"), std::string::npos);
}

TEST(Lexer, BareTextRunsToTheNextDelimiter) {
  const auto tokens = lex("frosted-glass fig.png 1,2{3.5.6}");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[0].kind, TokenKind::Word);
  EXPECT_EQ(tokens[0].text, "frosted-glass");
  EXPECT_EQ(tokens[1].kind, TokenKind::Word);
  EXPECT_EQ(tokens[1].text, "fig.png");
  EXPECT_EQ(tokens[2].kind, TokenKind::Number);
  EXPECT_EQ(tokens[2].text, "1,2");
  EXPECT_EQ(tokens[4].text, "3.5.6");
}

TEST(Lexer, RejectsControlCharacters) {
  const InputError error = lexError("box \x01");
  EXPECT_EQ(error.where().column, 5);
  EXPECT_NE(std::string(error.what()).find("control character 0x01"), std::string::npos);
}

TEST(Lexer, ErrorLineTextHasNoCarriageReturn) {
  const InputError error = lexError("box {}\r\nbox = \r\n");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().lineText, "box = ");
}

TEST(Lexer, CarriageReturnAloneEndsALineAndAComment) {
  // Old Mac OS files end lines with '\r' alone; mixed with the other two, each is one line end.
  const std::vector<Token> tokens = lex("box # comment\r{\r\n} \n\r  sphere");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[1].text, "{");
  EXPECT_EQ(tokens[1].line, 2);
  EXPECT_EQ(tokens[2].line, 3);
  EXPECT_EQ(tokens[3].text, "sphere");
  EXPECT_EQ(tokens[3].line, 5);
  EXPECT_EQ(tokens[3].column, 3);
  const InputError error = lexError("box {}\rbox {}\rbox = \r");
  EXPECT_EQ(error.where().line, 3);
  EXPECT_EQ(error.where().column, 5);
  EXPECT_EQ(error.where().lineText, "box = ");
}

}  // namespace
}  // namespace prt
