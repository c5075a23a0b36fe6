#include "report/ownership_map.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "report/html_text.h"

namespace prt {
namespace {

constexpr const char* kEncoding = "rle-leb128-base64";

void putVarint(std::string& out, uint64_t v) {
  while (v >= 0x80) {
    out += static_cast<char>(0x80 | (v & 0x7f));
    v >>= 7;
  }
  out += static_cast<char>(v);
}

std::string unbase64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  uint32_t buffer = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const int v = value(c);
    if (v < 0) throw std::invalid_argument("ownership map: bad base64");
    buffer = (buffer << 6) | static_cast<uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return out;
}

}  // namespace

nlohmann::json ownershipJson(const std::vector<int32_t>& owner, int width, int height,
                             int maxSide) {
  const int longest = std::max(width, height);
  const int step = std::max(1, (longest + maxSide - 1) / std::max(1, maxSide));
  const int w = (width + step - 1) / step;
  const int h = (height + step - 1) / step;
  std::string runs;
  int64_t current = -2;
  uint64_t length = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t source =
          static_cast<size_t>(y) * static_cast<size_t>(step) * static_cast<size_t>(width) +
          static_cast<size_t>(x) * static_cast<size_t>(step);
      const int64_t o = source < owner.size() ? std::max<int64_t>(-1, owner[source]) : -1;
      if (o == current) {
        ++length;
        continue;
      }
      if (length > 0) {
        putVarint(runs, static_cast<uint64_t>(current + 1));
        putVarint(runs, length);
      }
      current = o;
      length = 1;
    }
  }
  if (length > 0) {
    putVarint(runs, static_cast<uint64_t>(current + 1));
    putVarint(runs, length);
  }
  return {{"width", w},
          {"height", h},
          {"step", step},
          {"source_width", width},
          {"source_height", height},
          {"encoding", kEncoding},
          {"data", base64(runs)}};
}

std::vector<int32_t> decodeOwnership(const nlohmann::json& map) {
  if (!map.is_object() || map.value("encoding", "") != kEncoding || !map.contains("data") ||
      !map["data"].is_string()) {
    throw std::invalid_argument("ownership map: not a " + std::string(kEncoding) + " map");
  }
  const int64_t w = map.value("width", int64_t{0}), h = map.value("height", int64_t{0});
  if (w <= 0 || h <= 0 || w * h > (int64_t{1} << 28)) {
    throw std::invalid_argument("ownership map: bad size");
  }
  const std::string bytes = unbase64(map["data"].get<std::string>());
  std::vector<int32_t> out;
  out.reserve(static_cast<size_t>(w * h));
  size_t i = 0;
  auto varint = [&] {
    uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (i >= bytes.size()) throw std::invalid_argument("ownership map: truncated run");
      const auto b = static_cast<unsigned char>(bytes[i++]);
      v |= static_cast<uint64_t>(b & 0x7f) << shift;
      if ((b & 0x80) == 0) return v;
    }
    throw std::invalid_argument("ownership map: bad varint");
  };
  while (i < bytes.size()) {
    const uint64_t owner = varint();
    const uint64_t length = varint();
    if (owner > (uint64_t{1} << 31) || length > static_cast<uint64_t>(w * h) - out.size()) {
      throw std::invalid_argument("ownership map: runs overflow the map");
    }
    out.insert(out.end(), length, static_cast<int32_t>(static_cast<int64_t>(owner) - 1));
  }
  if (out.size() != static_cast<size_t>(w * h)) {
    throw std::invalid_argument("ownership map: runs do not fill the map");
  }
  return out;
}

}  // namespace prt
