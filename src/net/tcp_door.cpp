#include "net/tcp_door.h"

#include "net/link_tags.h"
#include "core/input_error.h"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace prt {
namespace {

constexpr uint64_t kProofFrameBytes = 4096;

std::string addressText(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return text;
}

}  // namespace

DoorAddress parseDoorAddress(const std::string& text) {
  DoorAddress out;
  const size_t colon = text.rfind(':');
  out.address = text.substr(0, colon);
  const auto bad = [&] {
    return InputError("--accept-address: '" + text +
                      "' is not [ADDRESS][:PORT] (an IPv4 address of this machine, a port "
                      "1-65535)");
  };
  if (colon != std::string::npos) {
    const std::string port = text.substr(colon + 1);
    if (port.empty() || port.size() > 5 ||
        port.find_first_not_of("0123456789") != std::string::npos) {
      throw bad();
    }
    const long value = std::stol(port);
    if (value < 1 || value > 65535) throw bad();
    out.port = static_cast<uint16_t>(value);
  }
  in_addr parsed{};
  if (!out.address.empty() && ::inet_pton(AF_INET, out.address.c_str(), &parsed) != 1) throw bad();
  return out;
}

TcpDoor::TcpDoor(const Secret& secret, const std::string& bindAddress, uint16_t port)
    : secret_(secret), bound_(bindAddress == "0.0.0.0" ? "" : bindAddress) {
  listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listener_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  int one = 1;
  ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_ANY);
  if (!bound_.empty() && ::inet_pton(AF_INET, bound_.c_str(), &a.sin_addr) != 1) {
    ::close(listener_);
    throw std::runtime_error("'" + bound_ + "' is not an IPv4 address");
  }
  if (::bind(listener_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
      ::listen(listener_, 64) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listener_);
    throw std::runtime_error("cannot listen on " + (bound_.empty() ? "*" : bound_) + ":" +
                             std::to_string(port) + ": " + why);
  }
  socklen_t size = sizeof a;
  ::getsockname(listener_, reinterpret_cast<sockaddr*>(&a), &size);
  port_ = ntohs(a.sin_port);
  prepareSocket(listener_);
}

TcpDoor::~TcpDoor() {
  closeAll();
  if (listener_ >= 0) ::close(listener_);
}

std::vector<std::string> TcpDoor::addresses() const {
  std::string port = std::to_string(port_);
  port.insert(port.begin(), ':');  // (not ":" + ...: GCC 12 sees a false overlap in it)
  if (!bound_.empty()) return {bound_ + port};
  std::vector<std::string> out, loopback;
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) == 0) {
    for (ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
      if (i->ifa_addr == nullptr || i->ifa_addr->sa_family != AF_INET) continue;
      const std::string text = addressText(*reinterpret_cast<sockaddr_in*>(i->ifa_addr)) + port;
      if (std::find(out.begin(), out.end(), text) != out.end()) continue;
      ((i->ifa_flags & 0x8 /* IFF_LOOPBACK */) ? loopback : out).push_back(text);
    }
    ::freeifaddrs(list);
  }
  out.insert(out.end(), loopback.begin(), loopback.end());
  if (out.empty()) out.push_back("127.0.0.1" + port);
  return out;
}

void TcpDoor::acceptNew() {
  for (;;) {
    sockaddr_in from{};
    socklen_t size = sizeof from;
    const int fd = ::accept4(listener_, reinterpret_cast<sockaddr*>(&from), &size, SOCK_CLOEXEC);
    if (fd < 0) return;
    prepareSocket(fd);
    if (!admitting_) {
      ::close(fd);
      continue;
    }
    Pending p;
    p.socket = std::make_unique<FramedSocket>(fd, kProofFrameBytes);
    p.challenge = newChallenge();
    p.since = std::chrono::steady_clock::now();
    p.peer = addressText(from);
    p.socket->send(kChallengeTag, Bytes(p.challenge.begin(), p.challenge.end()));
    pending_.push_back(std::move(p));
  }
}

void TcpDoor::refuse(Pending& p, const std::string& why) {
  refused_.push_back("a joiner from " + p.peer + ": " + why);
  p.socket->send(kRefusedTag, Bytes(why.begin(), why.end()));
  p.socket->drain(0.1);
  p.socket->close();
}

std::optional<TcpDoor::Event> TcpDoor::poll() {
  if (events_.empty()) {
    if (listener_ >= 0) acceptNew();
    const auto now = std::chrono::steady_clock::now();
    for (Pending& p : pending_) {
      const bool alive = p.socket->receive();
      if (std::optional<Frame> f = p.socket->next()) {
        std::string host;
        std::string why =
            f->tag == kProofTag
                ? checkProof(secret_, p.challenge, std::vector<uint8_t>(f->bytes.begin(), f->bytes.end()), &host)
                : "it did not prove it was invited";
        if (why.empty() && blocked_.count(host) > 0) {
          why = "a worker on " + host + " was rejected in this run";
        }
        if (!why.empty()) {
          refuse(p, why);
          continue;
        }
        p.socket->setMaxFrameBytes(FramedSocket::kMaxFrameBytes);
        const int joiner = static_cast<int>(joiners_.size());
        joiners_.push_back(std::move(p.socket));
        events_.push_back({Event::Kind::Joined, joiner, 0, {}, host});
        continue;
      }
      if (!alive) {
        p.socket->close();
      } else if (std::chrono::duration<double>(now - p.since).count() > kProofSeconds) {
        refuse(p, "it sent no proof of its invitation within " +
                      std::to_string(static_cast<int>(kProofSeconds)) + " s");
      }
    }
    pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                  [](const Pending& p) { return !p.socket || !p.socket->open(); }),
                   pending_.end());
    for (size_t j = 0; j < joiners_.size(); ++j) {
      FramedSocket* s = joiners_[j].get();
      if (s == nullptr) continue;
      const bool alive = s->receive() && s->transmit();
      while (std::optional<Frame> f = s->next()) {
        events_.push_back({Event::Kind::Frame, static_cast<int>(j), f->tag, std::move(f->bytes), {}});
      }
      if (!alive || !s->open()) {
        joiners_[j].reset();
        events_.push_back({Event::Kind::Closed, static_cast<int>(j), 0, {}, {}});
      }
    }
  }
  if (events_.empty()) return std::nullopt;
  Event e = std::move(events_.front());
  events_.erase(events_.begin());
  return e;
}

void TcpDoor::wait(double seconds) {
  std::vector<pollfd> fds;
  if (listener_ >= 0 && admitting_) fds.push_back({listener_, POLLIN, 0});
  for (const Pending& p : pending_) fds.push_back({p.socket->fd(), POLLIN, 0});
  for (const auto& s : joiners_) {
    if (s) fds.push_back({s->fd(), static_cast<short>(POLLIN | (s->pendingOutput() ? POLLOUT : 0)), 0});
  }
  ::poll(fds.data(), fds.size(), std::max(0, static_cast<int>(seconds * 1000)));
}

void TcpDoor::send(int joiner, int tag, const Bytes& bytes) {
  if (joiner < 0 || joiner >= joinerCount() || !joiners_[static_cast<size_t>(joiner)]) return;
  joiners_[static_cast<size_t>(joiner)]->send(tag, bytes);
}

bool TcpDoor::flush(double timeoutSeconds) {
  const auto start = std::chrono::steady_clock::now();
  bool all = true;
  for (const auto& s : joiners_) {
    if (!s) continue;
    const double left =
        timeoutSeconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    all = s->drain(std::max(0.0, left)) && all;
  }
  return all;
}

void TcpDoor::stopAdmitting() {
  admitting_ = false;
  for (Pending& p : pending_) p.socket->close();
  pending_.clear();
  if (listener_ >= 0) ::close(listener_);
  listener_ = -1;
}

void TcpDoor::closeAll() {
  stopAdmitting();
  for (auto& s : joiners_) {
    if (s) s->close();
  }
}

}  // namespace prt
