// What a peer of the master's TCP door may send before and after it is admitted: arbitrary
// bytes on a connection, read as frames (net/tcp_frames.h) under the door's limit for an
// unproven peer, and every proof frame checked as the door checks it (net/invitation.h). The
// bytes go through a socket pair, as they would arrive. Nothing may crash, leak, or take more
// than the frame limit's memory.

#include <sys/socket.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "net/invitation.h"
#include "net/link_tags.h"
#include "net/tcp_frames.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const prt::Secret secret = prt::newSecret();
  static const prt::Challenge challenge = prt::newChallenge();
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM, 0, pair) != 0) return 0;
  prt::prepareSocket(pair[0]);
  prt::FramedSocket reader(pair[0], 4096);  // the door's limit before a proof
  size_t written = 0;
  while (written < size) {
    const ssize_t n = ::write(pair[1], data + written, size - written);
    if (n <= 0) break;
    written += static_cast<size_t>(n);
    // Read as it arrives: the socket's buffer is smaller than the largest inputs.
    reader.receive();
    while (std::optional<prt::Frame> f = reader.next()) {
      if (f->tag == prt::kProofTag) {
        std::string host;
        (void)prt::checkProof(secret, challenge, std::vector<uint8_t>(f->bytes.begin(), f->bytes.end()), &host);
      }
    }
    if (!reader.open()) break;
  }
  ::close(pair[1]);
  while (reader.open() && reader.receive()) {
  }
  while (std::optional<prt::Frame> f = reader.next()) {
    int32_t a = 0, b = 0;
    (void)prt::readHeader(f->bytes, a, b);
  }
  return 0;
}
