#!/bin/sh
# End-to-end tests of workers joining a running MPI render: a render started by one mpirun with
# --accept-workers, and a second, independent mpirun of `prt join`, both pointed at the same
# ompi-server (Open MPI needs one to connect two jobs).
#   join_test.sh PRT MPIEXEC SCENE WORKDIR MODE [STRATEGY [FLAG]]  (FLAG: one more for the render)
# MODE
# The workers report their slowdown as their speed index (the oracle): a Towers of Hanoi run,
# slowed down as much as the rendering, would take most of the test.
#   join      1 slow starting worker, 2 joiners mid-render: the serial image, both jobs exit 0,
#             the report says when the joiners arrived and that they rendered pixels; the port
#             file is gone at the end
#   kill      as join, with one joining process SIGKILLed once it has rendered (its job runs with
#             --enable-recovery, so its sibling carries on): the serial image, exit 0, the
#             killed joiner among the lost workers
#   stop      as kill, with SIGSTOP instead: the same, and the joining mpirun still returns
#             (its live rank's watchdog ends it once the grace period has passed)
#   starthang 1 starting worker that hangs once it has rendered (no --enable-recovery: the
#             master's job ends with MPI_Abort(0)), 2 joiners that finish the image: the
#             serial image, and the joining job too exits 0 at once (it is released before
#             the abort, not left to find the master gone)
#   stale     prt join against the port file of a render that has ended: a clear error within
#             its --connect-timeout, never a hang
#   missing   prt join of a file that does not exist: exit 2 and a message naming it
#   blocked   a starting worker returns wrong pixels and is rejected: a later prt join from
#             its machine (this one) is refused, the render ends with the serial image
#   uninvited prt join with the port but not the secret (an older port file, a copy of its
#             first line), and with a wrong secret: each refused before it gets the scene
#             (exit 1, the reason said), the render undisturbed; then an invited join finishes
#             it: the serial image, refused_joiners lists the two
set -eu

prt=$1 mpiexec=$2 scene=$3 work=$4 mode=$5 strategy=${6:-adaptive} extra=${7:-}
here=$(cd "$(dirname "$0")" && pwd)

command -v ompi-server >/dev/null 2>&1 || { echo "skipped: no ompi-server"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# One host: shared memory and TCP on loopback only.
mca="--allow-run-as-root --oversubscribe --mca btl self,vader,tcp --mca btl_tcp_if_include lo
  --mca oob_tcp_if_include lo"

rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; for f in master.err join.err; do [ -f $f ] && sed 's/^/  /' $f >&2; done; exit 1; }

server=
master=
joiner=
cleanup() {
  for p in $joiner $master; do pkill -9 -P "$p" 2>/dev/null || true; kill -9 "$p" 2>/dev/null || true; done
  [ -n "$server" ] && kill "$server" 2>/dev/null || true
}
trap cleanup EXIT

ompi-server --no-daemonize -r "$work/uri" &
server=$!
for i in $(seq 1 100); do [ -s uri ] && break; sleep 0.05; done
[ -s uri ] || fail "ompi-server wrote no URI"
uri="--ompi-server file:$work/uri"

# A render of over a minute on the one slow starting worker alone, of some 8 s once two joiners
# (slowed down too) help: long enough after a joiner is killed for its lease to run out.
size="--width 64 --height 48 --spp 8 --drt 2"
slowdown=1000
join_slowdown=250

# Waits up to $2 seconds for process $1; its exit status in $status (124: still running).
wait_for() {
  waited=0
  while kill -0 "$1" 2>/dev/null && [ "$waited" -lt $(($2 * 10)) ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
  if kill -0 "$1" 2>/dev/null; then
    status=124
  else
    set +e
    wait "$1"
    status=$?
    set -e
  fi
}

start_master() {
  # shellcheck disable=SC2086
  timeout -k 5 120 "$mpiexec" $mca $uri -np 2 "$prt" render "$scene" $size -q \
    --strategy "$strategy" $extra --speed-index slowdown --slowdown $slowdown -o mpi.pfm \
    --accept-workers "$work/port" \
    --worker-timeout 3 --report report.json --checkpoint ck --checkpoint-every 0.1 \
    ${master_extra:-} >master.out 2>master.err &
  master=$!
  for i in $(seq 1 200); do [ -s port ] && break; sleep 0.05; done
  [ -s port ] || fail "the master wrote no port file"
  [ "$(stat -c %a port)" = 600 ] || fail "the port file is readable by others: $(stat -c %a port)"
  cp port stale-port  # for the stale mode: the port of a render that will have ended
  # Some pixels first, so the joiners arrive mid-render.
  for i in $(seq 1 200); do
    [ -f ck ] && [ "$(stat -c %s ck)" -gt 200 ] && break
    sleep 0.05
  done
}

case $mode in
  join|kill|stop)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    start_master
    recovery=
    [ "$mode" != join ] && recovery=--enable-recovery
    # shellcheck disable=SC2086
    timeout -k 5 100 "$mpiexec" $mca $uri $recovery -np 2 "$prt" join "$work/port" \
      --slowdown $join_slowdown >join.out 2>join.err &
    joiner=$!
    if [ "$mode" != join ]; then
      # The first joining process, once it has rendered a little (the master's report will
      # name it): killed for real.
      victim=
      for i in $(seq 1 100); do
        for child in $(pgrep -P "$joiner" 2>/dev/null); do
          for grandchild in $child $(pgrep -P "$child" 2>/dev/null); do
            if tr '\0' '\n' <"/proc/$grandchild/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=0"; then
              victim=$grandchild
            fi
          done
        done
        [ -n "$victim" ] && break
        sleep 0.05
      done
      [ -n "$victim" ] || fail "the joining rank never started"
      # Once the checkpoint holds pixels it rendered (it is worker 1, the first joiner).
      python3 "$here/../checkpoint_owner.py" ck 1 30 "$victim" ||
        fail "the first joiner rendered nothing within 30 s"
      if [ "$mode" = kill ]; then kill -9 "$victim"; else kill -STOP "$victim"; fi
    fi
    wait_for "$master" 100
    master_status=$status
    wait_for "$joiner" 60
    joined=$status
    [ -n "${victim:-}" ] && kill -9 "$victim" 2>/dev/null || true
    status=$master_status
    [ "$status" -eq 0 ] || fail "the render exited with $status"
    if [ "$mode" = join ]; then
      [ "$joined" -eq 0 ] || fail "prt join exited with $joined"
    else
      [ "$joined" -ne 124 ] || fail "prt join never returned after one of its ranks was killed"
    fi
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one"
    [ ! -e port ] || fail "the port file was left behind"
    python3 - "$mode" <<'PY'
import json, sys
mode = sys.argv[1]
r = json.load(open("report.json"))
w = r["workers"]
assert len(w) == 3, [x["worker"] for x in w]
assert w[0]["joined_at_s"] is None, w[0]
assert [j["worker"] for j in r["joined_workers"]] == [1, 2], r["joined_workers"]
for j in w[1:]:
    assert 0 < j["joined_at_s"] < r["elapsed_s"], j
assert sum(x["pixels"] for x in w) >= 64 * 48, "every pixel at least once"
if mode == "join":
    assert sum(x["pixels"] for x in w) == 64 * 48, "every pixel exactly once"
    assert all(x["pixels"] > 0 for x in w[1:]), [x["pixels"] for x in w]
    assert r["lost_workers"] == [], r["lost_workers"]
else:
    lost = [l["worker"] for l in r["lost_workers"]]
    assert lost == [1], lost  # its own times were lost with it, its unfinished pixels reissued
    # Its unfinished pixels were reissued, unless it was killed between two batches, holding
    # none (on a loaded machine, or near the end); the image above says nothing was lost.
    assert w[2]["pixels"] > 0, w[2]
PY
    ;;
  starthang)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    master_extra="--inject-fault 0:40:hang"
    start_master
    # shellcheck disable=SC2086
    timeout -k 5 100 "$mpiexec" $mca $uri -np 2 "$prt" join "$work/port" \
      --slowdown $join_slowdown >join.out 2>join.err &
    joiner=$!
    wait_for "$master" 100
    [ "$status" -eq 0 ] || fail "the render exited with $status"
    ended=$(date +%s)
    wait_for "$joiner" 60
    [ "$status" -eq 0 ] || fail "prt join exited with $status after the render ended"
    [ $(($(date +%s) - ended)) -lt 10 ] || fail "prt join took $(($(date +%s) - ended)) s to end after the render"
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one"
    python3 - <<'PY'
import json
r = json.load(open("report.json"))
assert [l["worker"] for l in r["lost_workers"]] == [0], r["lost_workers"]
assert [j["worker"] for j in r["joined_workers"]] == [1, 2], r["joined_workers"]
PY
    ;;
  stale)
    slowdown=20  # no joiner comes: a short render
    start_master
    wait_for "$master" 100
    [ "$status" -eq 0 ] || fail "the render exited with $status"
    started=$(date +%s)
    set +e
    # shellcheck disable=SC2086
    timeout -k 5 60 "$mpiexec" $mca $uri -np 1 "$prt" join "$work/stale-port" \
      --connect-timeout 3 >join.out 2>join.err
    status=$?
    set -e
    elapsed=$(($(date +%s) - started))
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "prt join of a stale port exited with $status"
    [ "$elapsed" -lt 30 ] || fail "prt join took $elapsed s to give up"
    grep -q "could not reach the render's master" join.err || fail "no clear message"
    ;;
  blocked)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    # shellcheck disable=SC2086
    timeout -k 5 120 "$mpiexec" $mca $uri -np 3 "$prt" render "$scene" $size -q \
      --speed-index slowdown --slowdown 1,1000 --batch 8 --verify 10 --inject-fault 0:0:corrupt \
      -o mpi.pfm --accept-workers "$work/port" --report report.json >master.out 2>master.err &
    master=$!
    for i in $(seq 1 200); do [ -s port ] && break; sleep 0.05; done
    [ -s port ] || fail "the master wrote no port file"
    # Worker 0 is caught at its first checked batch; worker 1, 1000 times slower, then needs
    # several seconds for the rest (at 200 times slower the render could end, under load,
    # before the joining job had started). The join comes 3 s in: with 1 s, under the load of
    # the whole suite, worker 0's first check once came after the joiner had been admitted.
    sleep 3
    set +e
    # shellcheck disable=SC2086
    timeout -k 5 60 "$mpiexec" $mca $uri -np 1 "$prt" join "$work/port" >join.out 2>join.err
    status=$?
    set -e
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "prt join exited with $status"
    grep -q "had a worker rejected earlier in this run" join.err || fail "not refused as blocked"
    wait_for "$master" 100
    [ "$status" -eq 0 ] || fail "the render exited with $status"
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one"
    python3 - <<'PY'
import json
r = json.load(open("report.json"))
assert [x["worker"] for x in r["rejected_workers"]] == [0], r["rejected_workers"]
assert r["rejected_workers"][0]["host"], r["rejected_workers"]
assert len(r["refused_joiners"]) == 1 and "rejected earlier" in r["refused_joiners"][0]["reason"]
PY
    ;;
  uninvited)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    start_master
    head -n 1 port >no-secret
    { head -n 1 port; echo "secret $(printf '%064d' 7)"; } >wrong-secret
    for file in no-secret wrong-secret; do
      set +e
      # shellcheck disable=SC2086
      timeout -k 5 60 "$mpiexec" $mca $uri -np 1 "$prt" join "$work/$file" \
        --slowdown $join_slowdown >join.out 2>join.err
      status=$?
      set -e
      [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "$file: prt join exited with $status"
      grep -q "the render refused this job: it did not prove it was invited" join.err ||
        fail "$file: no reason given"
    done
    kill -0 "$master" 2>/dev/null || fail "the render ended when refusing joiners"
    # shellcheck disable=SC2086
    timeout -k 5 100 "$mpiexec" $mca $uri -np 2 "$prt" join "$work/port" \
      --slowdown $join_slowdown >join.out 2>join.err &
    joiner=$!
    wait_for "$master" 100
    [ "$status" -eq 0 ] || fail "the render exited with $status"
    wait_for "$joiner" 60
    [ "$status" -eq 0 ] || fail "the invited prt join exited with $status"
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one"
    python3 - <<'PY'
import json
r = json.load(open("report.json"))
refused = r["refused_joiners"]
assert len(refused) == 2, refused
assert all("did not prove it was invited" in x["reason"] for x in refused), refused
assert [j["worker"] for j in r["joined_workers"]] == [1, 2], r["joined_workers"]
PY
    ;;
  missing)
    set +e
    # shellcheck disable=SC2086
    timeout -k 5 60 "$mpiexec" $mca $uri -np 2 "$prt" join "$work/no-such-port" \
      >join.out 2>join.err
    status=$?
    set -e
    [ "$status" -eq 2 ] || fail "expected exit code 2, got $status"
    grep -q "no-such-port' holds no port name" join.err || fail "no message naming the file"
    [ "$(grep -c "holds no port name" join.err)" -eq 1 ] || fail "error reported more than once"
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
echo "ok: $mode $strategy"
