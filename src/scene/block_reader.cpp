#include "scene/block_reader.h"

#include <algorithm>

#include "scene/keywords.h"

namespace prt {

namespace {

const Token& expectOpen(TokenStream& in, const Token& keyword, const std::string& title) {
  const Token& open = in.next();
  if (open.kind != TokenKind::LeftBrace) {
    in.fail(open, "expected '{' to start the '" + title + "' block after " + describe(keyword) +
                      ", found " + describe(open));
  }
  return open;
}

}  // namespace

BlockReader::BlockReader(TokenStream& in, const Token& keyword, std::string title,
                         std::initializer_list<std::string_view> params)
    : in_(in),
      keyword_(keyword),
      open_(expectOpen(in, keyword, title)),
      title_(std::move(title)),
      params_(params) {}

const Token* BlockReader::next() {
  const size_t index = in_.position();
  const Token& token = in_.next();
  switch (token.kind) {
    case TokenKind::RightBrace:
      return nullptr;
    case TokenKind::Word:
      break;
    case TokenKind::End:
      in_.fail(token, "unexpected end of file: the '" + title_ + "' block opened at " +
                          lineAndColumn(open_) + " has no closing '}'");
    case TokenKind::Number: {
      const bool afterNumber = index > 0 && in_.at(index - 1).kind == TokenKind::Number;
      in_.fail(token, "expected a parameter name or '}' in the '" + title_ + "' block, found " +
                          describe(token) +
                          (afterNumber ? " (too many numbers for the previous parameter?)" : ""));
    }
    default:
      in_.fail(token, "expected a parameter name or '}' in the '" + title_ + "' block, found " +
                          describe(token));
  }

  const auto known = std::find(params_.begin(), params_.end(), token.text);
  if (known == params_.end()) {
    std::string message = "unknown parameter " + describe(token) + " in the '" + title_ + "' block" +
                          didYouMean(token.text, params_) +
                          "; valid parameters: " + joinNames(params_);
    if (isDirective(token.text)) {
      message += " (is the '}' of the block opened at " + lineAndColumn(open_) + " missing?)";
    }
    in_.fail(token, message);
  }
  for (const Given& given : given_) {
    if (given.name == *known && *known != "key") {  // keyframes come one after another
      in_.fail(token, "duplicate parameter '" + token.text + "' in the '" + title_ +
                          "' block; it was already given at " +
                          lineAndColumn(in_.at(given.nameIndex)));
    }
  }
  given_.push_back(Given{*known, index});
  return &token;
}

bool BlockReader::has(std::string_view param) const {
  return std::any_of(given_.begin(), given_.end(),
                     [&](const Given& given) { return given.name == param; });
}

size_t BlockReader::valueIndex(std::string_view param) const {
  for (const Given& given : given_) {
    if (given.name == param) return given.nameIndex + 1;
  }
  return 0;  // not given: callers check has() first; the first token is a safe answer
}

const Token& BlockReader::valueToken(std::string_view param, int axis) const {
  return in_.at(valueIndex(param) + static_cast<size_t>(axis));
}

void BlockReader::require(std::initializer_list<std::string_view> params) const {
  for (const std::string_view param : params) {
    if (!has(param)) {
      in_.fail(keyword_, "the '" + title_ + "' block is missing '" + std::string(param) +
                             "' (required: " + joinNames(params) + ")");
    }
  }
}

}  // namespace prt
