#!/usr/bin/env bash
# Installs dependencies, builds with warnings as errors, runs every test (unit, end-to-end,
# MPI) through CTest, then fuzzes PRT's readers and decoders (scripts/fuzz.sh) for
# PRT_FUZZ_SECONDS each (default 30; 0 skips), one fuzzer per core.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# The ci preset sets every setting scripts/demo.sh changes (tests and benchmarks on, the
# kernels' three builds, -O3, the unity build), so the tests build what they test whatever an
# earlier demo configured in the same folder.
bash scripts/build.sh ci
ctest --preset ci "$@"
fuzz_seconds=${PRT_FUZZ_SECONDS:-30}
if ((fuzz_seconds > 0)); then bash scripts/fuzz.sh "$fuzz_seconds"; fi
