#!/bin/sh
# Instructions a render of the benchmark scene executes, counted by callgrind: a figure that,
# unlike time, does not move with the load of a shared machine, for comparing two builds of
# the tracer (the tracer runs at about three instructions a cycle, so fewer instructions is
# mostly less time; confirm a change with interleaved timings all the same).
#
#   bench/instructions.sh [RENDER OPTIONS...]   (default: --spp 16 --drt 1 --width 160 --height 120)
#   environment: PRT=build/prt  SCENE=scenes/complex.scene  TOP=12
#
# Prints the total and the functions with the most instructions of their own. The render
# runs on one thread with the baseline build of the trace kernels (valgrind 3.19 does not
# decode every AVX instruction of the x86-64-v3 build): the counts are that build's.
# Needs valgrind (apt-get install valgrind). About 20 s at the default size.
set -eu

root=$(cd "$(dirname "$0")/.." && pwd)
prt=${PRT:-$root/build/prt}
scene=${SCENE:-$root/scenes/complex.scene}
top=${TOP:-12}
[ $# -gt 0 ] || set -- --spp 16 --drt 1 --width 160 --height 120

[ -x "$prt" ] || { echo "error: no prt binary at $prt (set PRT=...)" >&2; exit 2; }
[ -f "$scene" ] || { echo "error: no scene file $scene" >&2; exit 2; }
command -v valgrind >/dev/null 2>&1 || { echo "error: valgrind is not installed" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/prt-instructions-XXXXXX")
trap 'rm -rf "$work"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2 valgrind --tool=callgrind \
  --callgrind-out-file="$work/callgrind.out" "$prt" render "$scene" --threads 1 "$@" \
  -q -o "$work/image.pfm" 2>"$work/valgrind.txt" || {
  cat "$work/valgrind.txt" >&2
  exit 1
}
callgrind_annotate --show-percs=yes "$work/callgrind.out" >"$work/annotated.txt" 2>&1 || {
  cat "$work/annotated.txt" >&2
  exit 1
}
grep -q 'PROGRAM TOTALS' "$work/annotated.txt" || {
  echo "error: callgrind_annotate printed no totals (a format this script does not know)" >&2
  exit 1
}
echo "$(basename "$scene") $*, one thread, baseline kernels"
awk -v top="$top" '
    /PROGRAM TOTALS/ { printf "instructions: %s\n", $1; next }
    /^-+$/ { rule++; next }
    rule >= 5 && /^ *[0-9,]+ *\(/ && shown < top {
      count = $1
      rest = $0
      sub(/^ *[0-9,]+ */, "", rest)
      share = rest
      sub(/\).*/, ")", share)
      sub(/^\([^)]*\) */, "", rest)
      sub(/^[^:]*:/, "", rest)          # the file, ??? without debugging information
      sub(/ \[[^]]*\]$/, "", rest)     # the library
      if (length(rest) > 100) rest = substr(rest, 1, 97) "..."
      printf "  %14s %9s  %s\n", count, share, rest
      shown++
    }' "$work/annotated.txt"
