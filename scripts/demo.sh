#!/usr/bin/env bash
# Installs dependencies, builds, and runs the main job: the benchmark scene rendered in
# parallel, with the load-balancing report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
mkdir -p out
build/prt render scenes/complex.scene -o out/complex.png "$@"
