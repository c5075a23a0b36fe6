#!/usr/bin/env bash
# Wrong results, for the fault matrix: every strategy with a worker that returns corrupt pixels
# (--inject-fault W:PIXELS:corrupt: bit 20 of the red channel flipped in about half of what it
# renders), from its first pixel and after 400, on the local driver and under MPI (4 ranks,
# worker 1 with two threads there), at the default --verify 1. Each row: whether the image is
# the serial one bit for bit, who was rejected when, the pixels taken back and the pixels
# verified.
#   bench/corrupt.sh [PRT] [OUT.md]     (default build/prt, stdout)
# The render: fig08 at 64x48, 16 spp, DRT 2, three workers at full speed.
set -uo pipefail
cd "$(dirname "$0")/.."
prt=${1:-build/prt}
out=${2:-/dev/stdout}
scene=scenes/fig08-basic-features.scene
geometry="--width 64 --height 48 --spp 16 --drt 2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi="mpirun --oversubscribe"
common="$geometry -q --batch 16 --no-checkpoint"

# shellcheck disable=SC2086
"$prt" render "$scene" $geometry -q -o "$work/serial.pfm"
strategies=$("$prt" render --help | sed -n 's/^ *\([a-z0-9-]*\) (\(static\|dynamic\|adaptive\))[:,].*/\1/p')

row() {  # fault driver strategy exit-code
  local same=no
  cmp -s "$work/serial.pfm" "$work/out.pfm" && same=yes
  python3 - "$work/r.json" "$1" "$2" "$3" "$4" "$same" >>"$work/table" <<'PY'
import json, sys
path, fault, driver, strategy, code, same = sys.argv[1:]
try:
    r = json.load(open(path))
except Exception:
    print(f"| {fault} | {driver} | {strategy} | exit {code} | {same} | - | - | - |")
    sys.exit()
rej = ", ".join(f"{x['worker']} at {x['at_s']:.2f} s" for x in r["rejected_workers"]) or "none"
back = sum(x["pixels_taken_back"] for x in r["rejected_workers"])
print(f"| {fault} | {driver} | {strategy} | exit {code} | {same} | {rej} | {back} | {r['verified_pixels']} |")
PY
}

: >"$work/table"
for s in $strategies; do
  for after in 0 400; do
    rm -f "$work"/{out.pfm,r.json}
    # shellcheck disable=SC2086
    timeout 60 "$prt" render "$scene" $common --workers 3 --strategy "$s" \
      --inject-fault "1:$after:corrupt" -o "$work/out.pfm" --report "$work/r.json"
    row "corrupt after $after px" local "$s" $?
    rm -f "$work"/{out.pfm,r.json}
    set -- "$prt" render "$scene" $common --strategy "$s" --inject-fault "1:$after:corrupt" \
      -o "$work/out.pfm" --report "$work/r.json"
    # shellcheck disable=SC2086
    timeout 90 $mpi -np 2 "$@" --threads 1 : -np 1 "$@" --threads 2 : -np 1 "$@" --threads 1 \
      >/dev/null 2>&1
    row "corrupt after $after px" mpi "$s" $?
  done
done
{
  echo "| fault | driver | strategy | outcome | image identical | rejected | pixels taken back | pixels verified |"
  echo "|---|---|---|---|---|---|---|---|"
  cat "$work/table"
} >"$out"
