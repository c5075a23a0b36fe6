#pragma once
// Parallel rendering from the command line: the flags, and the runs under the local (thread)
// driver and, when built with MPI, under mpirun.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <utility>

#include "cli/render_options.h"
#include "farm/parallel_run.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt::cli {

void addParallelOptions(CLI::App& cmd, RenderOptions& o);

// True when this process was started by mpirun/mpiexec (Open MPI, MPICH or PMIx launchers).
bool launchedByMpirun();



ParallelOptions toParallelOptions(const RenderOptions& o, int workers);
// Writes the image, the report, the trace and the ownership map the options ask for, and
// prints the report table.
// A still whose image cannot be written keeps every pixel in the checkpoint (InputError).
int finishParallelRun(const RenderOptions& o, const Scene& scene, const RenderSettings& settings,
                      const ParallelRun& run);

int renderParallelLocal(const RenderOptions& o, const Scene& scene, const RenderSettings& s);
// --- MPI hook: under mpirun only rank 0 (the master) calls `loadScene`; worker ranks never
// read the scene file, they receive the scene from the master.
using SceneLoader = std::function<std::pair<Scene, RenderSettings>()>;
int renderParallelMpi(const RenderOptions& o, const SceneLoader& loadScene);
// --- end MPI hook

}  // namespace prt::cli
