#!/usr/bin/env bash
# Installs dependencies, builds with warnings as errors, runs every test (unit, end-to-end,
# MPI) through CTest, then fuzzes the scene parser and the message decoder for
# PRT_FUZZ_SECONDS each (default 45; 0 skips; about 3 minutes in all with the fuzz build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Tests and benchmarks on, whatever an earlier scripts/demo.sh configured.
PRT_CMAKE_ARGS="-DPRT_BUILD_TESTS=ON -DPRT_BUILD_BENCH=ON" bash scripts/build.sh ci
ctest --preset ci "$@"
fuzz_seconds=${PRT_FUZZ_SECONDS:-45}
if ((fuzz_seconds > 0)); then bash scripts/fuzz.sh "$fuzz_seconds"; fi
