#include "drive/local_transport.h"

#include <algorithm>

namespace prt {

LocalNetwork::LocalNetwork(int workerCount) : start_(std::chrono::steady_clock::now()) {
  for (int w = 0; w < workerCount; ++w) workers_.push_back(std::make_unique<Mailbox>());
}

void LocalNetwork::join(int endpoint) {
  master_.push(Mail{endpoint, Channel::Protocol, {}, false, true});
}

Mailbox& LocalNetwork::boxOf(int endpoint) {
  return endpoint == kMaster ? master_ : *workers_[static_cast<size_t>(endpoint)];
}

double LocalNetwork::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::chrono::steady_clock::time_point LocalNetwork::timeAt(double seconds) const {
  // Deadlines far ahead (an infinite lease) are capped: a wait never needs more than an hour.
  const double capped = std::min(seconds, now() + 3600.0);
  return start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>(capped));
}

void LocalNetwork::shutDown() {
  shutdown_ = true;
  for (auto& box : workers_) box->push(Mail{kMaster, Channel::Protocol, {}, true});
}

void LocalTransport::send(int to, Channel channel, Bytes bytes) {
  if (to != kMaster && to >= net_.mailboxCount()) {
    // A worker that joined over a network: through the master.
    Mail relayed{self_, channel, std::move(bytes), false};
    relayed.relayTo = to;
    net_.boxOf(kMaster).push(std::move(relayed));
    return;
  }
  net_.boxOf(to).push(Mail{self_, channel, std::move(bytes), false});
}

Incoming LocalTransport::poll(double deadline) {
  std::optional<Mail> mail = net_.boxOf(self_).popUntil(net_.timeAt(deadline));
  while (mail && mail->relayTo != kMaster) {
    if (net_.relay()) net_.relay()(mail->from, mail->relayTo, mail->channel, std::move(mail->bytes));
    mail = net_.boxOf(self_).popUntil(net_.timeAt(deadline));
  }
  Incoming in;
  if (!mail) return in;
  in.from = mail->from;
  if (mail->lost) {
    in.kind = Incoming::Kind::PeerLost;
    return in;
  }
  if (mail->joined) {
    in.kind = Incoming::Kind::PeerJoined;
    return in;
  }
  in.kind = Incoming::Kind::Packet;
  in.channel = mail->channel;
  in.bytes = std::move(mail->bytes);
  return in;
}

void LocalTransport::dropConnection() {
  if (self_ != kMaster) net_.boxOf(kMaster).push(Mail{self_, Channel::Protocol, {}, true});
}

}  // namespace prt
