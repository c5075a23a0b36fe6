#pragma once
// The reservoir algorithm's arithmetic (Madamba and Serina 2017, Section II-A) as free
// functions, so the paper's worked examples are unit tests. See
// reference/reading-the-paper.md for the slips this follows rather than the printed text:
// the speed index is a time (lower is faster), so the slowest worker has the LARGEST index;
// every count is rounded up, is at least one task and never runs past the last task.
//
// Counts are rounded up with a tolerance of one part in 10^12, so a product that is an
// integer in exact arithmetic (99 tasks x 1/3) is not pushed up by floating-point noise.

#include <cstdint>
#include <vector>

namespace prt {

// ceil(x) for x >= 0, treating x within 1e-12 (relative) of an integer as that integer.
// Negative and NaN values give 0.
uint64_t ceilCount(double x);

// reservoir_preparation: ratio_i = slowest / speed_i with slowest the largest speed index,
// div_i = ratio_i / sum(ratio). Speeds in seconds, all positive; the result sums to 1.
std::vector<double> divisionOfLabor(const std::vector<double>& speedIndexSeconds);

// initial_distribution's limit: ceil(p * n) with p = initialPercent / 100, at most n.
uint64_t initialLimit(double initialPercent, uint64_t taskCount);

// initial_distribution's block sizes: block_s = ceil(limit * div_s), in worker order, each
// clamped so the running total never exceeds `limit` (late blocks may shrink or be empty).
std::vector<uint64_t> initialBlockSizes(const std::vector<double>& division, uint64_t limit);

// Reservoir: a request from a worker with division `div` takes ceil(div * remaining) tasks,
// at least 1 and at most `remaining` (0 when the reservoir is empty).
uint64_t reservoirHandout(double div, uint64_t remaining);

}  // namespace prt
