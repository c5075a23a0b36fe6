#pragma once
// Invitations to join a running render: only a process that read the port file of
// `--accept-workers` (readable by its owner only) may join. The file holds the MPI port and a
// random secret; the master sends each joining rank a random challenge, and the rank answers
// with HMAC-SHA256(secret, challenge || its version) and its version. A wrong proof, no proof
// or another PRT version is refused before the joiner gets the scene.
//
// The version rule is farm/build_info.h's.
// No MPI here: the bytes only. OpenSSL's HMAC and random generator, constant-time compare.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace prt {

using Secret = std::array<uint8_t, 32>;
using Challenge = std::array<uint8_t, 32>;

Secret newSecret();        // from the system's random generator
Challenge newChallenge();
std::string secretHex(const Secret& secret);
std::optional<Secret> secretFromHex(const std::string& hex);  // none: not 64 hex digits

// The port file: the MPI port name, then "secret <hex>", then "tcp HOST:PORT" for each address
// the master's TCP door (net/tcp_door.h) may be reached at.
std::string portFileText(const std::string& port, const Secret& secret,
                         const std::vector<std::string>& tcp = {});
struct PortFile {
  std::string port;
  std::optional<Secret> secret;  // none: the file has no (valid) secret line
  std::vector<std::string> tcp;  // the TCP door's addresses (none: an MPI port only)
};
PortFile parsePortFile(const std::string& text);
// The file itself is written by net/port_file.h's PortFileClaim.

// A joiner's answer: 32 bytes of HMAC of (challenge, build, host), then its build
// description (farm/build_info.h), a zero byte and its machine's name.
std::vector<uint8_t> proofFor(const Secret& secret, const Challenge& challenge,
                              const std::string& build, const std::string& host);
// Empty when `proof` answers `challenge` for `secret` from a compatible build; otherwise why
// not, for the refusal ("it did not prove it was invited", "it runs prt 0.2.0 ..."). `host`
// receives the machine's name the proof gives (for the blocklist).
std::string checkProof(const Secret& secret, const Challenge& challenge,
                       const std::vector<uint8_t>& proof, std::string* host = nullptr);

}  // namespace prt
