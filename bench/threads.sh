#!/usr/bin/env bash
# One worker rank of 2 threads against two worker ranks of 1 thread, on this machine's two
# cores: the same image under mpirun, elapsed time (the master's report) and memory (the
# largest resident set of each rank, from /usr/bin/time), RUNS rounds taken in turn.
#   RUNS=5 bench/threads.sh [PRT] [SCENE] [ARGS...]
# Default: the benchmark scene at 640x480, case A, the reservoir-scatter strategy.
set -euo pipefail
cd "$(dirname "$0")/.."
prt=${1:-build/prt}
scene=${2:-scenes/complex.scene}
shift $(($# > 2 ? 2 : $#)) || true
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--width 640 --height 480 --case A --strategy reservoir-scatter)
runs=${RUNS:-5}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
timed=(/usr/bin/time -f "%M" -a -o "$work/rss")

run() {  # layout: "1x2" or "2x1"
  : >"$work/rss"
  if [ "$1" = 1x2 ]; then
    mpirun --bind-to none -np 2 "${timed[@]}" "$prt" render "$scene" "${args[@]}" -q \
      --threads 2 -o "$work/out.pfm" --report "$work/r.json" 2>/dev/null
  else
    mpirun --bind-to none --oversubscribe -np 3 "${timed[@]}" "$prt" render "$scene" \
      "${args[@]}" -q --threads 1 -o "$work/out.pfm" --report "$work/r.json" 2>/dev/null
  fi
  elapsed=$(python3 -c "import json; print(json.load(open('$work/r.json'))['elapsed_s'])")
  # The master is the rank with the largest resident set (it holds the image).
  rss=$(sort -n "$work/rss" | awk '{a[NR]=$1} END {w=0; for (i=1;i<NR;i++) w+=a[i]; printf "%d %d", a[NR], w}')
  echo "$1 $elapsed $rss" >>"$work/results"
}

for ((i = 0; i < runs; i++)); do
  run 1x2
  run 2x1
done
python3 - "$work/results" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
by = {}
for layout, elapsed, master, workers in rows:
    by.setdefault(layout, []).append((float(elapsed), int(master), int(workers)))
for layout in ("1x2", "2x1"):
    r = by[layout]
    e = statistics.median(x[0] for x in r)
    print(f"{layout}: elapsed median {e:.3f} s (runs {', '.join(f'{x[0]:.3f}' for x in r)}), "
          f"master {statistics.median(x[1] for x in r) / 1024:.0f} MiB, "
          f"workers {statistics.median(x[2] for x in r) / 1024:.0f} MiB in all")
a = statistics.median(x[0] for x in by["1x2"])
b = statistics.median(x[0] for x in by["2x1"])
print(f"1 rank x 2 threads / 2 ranks x 1 thread: {a / b:.3f}")
PY
