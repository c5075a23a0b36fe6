#include "drive/transport.h"

namespace prt {

void sendOutbox(Transport& net, int from, const Outbox& out, EventLog& log) {
  for (const Envelope& e : out) {
    Bytes bytes = encode(e.message);
    const double now = net.now();
    log.add({EventKind::MessageSent, from, now, now, 0, bytes.size(), e.to,
             messageName(e.message)});
    net.send(e.to, Channel::Protocol, std::move(bytes));
  }
}

}  // namespace prt
