#pragma once
// RenderOptions: everything `prt render` accepts, serial and parallel.

#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/run_plan_flags.h"
#include "cli/strategy_flags.h"
#include "cluster/leases.h"
#include "cluster/worker.h"
#include "core/frame_sequence.h"
#include "image/image_io.h"
#include "loops/master_reactor.h"

namespace prt::cli {

// --video-timeout: seconds ffmpeg may go without progress before it is ended.
inline constexpr double kDefaultVideoTimeoutSeconds = 60;

struct RenderOptions;
// The frames --frames or --frame ask for (a still: one frame at time 0). Throws InputError.
FrameSequence framesOf(const RenderOptions& o);

// RunPlanFlags: --strategy, --batch, --worker-timeout, --endgame, --inject-fault, --join-at
// (local driver), shared with prt simulate.
struct RenderOptions : RunPlanFlags {
  SceneSource scene;  // the scene or model file and how to read it
  std::string output;         // empty: the scene's own output file
  std::optional<int> width;   // overrides the scene's image width, pixels
  std::optional<int> height;  // overrides the scene's image height, pixels
  std::optional<int> spp;     // SS: samples per pixel
  std::optional<int> drt;     // DRT rate
  std::string integrator;     // "hall" or "path"; empty: the scene's
  std::string environment;    // an HDR environment map (.hdr, .exr); empty: the scene's
  std::optional<double> environmentStrength, environmentRotate;  // over the scene's
  std::string testCase;       // A|B|C|D: sets DRT and SS as in the paper's Table III
  int threads = 0;            // serial: render threads (0: all cores); parallel: per worker
  bool quiet = false;
  ImageWriteOptions imageOptions;  // --exr-half, --jpeg-quality
  std::string serve;          // --serve [HOST:]PORT: the live page of the running render
  std::string costMapPath;    // serial: also write each pixel's render seconds (for simulate)
  std::string frames;         // --frames A-B[:STEP]: an animation's frames as one job
  std::string frame;          // --frame N: one frame of it
  double fps = 24;            // --fps: frame N is at N / fps seconds
  std::string videoPath;      // --video FILE: the sequence's frames made into a video
  double videoTimeoutSeconds = kDefaultVideoTimeoutSeconds;  // --video-timeout: ffmpeg stalled

  // Parallel rendering.
  std::optional<int> workers;              // local driver: worker threads
  std::vector<double> slowdowns;           // per worker, >= 1
  std::string slowdownAt;                  // --slowdown-at W:T:K,...
  std::string acceptWorkersPath;           // --accept-workers FILE
  std::string acceptAddress;               // --accept-address [ADDRESS][:PORT]
  std::string speedIndex = "auto";         // what workers measure: auto | hanoi | probe | none
  std::optional<double> batchSeconds;      // batches grow to this much work; none: by the
                                           // worker count (defaultBatchSeconds)
  double startupTimeoutSeconds = 120;      // --startup-timeout: MPI start-up's deadline
  std::string checkpointPath;              // --checkpoint FILE (or, resolved, OUTPUT.ckpt)
  bool noCheckpoint = false;               // --no-checkpoint: no automatic checkpoint
  bool checkpointAutomatic = false;        // resolved: the path is the automatic one, kept
                                           // only once the render proves long (or is stopped)
  double checkpointEverySeconds = kDefaultCheckpointEverySeconds;  // --checkpoint-every SECONDS
  bool resume = false;                     // --resume: start from the checkpoint
  std::optional<double> serialSeconds;     // serial time for speed-up
  bool measureSerial = false;              // render serially first to measure it
  std::string reportPath;                  // --report FILE.json
  std::string tracePath;                   // --trace FILE.json
  std::string ownershipPath;               // --ownership FILE.png
  std::string htmlPath;                    // --html FILE.html: the run's page
  std::string commandLine;                 // as typed, recorded in the report and the page
  double verifyPercent = 1;                // --verify: spot-check rate (0: off)
  uint64_t verifySeed = 0;                 // --verify-seed: the sample's seed (0: random)
};

}  // namespace prt::cli
