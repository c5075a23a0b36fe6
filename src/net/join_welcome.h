#pragma once
// What a joiner needs of the run's options, which it was not started with (the speed index,
// the batch, the lease): the master sends it in the welcome after the joiner's endpoint, over
// MPI (MpiLink::adopt) or TCP (net/tcp_door.h) alike.

#include "cluster/messages.h"
#include "farm/parallel_options.h"

namespace prt {

Bytes encodeWelcome(const ParallelOptions& o);
// The joiner's side: its endpoint and the run's options over its own (threads, slowdown).
// Throws std::runtime_error on a malformed welcome.
int decodeWelcome(const Bytes& bytes, ParallelOptions& o);

}  // namespace prt
