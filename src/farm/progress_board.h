#pragma once
// ProgressBoard: what a running render shows of itself — the pixels done, an ETA, one row per
// worker, the image so far — published by the render's own thread and read by any number of
// others (the terminal's progress lines, the live page's server). The render never waits for
// a reader: it publishes a copy under a short lock at most a few times a second, and copies
// the image only when a reader asked for it since the last copy.
// Thread-safe.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"

namespace prt {

struct WorkerProgress {
  enum class State { Starting, Working, Idle, Lost, Done };
  State state = State::Starting;
  uint64_t pixels = 0;        // in the image from it
  double pixelsPerSecond = 0; // over the last few seconds
  double silentSeconds = 0;   // since the master last heard from it
  std::optional<double> joinedAt;  // seconds into the run, for a worker that joined
  std::optional<double> lostAt;
  std::string lostReason;
};
const char* stateName(WorkerProgress::State state);

struct ProgressSnapshot {
  enum class Phase { Starting, Rendering, Finished, Failed };
  Phase phase = Phase::Starting;
  uint64_t version = 0;       // grows with every publish
  double elapsedSeconds = 0;
  uint64_t pixelsDone = 0;    // a checkpoint's pixels included
  uint64_t pixelsTotal = 0;
  uint64_t resumedPixels = 0;
  std::optional<double> etaSeconds;    // nothing until the cost of the work is known
  std::optional<double> doneFraction;  // of the expected work, not of the pixels
  std::vector<WorkerProgress> workers; // empty for a serial render
  std::string message;        // when finished or failed: what happened, where the image is
};
const char* phaseName(ProgressSnapshot::Phase phase);

// The image so far: one frame (the earliest one not finished, for a sequence) and which of
// its pixels are in.
struct PartialImage {
  uint64_t version = 0;       // the snapshot version it was copied at
  uint64_t frame = 0;         // ordinal in the sequence
  Image image{1, 1};
  std::vector<uint8_t> done;  // per pixel of `image`: 1 once rendered
  std::vector<int16_t> owner; // per pixel: the worker that rendered it (-1: none, or serial)
};

class ProgressBoard {
 public:
  ProgressBoard() = default;
  ProgressBoard(const ProgressBoard&) = delete;
  ProgressBoard& operator=(const ProgressBoard&) = delete;

  // The render's side. The version is set here.
  void publish(ProgressSnapshot snapshot);
  // True when a reader asked for the image since the last publishImage.
  bool imageWanted() const { return imageWanted_.load(std::memory_order_relaxed); }
  // True once a reader of the image is attached (watch()): the render's last image is then
  // copied for it. With none (a render with no live page), no image is ever copied.
  bool watched() const { return watched_.load(std::memory_order_relaxed); }
  void publishImage(PartialImage image);

  // The readers' side.
  // A reader of the image is attached (the live page): an image is wanted from now on.
  void watch() {
    watched_.store(true, std::memory_order_relaxed);
    imageWanted_.store(true, std::memory_order_relaxed);
  }
  ProgressSnapshot snapshot() const;
  // The last image copied, and a request for a fresh one.
  std::shared_ptr<const PartialImage> image();

  // Static facts of the run, set once before it starts.
  struct RunFacts {
    std::string driver;    // "serial", "threads", "mpi"
    std::string strategy;  // empty for serial
    int width = 0, height = 0;
    uint64_t frames = 1;
    std::string output;    // the image file (a sequence: its pattern)
  };
  void setFacts(RunFacts facts);
  RunFacts facts() const;

 private:
  mutable std::mutex mutex_;
  ProgressSnapshot snapshot_;
  RunFacts facts_;
  std::shared_ptr<const PartialImage> image_;
  std::atomic<bool> imageWanted_{false};
  std::atomic<bool> watched_{false};
};

}  // namespace prt
