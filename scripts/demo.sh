#!/usr/bin/env bash
# Installs dependencies, builds, and runs the main job: the benchmark scene (the paper's test
# case A) rendered by a master and four emulated workers of different speeds (two at half
# speed, two at a quarter: 1.5 cores' worth, faithful on a 2-core machine), with the
# load-balancing report of the default strategy and its page (out/run.html), then a side-by-side of what balancing buys:
# scatter, hybrid, the paper's reservoir and the default on the same emulated cluster, against
# the same serial time. Outputs land in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
# Only what the demo runs: its packages and the prt executable (scripts/test.sh installs and
# builds the rest). A build directory configured before keeps its settings.
bash scripts/install-deps.sh --demo
if [[ -f build/CMakeCache.txt ]]; then
  bash scripts/build.sh release prt
else
  # No tests, no benchmarks, and the trace kernels in their baseline build only (the
  # x86-64-v3 and x86-64-v4 ones are faster, and scripts/test.sh builds them).
  # -O2 instead of -O3: a quicker build of the same pixels (no fast-math either way), a few
  # per cent slower to render. A unity build: each library's sources compiled up to 16 to a
  # file, so the heavy headers (CLI11, nlohmann's JSON, assimp) are parsed once or twice per
  # library, not once per source; the same pixels again, and well under half the compiler time.
  PRT_CMAKE_ARGS="-DPRT_BUILD_TESTS=OFF -DPRT_BUILD_BENCH=OFF -DPRT_ISA_LEVELS=
    -DCMAKE_CXX_FLAGS_RELEASE=-O2 -DCMAKE_CXX_FLAGS=-DNDEBUG
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16" bash scripts/build.sh release prt
fi
mkdir -p out
build/prt render scenes/complex.scene --case A --workers 4 --slowdown 2,2,4,4 --measure-serial \
  --report out/report.json --html out/run.html --trace out/trace.json \
  --ownership out/ownership.png -o out/complex.png "$@"
echo "wrote out/run.html (the run's page: open it in any browser, no network needed),"
echo "      out/complex.png, out/ownership.png, out/report.json, out/trace.json (Perfetto)"

# The side-by-side: one run each, the serial time from the run above.
value() { grep -o "\"$1\": *[-0-9.e+]*" "$2" | head -1 | sed 's/.*: *//'; }
serial=$(value serial_s out/report.json)
default=$(grep -o '"strategy": *"[^"]*"' out/report.json | head -1 | sed 's/.*: *"//; s/"$//')
echo
echo "case A, 4 workers --slowdown 2,2,4,4 (ideal speed-up 1.5), serial ${serial} s:"
printf '%-20s %9s %9s %11s %7s\n' strategy elapsed_s speed-up efficiency ASU
for strategy in scatter hybrid reservoir "$default"; do
  report=out/demo-$strategy.json
  build/prt render scenes/complex.scene --case A --workers 4 --slowdown 2,2,4,4 \
    --strategy "$strategy" --serial-seconds "$serial" --report "$report" \
    -o out/demo.pfm --quiet "$@"
  label=$strategy
  [ "$strategy" = "$default" ] && label="$strategy (default)"
  printf '%-20s %9.3f %9.2f %10.1f%% %6.1f%%\n' "$label" "$(value elapsed_s "$report")" \
    "$(value speedup "$report")" "$(awk -v e="$(value efficiency "$report")" 'BEGIN{print 100*e}')" \
    "$(awk -v a="$(value asu "$report")" 'BEGIN{print 100*a}')"
done
rm -f out/demo.pfm
echo "(one run each on this machine; bench/adaptive.py gives medians and ratios)"
