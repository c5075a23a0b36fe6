#!/bin/sh
# prt join across hosts under plain mpirun: the render runs on two network-namespace hosts
# (scripts/netns-cluster.sh) with --accept-workers; `prt join` on a third host reaches the
# master over TCP, with no mpirun and no ompi-server. Then a second run whose joiner is
# SIGKILLed mid-render: the render finishes without it. Needs root; skipped (77) otherwise.
#   netns_join_test.sh PRT MPIEXEC SCENE WORKDIR CLUSTER_SCRIPT
set -eu

prt=$1 mpiexec=$2 scene=$3 work=$4 cluster=$5
here=$(cd "$(dirname "$0")" && pwd)
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
cleanup() {
  status=$?
  [ -n "$job" ] && { pkill -9 -P "$job" 2>/dev/null || true; kill -9 "$job" 2>/dev/null || true; }
  bash "$cluster" down "$hosts" >/dev/null 2>&1 || true
  [ "$status" -ne 0 ] && [ "$status" -ne 77 ] && [ -f err.txt ] && grep -v "PMIX ERROR" err.txt >&2
  exit "$status"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP
bash "$cluster" up 3 "$hosts" >/dev/null || skip "could not make the network namespaces"
head -2 "$hosts/hostfile" >two-hosts
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
geometry="--width 64 --height 48 --spp 16 --drt 2"
checkpoint=
# shellcheck disable=SC2086
"$prt" render "$scene" $geometry -q -o serial.pfm

# The render on prt-h0 (master) and prt-h1 (one slow worker); returns once the port file is there.
start_render() {
  rm -f port out.pfm report.json ck
  # shellcheck disable=SC2086,SC2046
  "$mpiexec" $(cat "$hosts/mpirun-flags") --enable-recovery --hostfile two-hosts -np 2 \
    "$prt" render "$scene" $geometry -q --slowdown 600 --speed-index none --worker-timeout 2 \
    --accept-workers "$work/port" -o out.pfm --report report.json $checkpoint >out.txt 2>err.txt &
  job=$!
  for _ in $(seq 300); do [ -s port ] && return 0; sleep 0.1; done
  fail "the render wrote no port file"
}

start_render
grep -q "^tcp 10.231.0.10:" port || fail "the port file names no address of prt-h0: $(cat port)"
# On prt-h2, under its own hostname (as the launch agent starts a rank there).
on_h2() { ip netns exec prt-h2 unshare --uts sh -c 'hostname prt-h2; exec "$@"' sh "$@"; }
on_h2 timeout 60 "$prt" join "$work/port" >join.txt 2>&1 || fail "prt join: $(cat join.txt)"
wait "$job" || fail "the render failed"
job=
cmp serial.pfm out.pfm || fail "the image differs from the serial render"
python3 - <<'PY' || fail "the report does not show the joiner on prt-h2"
import json
r = json.load(open("report.json"))
joined = [w for w in r["workers"] if w["joined_at_s"] is not None]
assert len(joined) == 1 and joined[0]["host"] == "prt-h2" and joined[0]["pixels"] > 0, r["workers"]
PY

# The joiner SIGKILLed once it has rendered something (the render's checkpoint shows pixels
# of worker 1): lost (its connection closes), its pixels reissued, the image still the serial
# one. Slowed down enough that the render cannot end before the kill on a quiet machine (the
# scene takes 0.03 s on one core) and the rest takes the slow worker seconds, not minutes.
checkpoint="--checkpoint $work/ck --checkpoint-every 0.1"
start_render
# (ip, unshare and sh each exec the next: $! is prt's process.)
ip netns exec prt-h2 unshare --uts sh -c 'hostname prt-h2; exec "$@"' sh \
  "$prt" join "$work/port" --slowdown 1000 >join.txt 2>&1 &
joiner=$!
python3 "$here/../checkpoint_owner.py" ck 1 30 "$joiner" ||
  fail "the joiner rendered nothing within 30 s: $(cat join.txt)"
kill -9 "$joiner" 2>/dev/null || fail "the joiner ended before it could be killed: $(cat join.txt)"
wait "$job" || fail "the render failed after its joiner was killed"
job=
cmp serial.pfm out.pfm || fail "the image differs after the joiner was killed"
python3 - <<'PY' || fail "the report does not show the joiner lost"
import json
r = json.load(open("report.json"))
lost = [l for l in r["lost_workers"]]
assert [l["worker"] for l in lost] == [1], lost
PY
echo "ok"
