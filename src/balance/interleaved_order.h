#pragma once
// An interleaved order of the tasks (pixels in scan-line order) in which every contiguous
// stretch samples the whole image, so a strategy that hands out contiguous stretches of a
// sequence (the reservoir's blocks and hand-outs) gives each worker a fair share of sky and
// glass however the cost is spread. Used by "reservoir-scatter".
//
// The tasks are split into S strata, stratum j holding the pixels j, j + S, j + 2S, ...: about
// kStratumTasks of them, spread from the top of the image to the bottom. Strata come in cells
// of kCellStrata neighbours (strata cB .. cB + B - 1: B pixels side by side at each of the
// stratum's places), and the cells follow one another in golden-ratio order, c = i * g mod C
// with g / C close to 0.618 and C prime, so consecutive cells land far apart across the image
// and any run of them covers it evenly (Weyl's sequence; every cell comes exactly once). A
// stretch of L tasks is then L / kStratumTasks whole strata plus at most two partial ones:
// even across a cluster of workers whose hand-outs are a few hundred tasks, no worker gets a
// band of scan lines. The cells keep a batch's pixels near one another: traced one thread,
// the keyframes scene's pixels cost 1.09x their scan-line time in lone strata and 1.03x in
// cells of 4 (bench/trace_bench.cpp BM_PixelOrder), and 4 slowed workers rendering a
// sequence gained about 5 % (bench/animation.py); the simulated ASU did not drop. Each
// stratum is one strided run, so the order stays compact: S runs in all.
//
// Pure function; thread-safe.

#include <cstdint>

#include <vector>

#include "balance/strategy.h"
#include "core/task_set.h"

namespace prt {

inline constexpr uint64_t kStratumTasks = 32;
inline constexpr uint64_t kCellStrata = 4;  // neighbouring strata per cell

// The number of cells for `taskCount` tasks: the smallest prime >= taskCount / (kStratumTasks
// * kCellStrata), at least 2 (1 for one task).
uint64_t interleavedCells(uint64_t taskCount);

// The number of strata: kCellStrata per cell, at most taskCount.
uint64_t interleavedStrata(uint64_t taskCount);

// Every task 0 .. taskCount-1 exactly once, in interleaved order. With `frameTasks` (a frame
// sequence's pixels per frame), each frame's tasks are interleaved among themselves and the
// frames follow one another, so that frames complete one after another, not all at the end.
// (The scan-line order, frame after frame, traces about 10 % faster on real workers but gave
// 1,024 simulated workers an ASU of 0.81 against 0.995: the first hand-outs then see unlike
// parts of the image.)
TaskSet interleavedOrder(uint64_t taskCount, uint64_t frameTasks = 0);

// The same for frames of the given sizes, in order (a resumed sequence, whose frames lack
// what the earlier run finished): each frame's tasks interleaved among themselves, never
// with another frame's, so that a hand-out spans one frame, or two where one ends.
TaskSet interleavedOrder(const std::vector<uint64_t>& frameTaskCounts);

// A strategy's order of StartInfo's tasks: by its frames' sizes when they differ, else as
// interleavedOrder(taskCount, frameTasks).
TaskSet interleavedOrder(const StartInfo& info);

}  // namespace prt
