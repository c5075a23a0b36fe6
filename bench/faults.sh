#!/usr/bin/env bash
# The fault matrix: every strategy under each fault the drivers survive, for the local driver
# and MPI, with whether the run finished (or was resumed from its checkpoint), whether the
# image is the serial one bit for bit, and how long after the fault the loss was detected.
#   bench/faults.sh [PRT] [OUT.md]     (default build/prt, stdout)
# The render: fig08 at 64x48, 16 spp, DRT 2, workers 30 times slower (a few seconds), lease 2 s.
# Detection time is the master's: from the worker's last message to its WorkerLost event
# (a crash of a local thread is seen at once; the rest by the lease, so between the lease less
# one heartbeat and the lease after the fault).
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
common="$geometry -q --batch 8 --worker-timeout 2 --checkpoint $work/ck --checkpoint-every 0.1"

# shellcheck disable=SC2086
"$prt" render "$scene" $geometry -q -o "$work/serial.pfm"
strategies=$("$prt" render --help | sed -n 's/^ *\([a-z0-9-]*\) (\(static\|dynamic\|adaptive\))[:,].*/\1/p')

# Detection seconds of the first loss in a report, or "-".
detection() {
  python3 - "$1" <<'PY' 2>/dev/null || echo "-"
import json, re, sys
r = json.load(open(sys.argv[1]))
lost = r.get("lost_workers", [])
if not lost: print("none"); sys.exit()
m = re.search(r"silent for ([0-9.]+) s", lost[0]["reason"])
print(m.group(1) + " s" if m else "at once (" + lost[0]["reason"] + ")")
PY
}

wait_progress() {
  for _ in $(seq 1 300); do
    [ -f "$work/ck" ] && [ "$(stat -c %s "$work/ck")" -gt 3000 ] && return 0
    sleep 0.05
  done
  return 1
}

rank_pid() {  # worker rank $2 of mpirun $1
  for _ in $(seq 1 100); do
    for c in $(pgrep -P "$1"); do
      tr '\0' '\n' <"/proc/$c/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2" && {
        echo "$c"
        return 0
      }
    done
    sleep 0.05
  done
}

row() {  # fault driver strategy outcome
  local fault=$1 driver=$2 strategy=$3 outcome=$4 same=no
  cmp -s "$work/serial.pfm" "$work/out.pfm" && same=yes
  printf '| %s | %s | %s | %s | %s | %s |\n' "$fault" "$driver" "$strategy" "$outcome" "$same" \
    "$(detection "$work/r.json")" >>"$work/table"
}

resume() {  # the rest of a killed run, serially
  # shellcheck disable=SC2086
  "$prt" render "$scene" $geometry -q -o "$work/out.pfm" --checkpoint "$work/ck" --resume \
    && echo resumed || echo "resume failed"
}

: >"$work/table"
for s in $strategies; do
  for fault in crash hang; do
    rm -f "$work"/{out.pfm,r.json,ck}
    # shellcheck disable=SC2086
    timeout 60 "$prt" render "$scene" $common --workers 3 --slowdown 30,30,30 --strategy "$s" \
      --inject-fault 1:100:$fault -o "$work/out.pfm" --report "$work/r.json" \
      && o=finished || o="failed ($?)"
    row "injected $fault" local "$s" "$o"
  done
  rm -f "$work"/{out.pfm,r.json,ck}
  # shellcheck disable=SC2086
  "$prt" render "$scene" $common --workers 3 --slowdown 30,30,30 --strategy "$s" \
    -o "$work/out.pfm" &
  job=$!
  wait_progress
  kill -9 $job
  wait $job 2>/dev/null
  row "SIGKILL of the whole run" local "$s" "$(resume)"
  for fault in "injected crash" "injected hang" SIGKILL SIGSTOP; do
    rm -f "$work"/{out.pfm,r.json,ck}
    flags=--enable-recovery
    [ "$fault" = "injected hang" ] && flags=
    extra=
    case $fault in
      "injected crash") extra="--inject-fault 1:100:crash" ;;
      "injected hang") extra="--inject-fault 1:100:hang" ;;
    esac
    # shellcheck disable=SC2086
    timeout 90 $mpi $flags -np 4 "$prt" render "$scene" $common --slowdown 30,30,30 \
      --strategy "$s" $extra -o "$work/out.pfm" --report "$work/r.json" 2>/dev/null &
    job=$!
    if [ "$fault" = SIGKILL ] || [ "$fault" = SIGSTOP ]; then
      launcher=$(pgrep -P $job mpirun || echo $job)
      victim=$(rank_pid "$launcher" 2)
      wait_progress
      [ "$fault" = SIGKILL ] && kill -9 "$victim" || kill -STOP "$victim"
    fi
    wait $job
    code=$?
    [ -n "${victim:-}" ] && kill -9 "$victim" 2>/dev/null
    victim=
    o="exit $code"
    [ -f "$work/out.pfm" ] && o="finished, exit $code"
    row "$fault" mpi "$s" "$o"
  done
  rm -f "$work"/{out.pfm,r.json,ck}
  # shellcheck disable=SC2086
  $mpi -np 4 "$prt" render "$scene" $common --slowdown 30,30,30 --strategy "$s" \
    -o "$work/out.pfm" 2>/dev/null &
  job=$!
  wait_progress
  pkill -9 -P "$(pgrep -P $job mpirun || echo $job)" 2>/dev/null
  pkill -9 -P $job 2>/dev/null
  kill -9 $job 2>/dev/null
  wait $job 2>/dev/null
  rm -f "$work/r.json"
  row "SIGKILL of the whole run" mpi "$s" "$(resume)"
done
{
  echo "| fault | driver | strategy | outcome | image identical | loss detected after |"
  echo "|---|---|---|---|---|---|"
  cat "$work/table"
} >"$out"
