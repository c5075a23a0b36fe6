#!/usr/bin/env bash
# Configures and builds PRT with a CMake preset (default: release). The executable is build/prt.
#   scripts/build.sh [PRESET [TARGET...]]   e.g. scripts/build.sh release prt: the command alone
# Extra CMake settings may come in PRT_CMAKE_ARGS (e.g. "-DPRT_BUILD_TESTS=OFF").
set -euo pipefail
cd "$(dirname "$0")/.."
preset=${1:-release}
shift || true
# shellcheck disable=SC2086
cmake --preset "$preset" ${PRT_CMAKE_ARGS:-} >/dev/null
if (($# > 0)); then
  cmake --build --preset "$preset" --target "$@" -- -j"$(nproc)"
else
  cmake --build --preset "$preset" -- -j"$(nproc)"
fi
