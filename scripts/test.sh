#!/usr/bin/env bash
# Installs dependencies, builds with warnings as errors, runs every test (unit, end-to-end,
# MPI) through CTest, then fuzzes the scene parser and the message decoder for
# PRT_FUZZ_SECONDS each (default 45; 0 skips; about 3 minutes in all with the fuzz build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The ci preset sets every setting scripts/demo.sh changes (tests and benchmarks on, the
# kernels' three builds, -O3, the unity build), so the tests build what they test whatever an
# earlier demo configured in the same folder.
bash scripts/build.sh ci
ctest --preset ci "$@"
fuzz_seconds=${PRT_FUZZ_SECONDS:-45}
if ((fuzz_seconds > 0)); then bash scripts/fuzz.sh "$fuzz_seconds"; fi
