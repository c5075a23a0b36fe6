#include "net/invitation.h"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>

#include <cstring>
#include <stdexcept>

#include "farm/build_info.h"

namespace prt {
namespace {

template <size_t N>
std::array<uint8_t, N> randomBytes() {
  std::array<uint8_t, N> out{};
  if (RAND_bytes(out.data(), static_cast<int>(N)) != 1) {
    throw std::runtime_error("the system's random generator failed");
  }
  return out;
}

// The message signed: the challenge, then the build and the host with a zero byte between.
std::array<uint8_t, 32> hmac(const Secret& secret, const Challenge& challenge,
                             const std::string& identity) {
  // Sized first and copied into (GCC 12 misreads an insert after an array here).
  std::vector<uint8_t> message(challenge.size() + identity.size());
  std::memcpy(message.data(), challenge.data(), challenge.size());
  if (!identity.empty()) {
    std::memcpy(message.data() + challenge.size(), identity.data(), identity.size());
  }
  std::array<uint8_t, 32> out{};
  unsigned int length = 0;
  if (HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()), message.data(),
           message.size(), out.data(), &length) == nullptr ||
      length != out.size()) {
    throw std::runtime_error("HMAC-SHA256 failed");
  }
  return out;
}


}  // namespace

Secret newSecret() { return randomBytes<32>(); }
Challenge newChallenge() { return randomBytes<32>(); }

std::string secretHex(const Secret& secret) {
  static const char* kDigits = "0123456789abcdef";
  std::string out;
  for (const uint8_t b : secret) {
    out += kDigits[b >> 4];
    out += kDigits[b & 15];
  }
  return out;
}

std::optional<Secret> secretFromHex(const std::string& hex) {
  if (hex.size() != 64) return std::nullopt;
  Secret out{};
  const auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  for (size_t i = 0; i < out.size(); ++i) {
    const int hi = digit(hex[2 * i]), lo = digit(hex[2 * i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    out[i] = static_cast<uint8_t>(hi * 16 + lo);
  }
  return out;
}

std::string portFileText(const std::string& port, const Secret& secret,
                         const std::vector<std::string>& tcp) {
  std::string text = port + "\nsecret " + secretHex(secret) + "\n";
  for (const std::string& address : tcp) text += "tcp " + address + "\n";
  return text;
}

PortFile parsePortFile(const std::string& text) {
  PortFile out;
  const auto trim = [](std::string s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
    return s;
  };
  size_t start = 0;
  for (int line = 0; start <= text.size(); ++line) {
    const size_t end = text.find('\n', start);
    const std::string item = trim(text.substr(start, end == std::string::npos ? end : end - start));
    if (line == 0) {
      out.port = item;
    } else if (item.rfind("secret ", 0) == 0 && !out.secret) {
      out.secret = secretFromHex(item.substr(7));
    } else if (item.rfind("tcp ", 0) == 0 && item.size() > 4 && out.tcp.size() < 64) {
      out.tcp.push_back(item.substr(4));
    }
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

std::vector<uint8_t> proofFor(const Secret& secret, const Challenge& challenge,
                              const std::string& build, const std::string& host) {
  std::string identity = build;
  identity += '\0';
  identity += host;
  const std::array<uint8_t, 32> mac = hmac(secret, challenge, identity);
  std::vector<uint8_t> out(mac.size() + identity.size());
  std::memcpy(out.data(), mac.data(), mac.size());
  std::memcpy(out.data() + mac.size(), identity.data(), identity.size());
  return out;
}

std::string checkProof(const Secret& secret, const Challenge& challenge,
                       const std::vector<uint8_t>& proof, std::string* host) {
  if (proof.size() < 32 || proof.size() > 32 + 512) return "it did not prove it was invited";
  const std::string identity(proof.begin() + 32, proof.end());
  const std::array<uint8_t, 32> mac = hmac(secret, challenge, identity);
  if (CRYPTO_memcmp(mac.data(), proof.data(), mac.size()) != 0) {
    return "it did not prove it was invited (no secret, or not this render's)";
  }
  const size_t zero = identity.find('\0');
  const std::string build = identity.substr(0, zero);
  if (host) *host = zero == std::string::npos ? "" : identity.substr(zero + 1);
  if (versionOf(build) != prtVersion()) {
    std::string shown;
    for (const char c : build) shown += (c >= 32 && c < 127) ? c : '?';
    return "it runs '" + shown + "', this render " + buildDescription() +
           ": builds of another version may not mix pixels";
  }
  return "";
}

}  // namespace prt
