#!/usr/bin/env bash
# Installs dependencies, builds with warnings as errors, and runs every test (unit, end-to-end,
# MPI) through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh ci
ctest --preset ci "$@"
