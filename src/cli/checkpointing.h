#pragma once
// --checkpoint and --resume on the command line, for serial and parallel renders.

#include <exception>
#include <functional>
#include <optional>

#include "cli/render_options.h"
#include "farm/checkpoint.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt::cli {

// The render's checkpoint settled: --checkpoint FILE as given; else, unless --no-checkpoint
// (or --cost-map, which times a whole render), OUTPUT.ckpt beside the output, automatic:
// written only once the render is expected to take more than kAutomaticCheckpointSeconds,
// or when it is stopped with pixels done.
RenderOptions withCheckpointPlan(RenderOptions o, const Scene& scene);

// The command that resumes this render: the one typed, with --resume.
std::string resumeCommand(const RenderOptions& o);
// After a run that stopped: when its checkpoint exists, the command that resumes it
// ("\nprt: to render the rest, run:\n  prt render ... --resume"), else nothing; and printed.
std::string howToResume(const RenderOptions& o);
void tellHowToResume(const RenderOptions& o);

// The checkpoint to start from: nothing without --resume (an existing checkpoint file is then
// refused, so an earlier run's progress is never overwritten by mistake), or when the file
// does not exist yet (a warning says so). Throws InputError for a damaged file, one of
// another render, or --resume without --checkpoint.
std::optional<Checkpoint> resumeCheckpoint(const RenderOptions& o, const Scene& scene,
                                           const RenderSettings& settings);

// The image (or a frame of a sequence) could not be written, e.g. its disk is full: keeps
// every finished pixel in the checkpoint, when the run has one, so that --resume writes it
// without rendering them again, and throws InputError with the write's error, where the
// pixels are (or that they could not be saved either) and the command that resumes.
[[noreturn]] void keepPixelsOfUnwrittenImage(const RenderOptions& o, const CheckpointKey& key,
                                             const TaskSet& done, const Image& image,
                                             const std::vector<int16_t>& owner,
                                             const std::exception& failure);

// With a checkpoint, stop signals are caught so the run can save its work first; returns the
// poll for them (null without a checkpoint: a signal then ends the run at once).
std::function<int()> stopSignalsFor(const RenderOptions& o);

// A serial render with --checkpoint: renders what the checkpoint lacks, in pieces, writing the
// checkpoint every --checkpoint-every seconds and when a stop signal arrives.
int renderSerialWithCheckpoint(const RenderOptions& o, const Scene& scene,
                               const RenderSettings& settings);

}  // namespace prt::cli
