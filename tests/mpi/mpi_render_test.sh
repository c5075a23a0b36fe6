#!/bin/sh
# End-to-end tests of `prt render` under mpirun.
#   mpi_render_test.sh PRT MPIEXEC SCENE WORKDIR MODE NP [ARG]
# MODE
#   image STRATEGY  the image is byte-identical to the serial render of the same scene
#   report [FLAG]   --report JSON has the run's measures and one entry per worker (with FLAG,
#                   e.g. --speed-index=probe, added to the command line)
#   fault KIND      --inject-fault 1:0:KIND: the master finishes the image without worker 1
#                   (hang: without --enable-recovery; crash: with it), exit code 0
#   crash-checkpoint  an injected crash without --enable-recovery ends the job; the
#                   checkpoint it leaves gives the serial image with --resume
#   kill            SIGKILL of a worker rank's process mid-render, under --enable-recovery:
#                   the serial image, exit code 0
#   kill-plain      SIGKILL of a worker rank's process mid-render under plain mpirun (no
#                   --enable-recovery, which ends the whole job a second later) with the
#                   automatic checkpoint: it is on disk before the kill, and --resume gives
#                   the serial image from it
#   stop            SIGSTOP of a worker rank's process mid-render, under --enable-recovery:
#                   the serial image; mpirun ends within the grace period
#   resume          SIGKILL of the whole job (mpirun and every rank) mid-render; --resume
#                   under mpirun gives the serial image
#   threads STRATEGY  ranks rendering with 1 and 2 threads mixed (mpirun's MPMD form):
#                   byte-identical to the serial render, and the report gives each worker's
#                   thread count
#   singleton       one rank is refused with a clear message
#   slowdown        a --slowdown list not matching the worker count is refused
#   sequence STRATEGY  an animated scene as one job (--frames 0-6:2): every frame written is
#                   byte-identical to the same --frame rendered serially
#   sequence-resume SIGKILL of the whole job of a sequence mid-render; --resume gives every
#                   frame of the serial render
#   startup-kill    SIGKILL of worker rank 2 the moment it appears (inside MPI start-up), three
#                   times, with and without --enable-recovery: every rank ends within
#                   --startup-timeout (5 s) plus a margin, exit code 1 through
#                   scripts/prt-mpirun (ARG), and a checkpoint from before is kept unchanged
#   exit-codes      under --enable-recovery through scripts/prt-mpirun (ARG): a missing
#                   scene 2, every worker lost 1, the master killed mid-render non-zero,
#                   prt join with a missing or stale port file 2 and 1, success 0
#   corrupt         workers that return wrong pixels (--inject-fault W:PIXELS:corrupt), a
#                   threaded rank among them (mpirun's MPMD form), early and late, one and two:
#                   each is rejected and no other, and the image is the serial one
#   changing        the default (adaptive) strategy with a worker slowing down part-way
#                   (--slowdown-at): the image is still the serial one
set -eu

prt=$1 mpiexec=$2 scene=$3 work=$4 mode=$5 np=$6 arg=${7:-}

# Open MPI refuses to run as root and to start more ranks than cores unless told to.
launcher_flags=
if "$mpiexec" --version 2>/dev/null | grep -qiE "open ?mpi|openrte|open-mpi"; then
  launcher_flags="--allow-run-as-root --oversubscribe"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1
fi

rm -rf "$work"
mkdir -p "$work"
cd "$work"

size="--width 24 --height 18 --spp 2"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Runs prt under mpirun with a hard time limit, so a hang fails the test instead of stalling
# the suite; stdout and stderr go to out.txt and err.txt.
mpi_prt() {
  set +e
  # shellcheck disable=SC2086
  timeout -k 5 90 "$mpiexec" $launcher_flags -np "$np" "$prt" render "$scene" ${geometry:-$size} \
    -q "$@" >out.txt 2>err.txt
  status=$?
  set -e
  cat out.txt
  cat err.txt >&2
  return 0
}

# Starts prt under mpirun in the background (pid in $job), output to out.txt and err.txt.
mpi_prt_background() {
  # shellcheck disable=SC2086
  "$mpiexec" $launcher_flags "$@" >out.txt 2>err.txt &
  job=$!
}

# Waits up to $1 seconds for the background job; its exit status in $status (124: still
# running, then killed with everything it started).
wait_job() {
  limit=$1
  waited=0
  while kill -0 "$job" 2>/dev/null && [ "$waited" -lt $((limit * 10)) ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
  if kill -0 "$job" 2>/dev/null; then
    kill_job
    status=124
  else
    set +e
    wait "$job"
    status=$?
    set -e
  fi
  cat err.txt >&2
}

kill_job() {
  pkill -9 -P "$job" 2>/dev/null || true
  kill -9 "$job" 2>/dev/null || true
  wait "$job" 2>/dev/null || true
}

# The pid of worker rank $1 of the background job (a child of mpirun), once it is running.
rank_pid() {
  for i in $(seq 1 100); do
    for child in $(pgrep -P "$job" 2>/dev/null); do
      if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1"; then
        echo "$child"
        return 0
      fi
    done
    sleep 0.05
  done
  return 1
}

# Waits until the first results have reached the master (its report counts them in the
# checkpoint's size: header and runs come first), at most 20 s.
wait_for_progress() {
  for i in $(seq 1 200); do
    [ -f "$1" ] && [ "$(stat -c %s "$1")" -gt "$2" ] && return 0
    sleep 0.1
  done
  return 1
}

# A render of a few seconds on slow workers (the more workers, the slower each), so a fault
# can strike mid-render.
slow="--width 64 --height 48 --spp 16 --drt 2"
slowdowns() { seq -s, 1 $((np - 1)) | sed "s/[0-9][0-9]*/$((30 * (np - 1)))/g"; }

case $mode in
  image)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    mpi_prt --strategy "$arg" --batch 16 -o mpi.pfm
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    cmp serial.pfm mpi.pfm || fail "the MPI image differs from the serial one"
    ;;
  sequence)
    frames="0 2 4 6"
    for f in $frames; do
      # shellcheck disable=SC2086
      "$prt" render "$scene" $size -q --fps 4 --frame "$f" -o "serial_$f.pfm"
    done
    mpi_prt --strategy "$arg" --batch 16 --fps 4 --frames 0-6:2 -o "mpi_#.pfm" --report r.json
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    for f in $frames; do
      cmp "serial_$f.pfm" "mpi_$f.pfm" || fail "frame $f under MPI differs from the serial one"
    done
    cmp -s serial_0.pfm serial_6.pfm && fail "frames 0 and 6 are the same: nothing moved"
    python3 - <<'PY'
import json
r = json.load(open("r.json"))
assert [f["frame"] for f in r["frames"]] == [0, 2, 4, 6], r["frames"]
assert sum(f["pixels"] for f in r["frames"]) == 4 * 24 * 18, r["frames"]
PY
    ;;
  sequence-resume)
    geometry="--width 48 --height 36 --spp 2"
    # shellcheck disable=SC2086
    "$prt" render "$scene" $geometry -q --fps 4 --frames 0-7 -o "serial_#.pfm"
    # shellcheck disable=SC2086
    mpi_prt_background -np "$np" "$prt" render "$scene" $geometry -q --fps 4 --frames 0-7 \
      --slowdown "$(slowdowns)" --batch 8 -o "mpi_#.pfm" --checkpoint ck --checkpoint-every 0.1
    wait_for_progress ck 2000 || { kill_job; fail "no progress within 20 s"; }
    kill_job
    geometry="$geometry" mpi_prt --batch 16 --fps 4 --frames 0-7 -o "mpi_#.pfm" --checkpoint ck \
      --resume
    [ "$status" -eq 0 ] || fail "the resumed run exited with $status"
    for f in 0 1 2 3 4 5 6 7; do
      cmp "serial_$f.pfm" "mpi_$f.pfm" || fail "frame $f of the resumed job differs"
    done
    [ ! -f ck ] || fail "the checkpoint was left behind"
    ;;
  changing)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    slow=$(python3 -c "print(','.join(['1'] * ($np - 1)))")
    mpi_prt --slowdown "$slow" --slowdown-at 0:0:3,0:0.05:6 --batch 16 -o mpi.pfm \
      --report report.json
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    cmp serial.pfm mpi.pfm || fail "the MPI image differs from the serial one"
    grep -q '"masu_basis": "measured_throughput"' report.json ||
      fail "no speed index ran, yet the MASU is not from measured throughput"
    ;;
  report)
    # shellcheck disable=SC2086
    mpi_prt --strategy reservoir --batch 16 -o mpi.pfm --report report.json --trace trace.json $arg
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    python3 - "$((np - 1))" <<'PY'
import json, sys
workers = int(sys.argv[1])
r = json.load(open("report.json"))
for key in ("elapsed_s", "efficiency", "masu", "messages", "bytes", "rays", "workers",
            "non_finite_samples"):
    assert key in r, "missing " + key
assert r["driver"] == "mpi", r["driver"]
assert r["non_finite_samples"] == 0, r["non_finite_samples"]
assert r["elapsed_s"] > 0 and 0 < r["efficiency"] <= 1.0 + 1e-9, r
assert r["masu"] > 0 and r["messages"] > 0 and r["rays"] > 0, r
assert len(r["workers"]) == workers, len(r["workers"])
assert sum(w["pixels"] for w in r["workers"]) == 24 * 18, "every pixel exactly once"
for w in r["workers"]:
    assert w["speed_index_s"] > 0 and w["messages_sent"] > 0 and w["busy_s"] > 0, w
    assert w["busy_s"] <= r["elapsed_s"] * 1.05 + 0.01, ("busy beyond the run", w)
    assert not w["lost"], w
trace = json.load(open("trace.json"))
assert trace, "empty trace"
PY
    ;;
  fault)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    recovery=
    [ "$arg" = crash ] && recovery=--enable-recovery
    start=$(date +%s)
    # shellcheck disable=SC2086
    set +e
    timeout -k 5 90 "$mpiexec" $launcher_flags $recovery -np "$np" "$prt" render "$scene" $size -q \
      --strategy reservoir --batch 16 -o mpi.pfm --inject-fault "1:0:$arg" --worker-timeout 2 \
      --report report.json >out.txt 2>err.txt
    status=$?
    set -e
    cat err.txt >&2
    elapsed=$(($(date +%s) - start))
    [ "$status" -eq 0 ] || fail "a run losing a $arg worker exited with $status"
    [ "$elapsed" -lt 60 ] || fail "the run took $elapsed s"
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one"
    grep -q "injected $arg" err.txt || fail "the worker did not report its injected $arg"
    python3 - <<'PY'
import json
r = json.load(open("report.json"))
lost = r["lost_workers"]
assert [l["worker"] for l in lost] == [1], lost
assert r["workers"][1]["lost"], r["workers"][1]
assert r["reissued_tasks"] > 0, r["reissued_tasks"]
PY
    ;;
  corrupt)
    geometry="--width 48 --height 36 --spp 2"
    # shellcheck disable=SC2086
    "$prt" render "$scene" $geometry -q -o serial.pfm
    for faults in "1:0:corrupt" "0:300:corrupt 2:0:corrupt"; do
      set -- "$prt" render "$scene" $geometry -q --batch 16 --verify 10 -o mpi.pfm \
        --report report.json
      for f in $faults; do set -- "$@" --inject-fault "$f"; done
      set +e
      # Rank 0 (the master) and worker 0 with one thread, workers 1 and 2 with two.
      # shellcheck disable=SC2086
      timeout -k 5 90 "$mpiexec" $launcher_flags -np 2 "$@" --threads 1 : -np $((np - 2)) "$@" \
        --threads 2 >out.txt 2>err.txt
      status=$?
      set -e
      cat err.txt >&2
      [ "$status" -eq 0 ] || fail "$faults: mpirun exited with $status"
      cmp serial.pfm mpi.pfm || fail "$faults: the image differs from the serial one"
      python3 - "$faults" <<'PY'
import json, sys
r = json.load(open("report.json"))
got = sorted(x["worker"] for x in r["rejected_workers"])
faults = sys.argv[1].split()
# An early fault is always caught; worker 0's late one only if it rendered past 300 pixels.
early = sorted(int(f.split(":")[0]) for f in faults if f.split(":")[1] == "0")
late = [int(f.split(":")[0]) for f in faults if f.split(":")[1] != "0"]
assert got == early or got == sorted(early + late), (got, faults, r["rejected_workers"])
assert r["verified_pixels"] > 0
assert all(x["pixels_taken_back"] >= 0 and "spot check" in x["reason"] for x in r["rejected_workers"])
PY
    done
    ;;
  crash-checkpoint)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    set +e
    # shellcheck disable=SC2086
    timeout -k 5 90 "$mpiexec" $launcher_flags -np "$np" "$prt" render "$scene" $size -q \
      --strategy self --chunk 8 --batch 8 -o mpi.pfm --inject-fault "1:40:crash" \
      --slowdown 4,4 --checkpoint ck --checkpoint-every 0.05 >out.txt 2>err.txt
    status=$?
    set -e
    cat err.txt >&2
    [ "$status" -ne 0 ] || fail "without --enable-recovery a crashed rank should end the job"
    [ ! -f mpi.pfm ] || fail "a failed run wrote an image"
    [ -f ck ] || fail "no checkpoint was left"
    mpi_prt --strategy reservoir --batch 16 -o mpi.pfm --checkpoint ck --resume --report r.json
    [ "$status" -eq 0 ] || fail "the resumed run exited with $status"
    cmp serial.pfm mpi.pfm || fail "the resumed image differs from the serial one"
    [ ! -f ck ] || fail "the checkpoint was not removed after the image was written"
    ;;
  kill|stop|kill-threaded)
    threads=
    if [ "$mode" = kill-threaded ]; then threads="--threads 2"; mode=kill; fi
    # shellcheck disable=SC2086
    "$prt" render "$scene" $slow -q -o serial.pfm
    start=$(date +%s)
    # shellcheck disable=SC2086
    mpi_prt_background --enable-recovery -np "$np" "$prt" render "$scene" $slow -q \
      --strategy "${arg:-reservoir}" --slowdown "$(slowdowns)" \
      --batch 8 -o mpi.pfm --worker-timeout 2 --report report.json --checkpoint ck \
      --checkpoint-every 0.1 $threads
    victim=$(rank_pid 2) || { kill_job; fail "worker rank 2 never started"; }
    wait_for_progress ck 200 || { kill_job; fail "no progress within 20 s"; }
    if [ "$mode" = kill ]; then kill -9 "$victim"; else kill -STOP "$victim"; fi
    wait_job 80
    kill -9 "$victim" 2>/dev/null || true
    elapsed=$(($(date +%s) - start))
    cmp serial.pfm mpi.pfm || fail "the image differs from the serial one (exit $status)"
    if [ "$mode" = kill ]; then
      [ "$status" -eq 0 ] || fail "a run surviving a killed rank exited with $status"
    else
      [ "$status" -ne 124 ] || fail "mpirun never returned after a stopped rank"
    fi
    [ "$elapsed" -lt 70 ] || fail "the run took $elapsed s"
    python3 - <<'PY'
import json
r = json.load(open("report.json"))
assert [l["worker"] for l in r["lost_workers"]] == [1], r["lost_workers"]
PY
    ;;
  kill-plain)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $slow -q -o serial.pfm
    # shellcheck disable=SC2086
    mpi_prt_background -np "$np" "$prt" render "$scene" $slow --strategy reservoir \
      --slowdown "$(slowdowns)" --batch 8 -o mpi.pfm --checkpoint-every 0.2
    victim=$(rank_pid 2) || { kill_job; fail "worker rank 2 never started"; }
    wait_for_progress mpi.pfm.ckpt 200 ||
      { kill_job; fail "no automatic checkpoint on disk within 20 s (or the run ended: $(ls))"; }
    kill -9 "$victim"
    wait_job 60
    [ "$status" -ne 0 ] && [ "$status" -ne 124 ] || fail "mpirun exited with $status"
    [ ! -f mpi.pfm ] || fail "the run wrote its image before the kill; make it slower"
    [ -f mpi.pfm.ckpt ] || fail "no checkpoint after the job was ended"
    if grep -q "none is saved yet" err.txt; then fail "a checkpoint on disk said to be none"; fi
    geometry=$slow mpi_prt --strategy reservoir --batch 16 -o mpi.pfm --resume --report r.json
    [ "$status" -eq 0 ] || fail "the resumed run exited with $status"
    cmp serial.pfm mpi.pfm || fail "the resumed image differs from the serial one"
    [ ! -f mpi.pfm.ckpt ] || fail "the checkpoint was not removed after the image was written"
    python3 - <<'PY'
import json
r = json.load(open("r.json"))
assert r["resumed_pixels"] > 0, r["resumed_pixels"]
PY
    ;;
  startup-kill)
    export MPIRUN="$mpiexec"
    echo "not a checkpoint of this render" >ck
    before=$(md5sum ck)
    for recovery in --enable-recovery ""; do
      for attempt in 1 2 3; do
        start=$(date +%s)
        # shellcheck disable=SC2086
        "$arg" $launcher_flags $recovery -np "$np" "$prt" render "$scene" $size -q -o mpi.pfm \
          --startup-timeout 5 --checkpoint ck >out.txt 2>err.txt &
        job=$!
        victim=
        for i in $(seq 1 2000); do
          for child in $(pgrep -P "$job" 2>/dev/null) $(pgrep -P "$(pgrep -P "$job" | head -1)" 2>/dev/null); do
            if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=2"; then
              kill -9 "$child" && victim=$child
              break
            fi
          done
          [ -n "$victim" ] && break
          sleep 0.002
        done
        [ -n "$victim" ] || { kill_job; fail "rank 2 never appeared"; }
        wait_job 40
        elapsed=$(($(date +%s) - start))
        [ "$status" -ne 124 ] || fail "a rank killed at start-up ($recovery, try $attempt): the job hung"
        [ "$status" -ne 0 ] || fail "a rank killed at start-up ($recovery, try $attempt): exit 0"
        [ "$elapsed" -lt 30 ] || fail "the job took $elapsed s to end"
        [ ! -f mpi.pfm ] || fail "an image was written"
        [ "$(md5sum ck)" = "$before" ] || fail "the checkpoint was changed"
        sleep 0.5
        pgrep -f -- "--startup-timeout 5 --checkpoint ck" >/dev/null && fail "ranks were left running"
        echo "startup kill ($recovery, try $attempt): exit $status after $elapsed s"
      done
    done
    ;;
  exit-codes)
    export MPIRUN="$mpiexec"
    launch() {
      set +e
      # shellcheck disable=SC2086
      timeout -k 5 90 "$arg" $launcher_flags --enable-recovery "$@" >out.txt 2>err.txt
      status=$?
      set -e
    }
    # shellcheck disable=SC2086
    launch -np "$np" "$prt" render "$scene" $size -q -o mpi.pfm
    [ "$status" -eq 0 ] || fail "a good render: exit $status"
    launch -np "$np" "$prt" render missing.scene -q -o mpi.pfm
    [ "$status" -eq 2 ] || fail "a missing scene: exit $status, not 2"
    faults=
    for w in $(seq 0 $((np - 2))); do faults="$faults --inject-fault $w:0:crash"; done
    # shellcheck disable=SC2086
    launch -np "$np" "$prt" render "$scene" $size -q -o lost.pfm $faults --worker-timeout 1
    [ "$status" -eq 1 ] || fail "every worker lost: exit $status, not 1"
    [ ! -f lost.pfm ] || fail "every worker lost, yet an image"
    launch -np 2 "$prt" join missing.port
    [ "$status" -eq 2 ] || fail "join with a missing port file: exit $status, not 2"
    echo "tag#0\$port#1234\$description#nobody:tcp://127.0.0.1:9" >stale.port
    launch -np 2 "$prt" join stale.port --connect-timeout 2
    [ "$status" -ne 0 ] || fail "join with a stale port file: exit 0"
    # The master killed mid-render: no image, and not success. On a loaded machine the master
    # can end on its own between being found and being killed (its workers' leases ran out):
    # then the scenario is tried again, up to three times.
    attempt=1
    while :; do
      rm -f killed.pfm ck
      # shellcheck disable=SC2086
      "$arg" $launcher_flags --enable-recovery -np "$np" "$prt" render "$scene" $slow -q \
        --slowdown "$(slowdowns)" --batch 8 -o killed.pfm --checkpoint ck --checkpoint-every 0.1 \
        >out.txt 2>err.txt &
      job=$!
      wait_for_progress ck 200 || { kill_job; fail "no progress within 20 s"; }
      master=
      for child in $(pgrep -P "$(pgrep -P "$job" | head -1)" 2>/dev/null) $(pgrep -P "$job"); do
        if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=0"; then
          master=$child
        fi
      done
      [ -n "$master" ] || { kill_job; fail "no master rank found"; }
      if kill -9 "$master" 2>/dev/null; then break; fi
      wait_job 60
      [ "$attempt" -lt 3 ] || fail "the master ended before it was killed, three times: $(cat err.txt)"
      echo "the master ended (exit $status) before it was killed; again" >&2
      attempt=$((attempt + 1))
    done
    wait_job 60
    [ "$status" -ne 124 ] || fail "the master killed: the job hung"
    [ "$status" -ne 0 ] || fail "the master killed: exit 0"
    [ ! -f killed.pfm ] || fail "the master killed, yet an image"
    grep -q "rank 0 ended without an exit status" err.txt || fail "no word on the master: $(cat err.txt)"
    ;;
  resume)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $slow -q -o serial.pfm
    # shellcheck disable=SC2086
    mpi_prt_background -np "$np" "$prt" render "$scene" $slow -q --strategy "${arg:-reservoir}" \
      --slowdown "$(slowdowns)" --batch 8 \
      -o mpi.pfm --checkpoint ck --checkpoint-every 0.1
    wait_for_progress ck 2000 || { kill_job; fail "no progress within 20 s"; }
    kill_job
    [ ! -f mpi.pfm ] || fail "the killed run wrote an image"
    geometry=$slow mpi_prt --strategy hybrid --batch 16 -o mpi.pfm --checkpoint ck --resume \
      --report r.json
    [ "$status" -eq 0 ] || fail "the resumed run exited with $status"
    cmp serial.pfm mpi.pfm || fail "the resumed image differs from the serial one"
    python3 - <<'PY'
import json
r = json.load(open("r.json"))
assert r["resumed_pixels"] > 0, r["resumed_pixels"]
assert sum(w["pixels"] for w in r["workers"]) == 64 * 48 - r["resumed_pixels"]
PY
    ;;
  threads)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    # Rank 0 (the master) and the first worker with one thread, the others with two.
    set -- "$prt" render "$scene" $size -q --strategy "$arg" --batch 8 -o mpi.pfm \
      --report report.json
    set +e
    # shellcheck disable=SC2086
    timeout -k 5 90 "$mpiexec" $launcher_flags -np 2 "$@" --threads 1 : -np $((np - 2)) "$@" \
      --threads 2 >out.txt 2>err.txt
    status=$?
    set -e
    cat err.txt >&2
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    cmp serial.pfm mpi.pfm || fail "the image with mixed thread counts differs from the serial one"
    python3 - "$((np - 1))" <<'PY'
import json, sys
r = json.load(open("report.json"))
threads = [w["threads"] for w in r["workers"]]
assert threads == [1] + [2] * (int(sys.argv[1]) - 1), threads
PY
    ;;
  singleton)
    mpi_prt -o mpi.pfm
    [ "$status" -eq 2 ] || fail "expected exit code 2, got $status"
    grep -q "needs at least 2 ranks" err.txt || fail "no hint about the rank count"
    ;;
  slowdown)
    mpi_prt -o mpi.pfm --slowdown 1,2,3,4
    [ "$status" -eq 2 ] || fail "expected exit code 2, got $status"
    grep -q "give one per worker" err.txt || fail "no hint about the slowdown list"
    [ "$(grep -c "give one per worker" err.txt)" -eq 1 ] || fail "error reported more than once"
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
echo "ok: $mode $np $arg"
