#pragma once
// ByteWriter / ByteReader: the little-endian binary layout every PRT wire format uses (the
// protocol messages, the MPI workers' end-of-run summaries). Plain values are copied
// byte-for-byte; strings carry a 16-bit length; a reader refuses truncated or overlong
// buffers with std::runtime_error naming what it was reading (a transport fault, not user
// input). Not thread-safe; one per buffer.

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace prt {

static_assert(std::endian::native == std::endian::little, "encoding assumes little-endian");

class ByteWriter {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw(&v, sizeof(T));
  }
  void raw(const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    out.insert(out.end(), b, b + n);
  }
  void text(const std::string& s) {
    if (s.size() > std::numeric_limits<uint16_t>::max()) {
      throw std::runtime_error("string too long to encode");
    }
    pod(static_cast<uint16_t>(s.size()));
    raw(s.data(), s.size());
  }
  std::vector<uint8_t> out;
};

class ByteReader {
 public:
  // `what` names the format in error messages, e.g. "message" or "worker summary".
  ByteReader(const uint8_t* data, size_t size, const char* what)
      : data_(data), size_(size), what_(what) {}

  template <typename T>
  T pod() {
    T v;
    raw(&v, sizeof(T));
    return v;
  }
  void raw(void* dest, size_t n) {
    need(n);
    if (n == 0) return;  // dest may be null then (an empty vector's data()): memcpy forbids it
    std::memcpy(dest, data_ + pos_, n);
    pos_ += n;
  }
  std::string text() {
    const auto n = pod<uint16_t>();
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += n;
    return s;
  }
  void need(uint64_t n) const {
    if (n > size_ - pos_) fail("truncated");
  }
  // That `count` items of `itemBytes` each remain, without the product overflowing (a
  // corrupt count must not pass as a small one and then size a huge allocation).
  void needItems(uint64_t count, uint64_t itemBytes) const {
    if (count > (size_ - pos_) / itemBytes) fail("truncated");
  }
  void finish() const {
    if (pos_ != size_) fail("trailing bytes");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(std::string("malformed ") + what_ + ": " + why);
  }

 private:
  const uint8_t* data_;
  size_t size_;
  const char* what_;
  size_t pos_ = 0;
};

}  // namespace prt
