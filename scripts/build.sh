#!/usr/bin/env bash
# Configures and builds PRT with a CMake preset (default: release). The executable is build/prt.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -- -j"$(nproc)"
