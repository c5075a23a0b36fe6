#pragma once
// A TCP connection carrying tagged frames (net/link_tags.h), without ever blocking: a frame is
// a 32-bit length (of what follows), a 32-bit tag, then the bytes, in the machine's byte
// order (PRT's messages are little-endian throughout: cluster/messages.h). Reads take what has
// arrived; writes queue and go out as the socket accepts them. A frame longer than the limit
// closes the connection: a peer that has not proved it was invited may send a few hundred
// bytes only. Not thread-safe; one owner.

#include <cstdint>
#include <optional>
#include <string>

#include "cluster/messages.h"

namespace prt {

struct Frame {
  int tag = 0;
  Bytes bytes;
};

class FramedSocket {
 public:
  static constexpr uint64_t kMaxFrameBytes = (uint64_t{1} << 31) - 1;

  explicit FramedSocket(int fd, uint64_t maxFrameBytes = kMaxFrameBytes);
  ~FramedSocket();
  FramedSocket(const FramedSocket&) = delete;
  FramedSocket& operator=(const FramedSocket&) = delete;

  int fd() const { return fd_; }
  bool open() const { return fd_ >= 0; }
  void setMaxFrameBytes(uint64_t limit) { maxFrame_ = limit; }
  // Reads what has arrived; false once the peer closed, the connection failed or a frame was
  // too long (the socket is then closed).
  bool receive();
  // The next whole frame received, if any; hasFrame() says whether there is one.
  std::optional<Frame> next();
  bool hasFrame() const;
  // Queues a frame and writes what the socket takes now.
  void send(int tag, const Bytes& bytes);
  // Writes what the socket takes now; false once the connection failed.
  bool transmit();
  bool pendingOutput() const { return outOffset_ < out_.size(); }
  // Waits (poll) until the queued output is written, for at most `timeoutSeconds`.
  bool drain(double timeoutSeconds);
  void close();

 private:
  int fd_;
  uint64_t maxFrame_;
  Bytes in_;
  size_t inOffset_ = 0;  // start of the first frame not taken
  Bytes out_;
  size_t outOffset_ = 0;  // bytes of out_ already written
};

// Makes `fd` non-blocking, without Nagle's delay, and closed on exec.
void prepareSocket(int fd);

// Connects to "HOST:PORT" (a numeric IPv4 address or a name), waiting at most
// `timeoutSeconds`; the socket is prepared. -1 and `why` on failure.
int connectTo(const std::string& address, double timeoutSeconds, std::string& why);

}  // namespace prt
