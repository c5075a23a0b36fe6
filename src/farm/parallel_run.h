#pragma once
// ParallelRun: what a parallel render produces, whatever drove it, and the master-side
// bookkeeping both drivers share: assembling the image and the ownership map from result
// batches, and building the report from the event stream.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

#include "cluster/messages.h"
#include "farm/checkpoint.h"
#include "farm/parallel_options.h"
#include "farm/progress_board.h"
#include "drive/transport.h"
#include "drive/worker_loop.h"
#include "image/image.h"
#include "metrics/events.h"
#include "metrics/run_report.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

class LocalNetwork;

struct ParallelRun {
  Image image{1, 1};
  std::vector<int16_t> owner;  // per pixel: the worker that rendered it
  std::vector<Event> events;
  RunReport report;
};

// What a parallel render needs, whatever drives it.
struct RunRequest {
  Scene scene;
  RenderSettings settings;
  ParallelOptions options;
  double masterSpeedIndexSeconds = 0;   // the serial machine's speed index, for MASU
  std::optional<double> serialSeconds;  // for speed-up and ASU
  std::optional<Checkpoint> resumeFrom;  // pixels an earlier run finished (--resume)
  std::function<int()> interrupted;      // a pending stop signal (0: none); may be null
  // The frames to render (a still: one). The image of a sequence is its frames one above the
  // other (width x height * frames), task i * width * height + p being pixel p of frame i.
  FrameSequence frames;
  // Called on the master's thread with each frame of a sequence as soon as all its pixels are
  // in, in the order they complete (and at the start, for frames a checkpoint completes).
  std::function<void(uint64_t ordinal, const Image& frame)> frameDone;
  // Where the master publishes its progress while it runs (see farm/progress_board.h);
  // null: nowhere.
  ProgressBoard* progress = nullptr;
  // Called on the master's thread with the machine of each worker rejected (its results were
  // wrong): a driver that admits joiners refuses that machine from then on. May be null.
  std::function<void(const std::string& host)> rejectedHost;
  // The local driver: wraps its master's transport (a door that admits workers over a network,
  // numbered after the local ones: net/local_door.h). May be null.
  std::function<std::unique_ptr<Transport>(Transport& master, LocalNetwork& network)>
      wrapLocalMaster;
};

// The run could not finish (every worker lost, interrupted). The message says what survived
// and how to resume when there is a checkpoint.
class RunFailed : public std::runtime_error {
 public:
  RunFailed(const std::string& message, int signal)
      : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }  // the stop signal, or 0

 private:
  int signal_;
};

// The master's side of a parallel render over `net`, the same for every transport: the
// Master and its strategy, the MasterLoop (leases, heartbeats, reissue), checkpoints, the
// image and the report (`driver` names the transport in it). `abandoned`, if given, is polled
// by the loop: true stops the run (a failure the driver reports itself). Throws RunFailed.
ParallelRun runMasterSide(Transport& net, const RunRequest& request, const std::string& driver,
                          std::function<bool()> abandoned = nullptr);

// A worker's side over `net`: its engine (slowdown, speed index) and the WorkerLoop, with
// this transport's way of failing for an injected fault.
WorkerExit runWorkerSide(Transport& net, int id, const ParallelOptions& options,
                         const WorkerFaultActions& faults);

// Assembles result batches into the image and the ownership map, and counts the pixels of
// each frame of a sequence (frames of `frameHeight` rows stacked; a still is one frame).
class ImageAssembler {
 public:
  ImageAssembler(int width, int height, int frameHeight = 0);
  // Adds a batch of fresh pixels; calls `completed` with each frame it completes.
  void add(int worker, const TaskSet& tasks, const std::vector<float>& rgb,
           const std::function<void(uint64_t)>& completed = {});
  // Takes pixels out again (a rejected worker's): unowned, black, their frames incomplete.
  void takeBack(const TaskSet& tasks);
  bool frameComplete(uint64_t ordinal) const { return frameCounts_[ordinal] == pixelsPerFrame_; }
  uint64_t frameCount() const { return frameCounts_.size(); }
  // The ordinal-th frame's pixels as an image of its own.
  Image frame(uint64_t ordinal) const;
  // Starts from a checkpoint's pixels.
  void restore(const Checkpoint& checkpoint);
  Image& image() { return image_; }
  std::vector<int16_t>& owner() { return owner_; }

 private:
  Image image_;
  std::vector<int16_t> owner_;
  uint64_t pixelsPerFrame_;
  std::vector<uint64_t> frameCounts_;  // pixels in, per frame
};

// The ordinal-th frame of a sequence's image (its frames stacked, `frameHeight` rows each).
Image frameOfSequence(const Image& stacked, int frameHeight, uint64_t ordinal);

// The scene as the master sends it.
SceneMsg makeSceneMessage(const Scene& scene, const RenderSettings& settings,
                          const FrameSequence& frames = {});

// The ownership map: each pixel in its worker's colour, shaded by the image's brightness so
// the picture stays recognisable. Written like any image (extension picks the format).
Image ownershipImage(const Image& image, const std::vector<int16_t>& owner);

}  // namespace prt
