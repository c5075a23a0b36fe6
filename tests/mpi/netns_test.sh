#!/bin/sh
# A render across three hosts (network namespaces on a bridge, scripts/netns-cluster.sh) over
# TCP; mid-render one host's link goes down. The run must finish with the serial image, or
# leave a checkpoint from which --resume gives it; and, run by scripts/prt-mpirun, the whole
# job must end within its bound after the image is written (PRT_MPIRUN_GRACE, 5 s here, after
# rank 0's last word, plus 2 s), although mpirun itself waits for the cut-off host's daemon for
# ever. Needs root; skipped (exit 77) otherwise.
#   netns_test.sh PRT MPIEXEC SCENE WORKDIR CLUSTER_SCRIPT WRAPPER
set -eu

prt=$1 mpiexec=$2 scene=$3 work=$4 cluster=$5 wrapper=$6
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || skip "making network namespaces needs root"
command -v ip >/dev/null || skip "no ip command (iproute2)"
command -v unshare >/dev/null || skip "no unshare command (util-linux)"
"$mpiexec" --version 2>/dev/null | grep -qiE "open ?mpi|openrte" || skip "the launch agent needs Open MPI"

rm -rf "$work"
mkdir -p "$work"
cd "$work"
hosts=$work/hosts
job=
step="making the hosts"
cleanup() {
  status=$?
  [ -n "$job" ] && { pkill -9 -P "$job" 2>/dev/null || true; kill -9 "$job" 2>/dev/null || true; }
  bash "$cluster" down "$hosts" >/dev/null 2>&1 || true
  if [ "$status" -ne 0 ] && [ "$status" -ne 77 ]; then
    echo "netns test: ended with status $status while $step" >&2
    [ -f "$work/err.txt" ] && grep -v "PMIX ERROR" "$work/err.txt" >&2
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'echo "netns test: signal received while $step" >&2; exit 1' INT TERM HUP
bash "$cluster" up 3 "$hosts" || skip "could not make the network namespaces"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
geometry="--width 64 --height 48 --spp 16 --drt 2"
step="rendering the serial image"
# shellcheck disable=SC2086
"$prt" render "$scene" $geometry -q -o serial.pfm
step="rendering across the hosts"
# Starts the run across the hosts and waits up to 30 s for its first checkpointed pixels
# (or for mpirun to give up). Scatter gives worker 1 half the image, and at 1000 times slower
# its half takes about 12 s (the serial image takes 0.03 s), so the cut below always finds it
# holding unfinished pixels, however fast the tracer; worker 0 renders them once worker 1 is
# declared lost. Two tries, each on hosts made afresh: the start of a job across namespaces
# (daemons launched through the agent, TCP set up on the bridge) has been seen to stall once
# in many runs. No speed index: at 1000 times slower its run alone would take half a minute.
start_run() {
  rm -f ck out.pfm report.json
  # shellcheck disable=SC2086,SC2046
  MPIRUN=$mpiexec PRT_MPIRUN_GRACE=5 sh "$wrapper" $(cat "$hosts/mpirun-flags") --enable-recovery \
    --hostfile "$hosts/hostfile" -np 3 \
    "$prt" render "$scene" $geometry -q --strategy scatter --speed-index none \
    --slowdown 60,1000 --batch 8 --worker-timeout 2 \
    -o out.pfm --checkpoint ck --checkpoint-every 0.1 --report report.json >out.txt 2>err.txt &
  job=$!
  for i in $(seq 1 300); do
    if [ -f ck ] && [ "$(stat -c %s ck 2>/dev/null || echo 0)" -gt 3000 ]; then return 0; fi
    # mpirun gave up before the render started (it could not start a daemon on a host):
    # the same as no progress.
    kill -0 "$job" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}
if ! start_run; then
  echo "netns test: no progress across the hosts (mpirun ended, or 30 s passed); its output:" >&2
  grep -v "PMIX ERROR" out.txt err.txt >&2 || true
  pkill -9 -P "$job" 2>/dev/null || true
  kill -9 "$job" 2>/dev/null || true
  bash "$cluster" up 3 "$hosts" >/dev/null || fail "could not make the hosts again"
  start_run || { grep -v "PMIX ERROR" err.txt >&2; fail "no progress across the hosts within 30 s, twice"; }
fi
step="cutting prt-h2 off"
bash "$cluster" link-down 2  # worker rank 2 (worker 1) is on prt-h2
step="waiting for the image without prt-h2"
echo "link of prt-h2 down"
# The master finishes the image with the hosts it can reach; mpirun itself waits for the
# cut-off host's daemon, and scripts/prt-mpirun ends it within its bound.
for i in $(seq 1 600); do
  [ -f out.pfm ] && break
  kill -0 "$job" 2>/dev/null || break
  sleep 0.1
done
image_at=$(date +%s.%N)
step="waiting for the job to end after the image"
ended=
if [ -f out.pfm ]; then
  for i in $(seq 1 600); do
    if ! kill -0 "$job" 2>/dev/null; then
      ended=$(date +%s.%N)
      break
    fi
    sleep 0.1
  done
fi
grep -v "PMIX ERROR" err.txt >&2 || true
step="checking the outcome"
if [ -f out.pfm ]; then
  cmp serial.pfm out.pfm || fail "the image differs from the serial one"
  # The report is written after the image: wait for it (10 s at most).
  for i in $(seq 1 100); do
    [ -f report.json ] && break
    sleep 0.1
  done
  [ -f report.json ] || fail "an image but no report"
  python3 - <<'PY'
import json
r = json.load(open("report.json"))
assert [l["worker"] for l in r["lost_workers"]] == [1], r["lost_workers"]
print("finished without the cut-off host; lost:", r["lost_workers"])
PY
  [ -n "$ended" ] || fail "the job had not ended 60 s after its image was written"
  after=$(awk "BEGIN { printf \"%.1f\", $ended - $image_at }")
  echo "the job ended $after s after its image was written"
  wait "$job" && code=0 || code=$?
  job=
  [ "$code" -eq 0 ] || fail "prt-mpirun exited $code after a complete image"
  awk "BEGIN { exit !($after < 20) }" || fail "the job ended $after s after its image (bound 5 s + 2 s after rank 0's last word)"
else
  [ -f ck ] || fail "neither an image nor a checkpoint"
  # shellcheck disable=SC2086
  "$prt" render "$scene" $geometry -q -o out.pfm --checkpoint ck --resume ||
    fail "resuming the checkpoint failed"
  cmp serial.pfm out.pfm || fail "the resumed image differs from the serial one"
  echo "resumed from the checkpoint"
fi
echo "ok: netns"
