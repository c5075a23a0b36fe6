#pragma once
// The kinds of traffic between the master and its workers, as MPI tags (src/mpi) and as the
// tag of a TCP frame (net/tcp_frames.h): one numbering for both links. Protocol messages are
// typed (cluster/messages.h), so one tag carries them all.

#include <cstdint>
#include <string>

#include "cluster/messages.h"

namespace prt {

enum LinkTag : int {
  kMessageTag = 1,  // an encoded protocol Message (cluster/messages.h)
  kSummaryTag = 2,  // worker -> master after StopMsg: an encoded WorkerSummary
  kReleaseTag = 3,  // master -> worker: the job's end; an int32 (see ReleaseCode), then for
                    // the worker that must wake the master's port listener, the port name
  kRelayTag = 4,    // worker -> master: for another worker it cannot reach
  kRelayedTag = 5,  // master -> worker: relayed from another worker
  kWelcomeTag = 6,  // master -> joiner: its endpoint and the run's worker options
  kChallengeTag = 8,  // master -> joiner: 32 random bytes to prove the invitation on
  kProofTag = 9,      // joiner -> master: the proof (net/invitation.h)
  kRefusedTag = 10,   // master -> joiner: why it was refused (text)
};

// What a release tells a worker to do.
enum ReleaseCode : int32_t {
  kReleaseFinalize = 0,  // the run is over and every worker is there: exit 0
  kReleaseExit = -1,     // the run is over but a worker was lost: exit 0 (MPI: no finalize)
  // > 0: the master refused the run (bad input): exit with this code
};

// A release's bytes: the code, then for the worker that must wake the master's MPI port
// listener, the port's name.
Bytes releaseMessage(int32_t code, const std::string& wakePort = {});

// Two int32 (an endpoint and a tag, or an endpoint and 0) before `payload`: the header of a
// relayed message and of a welcome.
Bytes withHeader(int32_t a, int32_t b, const Bytes& payload);
bool readHeader(const Bytes& bytes, int32_t& a, int32_t& b);

}  // namespace prt
