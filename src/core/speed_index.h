#pragma once
// The paper's speed index: the seconds a machine takes to solve the Towers of Hanoi
// recursively. Lower is faster. kSpeedIndexDiscs is chosen so one run takes about a tenth of
// a second on a current x86-64 core (2^22 - 1 = 4.2 M moves).
// Reads the clock: call it from drivers, never from strategies.

#include <cstdint>

namespace prt {

inline constexpr int kSpeedIndexDiscs = 25;

// Solves the puzzle for `discs` discs and returns a checksum of the moves made (so the work
// cannot be optimised away); the number of moves is 2^discs - 1.
uint64_t solveHanoi(int discs);

// Runs solveHanoi(discs) `repeats` times and returns the median wall time in seconds.
double measureSpeedIndexSeconds(int discs = kSpeedIndexDiscs, int repeats = 3);

}  // namespace prt
