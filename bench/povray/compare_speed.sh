#!/bin/sh
# PRT against POV-Ray 3.7 on one thread: the time each takes to render scenes/complex.scene.
#
#   bench/povray/compare_speed.sh [SPP...]          (default: 1 16)
#   environment: PRT=build/prt  WIDTH=640  HEIGHT=480  RUNS=3  SCENE=scenes/complex.scene
#
# How it is measured, for each SPP:
#   PRT      prt render SCENE --threads 1 --spp SPP --drt 1 --width W --height H -q -o prt.png
#            (one thread; one shadow ray per light with extent and one perturbed ray per glossy
#            or blurry hit, as DRT 1 defines)
#   POV-Ray  prt export SCENE --spp SPP --drt 1 --area-grid 1 ..., then the povray command line
#            written into the exported file's header plus +WT1 (one render thread): no display,
#            no jitter, sRGB PNG; antialiasing off for SPP 1, otherwise non-adaptive method 1 at
#            threshold 0, +R n with n*n + 1 samples per pixel closest to SPP (16 -> 4x4 + 1 =
#            17 samples, 6 % more than PRT's 16). --area-grid 1 makes each light with extent a
#            point light at its centre: one shadow ray per light, as PRT's DRT 1, so both spend
#            about the same number of rays (POV-Ray has no glossy reflection: it traces one
#            mirror ray where PRT traces one perturbed ray).
#   Timing   hyperfine --warmup 1 --runs RUNS, the median wall-clock time of each whole
#            process (start-up, parsing, rendering, PNG writing); without hyperfine, the median
#            of RUNS runs timed with date. Also reported: each renderer's own figure for the
#            rendering alone (PRT's summary line, POV-Ray's "Trace Time"), the median of RUNS
#            more runs, the two renderers taking turns.
#   Ratio    PRT/POV-Ray speed = POV-Ray's time / PRT's time (above 1: PRT is faster).
# Nothing is written outside a temporary directory, which is removed at the end.
set -eu

root=$(cd "$(dirname "$0")/../.." && pwd)
prt=${PRT:-$root/build/prt}
scene=${SCENE:-$root/scenes/complex.scene}
width=${WIDTH:-640}
height=${HEIGHT:-480}
runs=${RUNS:-3}
[ $# -gt 0 ] || set -- 1 16

case $prt in /*) ;; *) prt=$(pwd)/$prt ;; esac
case $scene in /*) ;; *) scene=$(pwd)/$scene ;; esac
[ -x "$prt" ] || { echo "error: no prt binary at $prt (set PRT=...)" >&2; exit 2; }
[ -f "$scene" ] || { echo "error: no scene file $scene" >&2; exit 2; }
command -v povray >/dev/null 2>&1 || { echo "error: povray is not installed" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/prt-povray-bench-XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM
cd "$work"

# Median of the numbers on stdin.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# Median wall-clock seconds of running "$1" (a shell command) $runs times, after one warm-up.
time_command() {
  if command -v hyperfine >/dev/null 2>&1; then
    hyperfine --style none --warmup 1 --runs "$runs" --export-csv timing.csv "$1" \
      >/dev/null 2>>hyperfine-warnings.txt
    # CSV columns: command,mean,stddev,median,user,system,min,max
    awk -F, 'NR == 2 { print $4 }' timing.csv
  else
    sh -c "$1"
    i=0
    while [ $i -lt "$runs" ]; do
      start=$(date +%s.%N)
      sh -c "$1"
      end=$(date +%s.%N)
      echo "$end - $start" | awk '{ print $1 - $3 }'
      i=$((i + 1))
    done | median
  fi
}

timer=date
command -v hyperfine >/dev/null 2>&1 && timer="hyperfine $(hyperfine --version | awk '{print $2}')"
echo "scene $(basename "$scene"), ${width}x${height}, one thread each, median of $runs runs ($timer)"
echo "$(povray --version 2>&1 | grep -m1 '^POV-Ray'); $("$prt" --version) at $prt"
printf '%-5s %-10s %-10s %-10s %-12s %-12s %-10s\n' spp "PRT s" "POV s" "PRT/POV" \
  "PRT trace s" "POV trace s" "PRT/POV"

for spp in "$@"; do
  "$prt" export "$scene" --spp "$spp" --drt 1 --area-grid 1 --width "$width" --height "$height" \
    -q -o complex.pov
  pov_command="$(sed -n 's|^//   povray |povray |p' complex.pov) +WT1"
  prt_command="'$prt' render '$scene' --threads 1 --spp $spp --drt 1 --width $width --height $height -q -o prt.png"

  prt_wall=$(time_command "$prt_command")
  pov_wall=$(time_command "$pov_command >/dev/null 2>&1")

  # The renderers' own figures for the rendering alone: medians of $runs more runs, PRT and
  # POV-Ray taking turns so that a change in the machine's load falls on both.
  : >prt-trace.txt
  : >pov-trace.txt
  i=0
  while [ $i -lt "$runs" ]; do
    "$prt" render "$scene" --threads 1 --spp "$spp" --drt 1 --width "$width" --height "$height" \
      -o prt.png | sed -n 's/.* DRT [0-9]*, \([0-9.]*\) s,.*/\1/p' >>prt-trace.txt
    sh -c "$pov_command" 2>&1 | sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' >>pov-trace.txt
    i=$((i + 1))
  done
  prt_trace=$(median <prt-trace.txt)
  pov_trace=$(median <pov-trace.txt)

  printf '%-5s %-10.3f %-10.3f %-10.2f %-12.3f %-12.3f %-10.2f\n' "$spp" "$prt_wall" "$pov_wall" \
    "$(echo "$pov_wall $prt_wall" | awk '{ print $1 / $2 }')" "$prt_trace" "$pov_trace" \
    "$(echo "$pov_trace $prt_trace" | awk '{ print $1 / $2 }')"
done
echo "PRT/POV = POV-Ray's time / PRT's time: how many times faster PRT is (below 1: slower)."
if [ -s hyperfine-warnings.txt ]; then
  echo "note: hyperfine saw statistical outliers (a busy machine?); re-run for firmer figures."
fi
