#include "scene/value_reader.h"

#include <cctype>
#include <cmath>

#include "core/text.h"
#include "scene/number_text.h"

namespace prt {
namespace {

std::string lowerCase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool namesNonFinite(const Token& token) {
  if (token.kind != TokenKind::Word) return false;
  const std::string word = lowerCase(token.text);
  return word == "nan" || word == "inf" || word == "infinity";
}

// `what` names the value being read, e.g. "'radius'" or "'center' (y)".
double parseDoubleToken(const TokenStream& in, const Token& token, const std::string& what) {
  if (namesNonFinite(token)) {
    in.fail(token, what + " must be a finite number, found " + describe(token));
  }
  if (token.kind != TokenKind::Number) {
    in.fail(token, what + " needs a number, found " + describe(token));
  }
  const ParsedNumber<double> parsed = parseDouble(token.text);
  switch (parsed.status) {
    case NumberStatus::Ok:
      return parsed.value;
    case NumberStatus::NotFinite:
      in.fail(token, what + " must be a finite number, found " + describe(token));
    case NumberStatus::OutOfRange:
      in.fail(token, "number " + describe(token) +
                         " is beyond double precision (magnitudes from about 4.9e-324 to "
                         "1.8e308, or 0)");
    case NumberStatus::Malformed:
      break;
  }
  std::string message = "malformed number " + describe(token) + " for " + what;
  if (token.text.find(',') != std::string::npos) {
    message += "; separate numbers with spaces, not commas";
  }
  in.fail(token, message);
}

void checkRange(const TokenStream& in, const Token& token, const std::string& what, double value,
                const Range& range) {
  if (!range.contains(value)) {
    in.fail(token, what + " must be " + range.describe() + ", found " + formatDouble(value));
  }
}

}  // namespace

bool Range::contains(double value) const {
  const bool aboveMin = minOpen ? value > min : value >= min;
  const bool belowMax = maxOpen ? value < max : value <= max;
  return aboveMin && belowMax;
}

std::string Range::describe() const {
  const bool hasMin = std::isfinite(min);
  const bool hasMax = std::isfinite(max);
  if (hasMin && hasMax) {
    return std::string("in ") + (minOpen ? "(" : "[") + formatDouble(min) + ", " +
           formatDouble(max) + (maxOpen ? ")" : "]");
  }
  if (hasMin) return (minOpen ? "> " : ">= ") + formatDouble(min);
  if (hasMax) return (maxOpen ? "< " : "<= ") + formatDouble(max);
  return {};
}

double readNumber(TokenStream& in, std::string_view param, Range range) {
  const std::string what = quote(param, '\'');
  const Token& token = in.next();
  const double value = parseDoubleToken(in, token, what);
  checkRange(in, token, what, value, range);
  return value;
}

int readInteger(TokenStream& in, std::string_view param, int min, int max) {
  const std::string what = quote(param, '\'');
  const std::string allowed =
      "a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const Token& token = in.next();
  if (token.kind != TokenKind::Number) {
    in.fail(token, what + " needs " + allowed + ", found " + describe(token));
  }
  const ParsedNumber<int64_t> parsed = parseInteger(token.text);
  if (parsed.status == NumberStatus::Malformed) {
    // Distinguish "3.5" (a number, but not whole) from "3..5" (not a number at all).
    parseDoubleToken(in, token, what);
    in.fail(token, what + " must be " + allowed + ", found " + describe(token));
  }
  if (parsed.status != NumberStatus::Ok || parsed.value < min || parsed.value > max) {
    in.fail(token, what + " must be " + allowed + ", found " + describe(token));
  }
  return static_cast<int>(parsed.value);
}

namespace {

Vec3 readTriple(TokenStream& in, std::string_view param, const Range& componentRange,
                const char* const (&axes)[3]) {
  const std::string what = quote(param, '\'');
  Vec3 value;
  for (int i = 0; i < 3; ++i) {
    const Token& token = in.next();
    if (token.kind != TokenKind::Number && !namesNonFinite(token)) {
      const std::string count = i == 0 ? "" : " after " + std::to_string(i);
      in.fail(token, what + " needs 3 numbers (" + axes[0] + " " + axes[1] + " " + axes[2] +
                         "), found " + describe(token) + count);
    }
    const std::string component = what + " (" + axes[i] + ")";
    value[i] = parseDoubleToken(in, token, component);
    checkRange(in, token, component, value[i], componentRange);
  }
  return value;
}

constexpr const char* kSpaceAxes[] = {"x", "y", "z"};
constexpr const char* kColorAxes[] = {"r", "g", "b"};

}  // namespace

Vec3 readVector(TokenStream& in, std::string_view param, Range componentRange) {
  return readTriple(in, param, componentRange, kSpaceAxes);
}

Vec3 readColor(TokenStream& in, std::string_view param) {
  return readTriple(in, param, Range::closed(0, kMaxColorComponent), kColorAxes);
}

std::string readString(TokenStream& in, std::string_view param) {
  const Token& token = in.next();
  if (token.kind != TokenKind::String) {
    in.fail(token, quote(param, '\'') + " needs a quoted string such as \"out.png\", found " +
                       describe(token));
  }
  return token.text;
}

}  // namespace prt
