#pragma once
// Worker speeds for the simulator, relative to the machine the cost map was recorded on:
// 1 = full speed, 0.5 = twice as slow (a real run's --slowdown 2), 2 = twice as fast. A
// worker of speed s renders a batch in cost / s seconds and measures a speed index of
// baseSpeedIndex / s (the speed index is a time).
//
// The random distributions draw from std::mt19937_64, whose output the C++ standard fixes,
// through our own transforms (std::normal_distribution and std::shuffle differ between
// standard libraries), so a seed gives the same speeds everywhere.

#include <cstdint>
#include <vector>

#include "core/speed_schedule.h"

namespace prt {

// Throws InputError unless there is one speed per worker, each finite and > 0.
void validateWorkerSpeeds(const std::vector<double>& speeds, int workers);

// Every worker at speed 1.
std::vector<double> uniformSpeeds(int workers);

// round(share * workers) workers, picked by a seeded shuffle, run `factor` times slower
// (speed 1 / factor); the rest at speed 1. share in [0, 1], factor >= 1 (InputError
// otherwise).
std::vector<double> slowShareSpeeds(int workers, double share, double factor, uint64_t seed);

// Log-normal speeds exp(sigma * z), z standard normal: median 1, so some workers are faster
// than the recording machine and some slower. sigma >= 0 (InputError otherwise).
std::vector<double> lognormalSpeeds(int workers, double sigma, uint64_t seed);

// Speeds that change mid-run (--speed-at): when `work` full-speed seconds started at `start`
// on a worker of speed `initial` whose changes (sorted, changesOf()) are `sorted` are done.
// Without changes, start + work / initial.
double workDoneAt(double start, double work, double initial, const std::vector<SpeedChange>& sorted);

}  // namespace prt
