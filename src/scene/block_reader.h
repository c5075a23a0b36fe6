#pragma once
// BlockReader: the mechanics shared by every block, "{ name value name value ... }". It checks
// that each name is one the block accepts and is not repeated (but for `key`, the keyframes
// of an animated block, which come one after another), and remembers where each was
// given; reading the values is the caller's job, as only it knows their types:
//
//   BlockReader block(in, keyword, "sphere", {"center", "radius", "surface"});
//   while (const Token* param = block.next()) {
//     if (param->text == "center") ... readVector(in, "center") ...
//   }
//   block.require({"center", "radius"});

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "scene/token_stream.h"

namespace prt {

class BlockReader {
 public:
  // Consumes the '{'. `keyword` is where the block starts (missing parameters are reported
  // there); `title` names the block in messages, e.g. "sphere" or "light rect". The names in
  // `params` must outlive the reader (string literals do).
  BlockReader(TokenStream& in, const Token& keyword, std::string title,
              std::initializer_list<std::string_view> params);

  // The name token of the next parameter, whose value the caller must then read; nullptr once
  // the closing '}' has been consumed.
  const Token* next();

  bool has(std::string_view param) const;
  // The stream index of the first token of `param`'s value (which must have been given).
  size_t valueIndex(std::string_view param) const;
  // The token of component `axis` of a vector-valued parameter, for pointing at it.
  const Token& valueToken(std::string_view param, int axis = 0) const;

  // Throws at the block's keyword naming the first of `params` that was not given.
  void require(std::initializer_list<std::string_view> params) const;

  const Token& keyword() const { return keyword_; }

 private:
  struct Given {
    std::string_view name;
    size_t nameIndex;  // stream index of the name token; its value follows it
  };

  TokenStream& in_;
  const Token& keyword_;
  const Token& open_;
  std::string title_;
  std::vector<std::string_view> params_;
  std::vector<Given> given_;
};

}  // namespace prt
