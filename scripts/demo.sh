#!/usr/bin/env bash
# Installs dependencies, builds, and runs the main job: the benchmark scene (the paper's test
# case A) rendered by a master and four emulated workers of different speeds (two at half
# speed, two at a quarter: 1.5 cores' worth, faithful on a 2-core machine), balanced by the
# reservoir algorithm, with the load-balancing report. Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh release
mkdir -p out
build/prt render scenes/complex.scene --case A --workers 4 --strategy reservoir \
  --slowdown 2,2,4,4 --measure-serial \
  --report out/report.json --trace out/trace.json --ownership out/ownership.png \
  -o out/complex.png "$@"
echo "wrote out/complex.png, out/ownership.png, out/report.json, out/trace.json (open in Perfetto)"
