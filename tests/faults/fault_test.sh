#!/bin/sh
# End-to-end fault tests of `prt render` without MPI (the local driver and the serial render).
#   fault_test.sh PRT SCENE WORKDIR MODE
# MODE
#   deadlocks      the runs that once waited for ever end, with the serial image, for every
#                  strategy: a lost worker holding every task, an initial share of nothing
#   resume-local   SIGKILL of a local parallel run mid-render; --resume gives the serial image
#   resume-serial  SIGKILL of a serial render with --checkpoint; --resume gives its image
#   refusals       a checkpoint of another render, or one left without --resume, is refused
#                  with exit code 2 and no image; so are hand-made checkpoints with a valid
#                  checksum (a run whose stride overflows, a NaN pixel, runs out of order),
#                  serial and parallel, the file kept
#   joins          for every strategy: workers that join mid-render (--join-at), alone and
#                  with losses in the same run (a starting worker crashes, a joiner hangs):
#                  the serial image, and the report says who joined when
#   corrupt        workers that return wrong pixels (--inject-fault W:PIXELS:corrupt), early
#                  and late, one and two of them, threaded or not, for several strategies: each
#                  is rejected (and no other), its pixels are rendered again, and the image is
#                  the serial one; with --verify 0 the same fault does reach the image
#   hostile-notice a joiner over TCP (HOSTILE, speaking the wire protocol) sends one transfer
#                  notice claiming every pixel moved to worker 0, then disconnects: it is
#                  rejected, and the run ends with the serial image (adaptive, stealing, self)
#   hostile-tasks  a joiner relays to worker 0 a task message of 2^40 copies of pixel 0: the
#                  worker refuses it, and the run ends with the serial image
#   hostile-linger a joiner that heartbeats after the Stop and never says goodbye: the render
#                  ends a lease after its last pixel, and at once on SIGTERM, image written
#   hostile-hoard  a joiner takes tasks and returns none, heartbeating: its task lease runs
#                  out, its tasks are rendered by the others (adaptive, stealing, and
#                  adaptive with --endgame on); also when it claims a speed index of 10^6 s
#                  (stealing)
#   (the hostile modes take the hostile joiner's path as a fifth argument)
set -eu

prt=$1 scene=$2 work=$3 mode=$4 hostile=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# Runs prt with a hard limit, so a hang fails the test instead of stalling the suite.
run() {
  set +e
  timeout -k 2 30 "$prt" render "$scene" -q "$@" 2>err.txt
  status=$?
  set -e
  [ "$status" -ne 124 ] && [ "$status" -ne 137 ] || fail "prt render $* hung"
}

slow="--width 64 --height 48 --spp 16 --drt 2"

# A background render, killed with SIGKILL once its checkpoint holds some pixels.
kill_mid_render() {
  rm -f out.pfm ck
  "$prt" render "$scene" -q "$@" &
  job=$!
  for i in $(seq 1 300); do
    if [ -f ck ] && [ "$(stat -c %s ck)" -gt 2000 ]; then break; fi
    sleep 0.05
  done
  kill -9 "$job" 2>/dev/null || fail "the render ended before it could be killed"
  wait "$job" 2>/dev/null || true
  [ -f ck ] || fail "no checkpoint"
  [ ! -f out.pfm ] || fail "a killed run wrote an image"
}

case $mode in
  deadlocks)
    strategies=$("$prt" render --help | sed -n 's/^ *\([a-z0-9-]*\) (\(static\|dynamic\|adaptive\))[:,].*/\1/p')
    [ "$(echo "$strategies" | wc -w)" -ge 15 ] || fail "no strategy list in prt render --help"
    for strategy in $strategies; do
      "$prt" render "$scene" -q --width 16 --height 1 -o serial.pfm
      run --width 16 --height 1 --workers 2 --strategy "$strategy" --inject-fault 0:0:crash -o out.pfm
      [ "$status" -eq 0 ] || fail "$strategy, lost worker holding everything: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy: image differs"
      "$prt" render "$scene" -q --width 3 --height 1 -o serial.pfm
      run --width 3 --height 1 --workers 3 --slowdown 1,20,20 --strategy "$strategy" \
        --inject-fault 0:0:crash -o out.pfm
      [ "$status" -eq 0 ] || fail "$strategy, 3x1 with slow others: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy: image differs"
      "$prt" render "$scene" -q --width 64 --height 48 -o serial.pfm
      run --width 64 --height 48 --workers 2 --initial-percent 0.01 --strategy "$strategy" \
        --inject-fault 0:0:hang --worker-timeout 1 -o out.pfm
      [ "$status" -eq 0 ] || fail "$strategy, hung worker with a tiny initial share: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy: image differs"
      run --width 64 --height 48 --workers 2 --initial-percent 1e-14 --strategy "$strategy" \
        -o out.pfm
      [ "$status" -eq 0 ] || fail "$strategy, initial share of nothing: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy: image differs"
      echo "ok: $strategy"
    done
    ;;
  joins)
    strategies=$("$prt" render --help | sed -n 's/^ *\([a-z0-9-]*\) (\(static\|dynamic\|adaptive\))[:,].*/\1/p')
    [ "$(echo "$strategies" | wc -w)" -ge 15 ] || fail "no strategy list in prt render --help"
    size="--width 48 --height 36 --spp 16 --drt 2"
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $size -o serial.pfm
    for strategy in $strategies; do
      # shellcheck disable=SC2086
      run $size --workers 1 --slowdown 60,10,10 --join-at 0.3:2 --strategy "$strategy" \
        --speed-index slowdown --batch 8 -o out.pfm --report r.json
      [ "$status" -eq 0 ] || fail "$strategy, two joiners: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy, two joiners: image differs"
      python3 - "$strategy" <<'PY'
import json, sys
r = json.load(open("r.json"))
assert [j["worker"] for j in r["joined_workers"]] == [1, 2], r["joined_workers"]
assert sum(w["pixels"] for w in r["workers"]) == 48 * 36
# The strategies that hand out (or move) work as they go let the newcomers help (which of
# the two takes more depends on when each finished setting up).
if sys.argv[1] in ("adaptive", "stealing", "self", "hybrid", "reservoir"):
    assert sum(w["pixels"] for w in r["workers"][1:]) > 0, [w["pixels"] for w in r["workers"]]
PY
      # Arrivals and losses in one run: starting worker 0 crashes (after 150 pixels, some
      # 0.2 s in, mostly once both joiners are there: a static strategy then spreads its tasks
      # over the live workers, joiners included), joiner 3 hangs. Slowdowns small enough that
      # a busy machine does not stretch the run past run()'s limit whichever comes first.
      # shellcheck disable=SC2086
      run $size --workers 2 --slowdown 50,50,10,10 --join-at 0.05:1,0.1:1 --strategy "$strategy" \
        --speed-index slowdown --batch 8 --inject-fault 0:150:crash --inject-fault 3:0:hang \
        --worker-timeout 1 -o out.pfm --report r.json
      [ "$status" -eq 0 ] || fail "$strategy, joins and losses: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy, joins and losses: image differs"
      python3 - <<'PY'
import json
r = json.load(open("r.json"))
assert [j["worker"] for j in r["joined_workers"]] == [2, 3], r["joined_workers"]
lost = sorted(l["worker"] for l in r["lost_workers"])
# Joiner 3 hangs before rendering anything: lost once its lease runs out, if it was given any
# tasks (a static strategy gives a joiner only the tasks of later losses).
assert lost in ([0], [0, 3]), r["lost_workers"]
PY
      echo "ok: $strategy"
    done
    ;;
  tcp-join)
    # A local render with --accept-workers and machines that join over TCP (prt join FILE, no
    # MPI): the serial image with a joiner's pixels in it, for a pooled strategy, stealing
    # (transfers between a local worker and a joiner go through the master, both ways) and
    # hybrid (diffusion); a joiner SIGKILLed mid-render is lost and the image still right; an
    # uninvited joiner (a copy of the file with another secret) is refused, exit 1.
    size="--width 64 --height 48 --spp 16 --drt 2"
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $size -o serial.pfm
    start_render() {
      rm -f port out.pfm r.json ck
      # shellcheck disable=SC2086
      timeout -k 2 60 "$prt" render "$scene" -q $size --workers 1 --speed-index none \
        --accept-workers "$work/port" --worker-timeout 2 -o out.pfm --report r.json "$@" \
        2>render-err.txt &
      render=$!
      for _ in $(seq 100); do [ -s port ] && return 0; sleep 0.05; done
      fail "no port file: $(cat render-err.txt)"
    }
    for strategy in adaptive stealing hybrid; do
      start_render --slowdown 300 --strategy "$strategy" --batch 16
      timeout -k 2 60 "$prt" join "$work/port" 2>join-err.txt || fail "$strategy: prt join: $(cat join-err.txt)"
      wait "$render" || fail "$strategy: the render failed: $(cat render-err.txt)"
      cmp serial.pfm out.pfm || fail "$strategy: the image differs"
      [ ! -f port ] || fail "$strategy: the port file was left behind"
      python3 - <<'PY' || fail "$strategy: the report does not show the joiner's work"
import json
r = json.load(open("r.json"))
assert [j["worker"] for j in r["joined_workers"]] == [1], r["joined_workers"]
assert r["workers"][1]["pixels"] > 0, r["workers"]
PY
    done
    # A joiner killed once it is at work: once the checkpoint holds pixels it rendered (the
    # scene renders in 0.03 s on one core: a fixed wait could outlast the render).
    start_render --slowdown 300 --checkpoint "$work/ck" --checkpoint-every 0.1
    "$prt" join "$work/port" --slowdown 1000 2>join-err.txt &
    joiner=$!
    python3 "$here/../checkpoint_owner.py" ck 1 30 "$joiner" ||
      fail "the joiner rendered nothing within 30 s: $(cat join-err.txt)"
    kill -9 "$joiner" 2>/dev/null || fail "the joiner ended before it could be killed: $(cat join-err.txt)"
    wait "$render" || fail "the render failed after its joiner was killed: $(cat render-err.txt)"
    cmp serial.pfm out.pfm || fail "the image differs after the joiner was killed"
    python3 -c 'import json; r = json.load(open("r.json")); assert [l["worker"] for l in r["lost_workers"]] == [1], r["lost_workers"]' ||
      fail "the killed joiner is not reported lost"
    # Uninvited: the addresses without the secret.
    start_render --slowdown 100
    grep "^tcp " port >stolen-port
    set +e
    timeout -k 2 30 "$prt" join stolen-port 2>join-err.txt
    joined=$?
    set -e
    [ "$joined" -eq 1 ] || fail "an uninvited joiner exited $joined: $(cat join-err.txt)"
    grep -q "refused" join-err.txt || fail "the uninvited joiner was not told: $(cat join-err.txt)"
    wait "$render" || fail "the render failed after refusing a joiner"
    cmp serial.pfm out.pfm || fail "the image differs after a refusal"
    python3 -c 'import json; r = json.load(open("r.json")); assert len(r["refused_joiners"]) == 1, r["refused_joiners"]' ||
      fail "the refusal is not in the report"
    ;;
  corrupt)
    size="--width 64 --height 48 --spp 2"
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $size -o serial.pfm
    # The report names exactly the corrupt workers as rejected, with pixels verified.
    rejected() {
      python3 - "$1" <<'PY'
import json, sys
r = json.load(open("r.json"))
want = sorted(int(w) for w in sys.argv[1].split(",") if w)
got = sorted(x["worker"] for x in r["rejected_workers"])
assert got == want, (got, want, r["rejected_workers"])
assert r["verified_pixels"] > 0, r["verified_pixels"]
for x in r["rejected_workers"]:
    assert "spot check" in x["reason"], x
PY
    }
    # The fault reaches the image when nothing checks.
    # shellcheck disable=SC2086
    run $size --workers 3 --inject-fault 1:0:corrupt --verify 0 -o out.pfm
    [ "$status" -eq 0 ] || fail "--verify 0: exit $status"
    if cmp -s serial.pfm out.pfm; then fail "the corrupt worker changed nothing"; fi
    for strategy in adaptive hybrid scatter reservoir stealing; do
      # Early, at the default rate: a new worker is checked in every batch.
      # shellcheck disable=SC2086
      run $size --workers 3 --strategy "$strategy" --batch 16 --inject-fault 1:0:corrupt \
        -o out.pfm --report r.json
      [ "$status" -eq 0 ] || fail "$strategy, corrupt from the start: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy, corrupt from the start: image differs"
      rejected 1
      # Late (after most of its share), and two corrupt workers, one of them with two
      # threads: a higher rate, so that the few wrong pixels are surely sampled.
      # shellcheck disable=SC2086
      run $size --workers 4 --strategy "$strategy" --batch 16 --verify 10 \
        --inject-fault 0:600:corrupt --inject-fault 2:100:corrupt --threads 2 \
        -o out.pfm --report r.json
      [ "$status" -eq 0 ] || fail "$strategy, two corrupt workers: exit $status"
      cmp serial.pfm out.pfm || fail "$strategy, two corrupt workers: image differs"
      python3 - <<'PY'
import json
r = json.load(open("r.json"))
# Worker 0 turns corrupt only after 600 pixels: it may finish its share before.
got = sorted(x["worker"] for x in r["rejected_workers"])
assert got in ([2], [0, 2]), r["rejected_workers"]
PY
      echo "ok: $strategy"
    done
    # One worker, every pixel checked by the master itself: costly pixels (the complex scene
    # at 64 spp, DRT 8) make each of the master's checks of a batch take seconds; the
    # worker must not be lost for it, nor the master for the worker.
    # shellcheck disable=SC2086
    timeout -k 2 60 "$prt" render "$(dirname "$scene")/complex.scene" -q --width 16 --height 12 \
      --spp 64 --drt 8 --workers 1 --verify 100 --worker-timeout 3 -o out.pfm --report r.json \
      2>err.txt || fail "one worker checked by the master: exit $? ($(cat err.txt))"
    python3 -c 'import json; r = json.load(open("r.json")); assert not r["lost_workers"] and r["referee_checks"] == 16 * 12, (r["lost_workers"], r["referee_checks"])'
    # Every worker but one corrupt: the master checks the last one itself.
    # shellcheck disable=SC2086
    run $size --workers 3 --inject-fault 0:0:corrupt --inject-fault 2:0:corrupt --verify 5 \
      -o out.pfm --report r.json
    [ "$status" -eq 0 ] || fail "two of three corrupt: exit $status"
    cmp serial.pfm out.pfm || fail "two of three corrupt: image differs"
    rejected 0,2
    ;;
  resume-local)
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $slow -o serial.pfm
    # shellcheck disable=SC2086
    kill_mid_render $slow --workers 2 --slowdown 40,40 --batch 8 -o out.pfm --checkpoint ck \
      --checkpoint-every 0.1
    # shellcheck disable=SC2086
    run $slow --workers 3 --strategy scatter -o out.pfm --checkpoint ck --resume --report r.json
    [ "$status" -eq 0 ] || fail "the resumed run exited with $status"
    cmp serial.pfm out.pfm || fail "the resumed image differs from the serial one"
    [ ! -f ck ] || fail "the checkpoint was not removed"
    python3 - <<'PY'
import json
r = json.load(open("r.json"))
assert r["resumed_pixels"] > 0, r
assert sum(w["pixels"] for w in r["workers"]) == 64 * 48 - r["resumed_pixels"]
PY
    ;;
  resume-serial)
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $slow -o serial.pfm
    # The serial render is fast: a large image and one thread, killed at its first checkpoint.
    "$prt" render "$scene" -q --width 640 --height 480 --spp 8 --threads 1 -o big.pfm
    kill_mid_render --width 640 --height 480 --spp 8 --threads 1 -o out.pfm --checkpoint ck \
      --checkpoint-every 0.05
    run --width 640 --height 480 --spp 8 -o out.pfm --checkpoint ck --resume
    [ "$status" -eq 0 ] || fail "the resumed serial render exited with $status"
    cmp big.pfm out.pfm || fail "the resumed serial image differs"
    # And resuming a serial checkpoint with a parallel run.
    # shellcheck disable=SC2086
    kill_mid_render $slow --workers 2 --slowdown 40,40 --batch 8 -o out.pfm --checkpoint ck \
      --checkpoint-every 0.1
    # shellcheck disable=SC2086
    run $slow -o out.pfm --checkpoint ck --resume
    [ "$status" -eq 0 ] || fail "a serial resume of a parallel checkpoint exited with $status"
    cmp serial.pfm out.pfm || fail "the image differs"
    ;;
  refusals)
    # shellcheck disable=SC2086
    kill_mid_render $slow --workers 2 --slowdown 40,40 --batch 8 -o out.pfm --checkpoint ck \
      --checkpoint-every 0.1
    run --width 64 --height 48 --spp 4 --drt 2 -o out.pfm --checkpoint ck --resume
    [ "$status" -eq 2 ] || fail "a checkpoint of another render: exit $status, not 2"
    grep -q "belongs to another render" err.txt || fail "no reason given: $(cat err.txt)"
    run $slow -o out.pfm --checkpoint ck
    [ "$status" -eq 2 ] || fail "an existing checkpoint without --resume: exit $status, not 2"
    grep -q "to continue it, run" err.txt || fail "no hint: $(cat err.txt)"
    grep -q -- "--checkpoint ck --resume" err.txt || fail "no resume command: $(cat err.txt)"
    run $slow -o out.pfm --resume --no-checkpoint
    [ "$status" -eq 2 ] || fail "--resume with --no-checkpoint: exit $status"
    [ ! -f out.pfm ] || fail "a refused run wrote an image"
    # The real checkpoint's header with runs and pixels made by hand, and a valid checksum.
    cp ck real.ck
    for made in overflow nan backwards; do
      python3 - "$made" real.ck ck <<'PY'
import struct, sys
made, src, dst = sys.argv[1:4]
data = open(src, "rb").read()[:-8]
n = struct.unpack_from("<H", data, 16)[0]
head = data[:18 + n + 8]
runs = {"overflow": [(1, 3, 1 << 63)], "nan": [(0, 2, 1)], "backwards": [(10, 2, 1), (3, 2, 1)]}[made]
pixels = sum(c for _, c, _ in runs)
colours = [0.5] * (3 * pixels)
if made == "nan":
    colours[4] = float("nan")
body = head + struct.pack("<Q", len(runs)) + b"".join(struct.pack("<QQQ", *r) for r in runs)
body += struct.pack("<%df" % len(colours), *colours) + struct.pack("<%dh" % pixels, *([0] * pixels))
h = 14695981039346656037
for b in body:
    h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
open(dst, "wb").write(body + struct.pack("<Q", h))
PY
      before=$(md5sum ck)
      for workers in 1 2; do
        run $slow --workers $workers -o out.pfm --checkpoint ck --resume
        [ "$status" -eq 2 ] || fail "hand-made checkpoint ($made, $workers workers): exit $status"
        grep -q "is damaged" err.txt || fail "$made: no reason given: $(cat err.txt)"
        [ ! -f out.pfm ] || fail "$made: a refused run wrote an image"
        [ "$(md5sum ck)" = "$before" ] || fail "$made: the checkpoint was changed"
      done
    done
    # A checkpoint holding every pixel (killed between its last write and the image): the
    # workers are stopped at once, and each sends its summary (none waited for in vain).
    cp real.ck ck
    python3 - complete real.ck ck <<'PY'
import struct, sys
data = open(sys.argv[2], "rb").read()[:-8]
n = struct.unpack_from("<H", data, 16)[0]
pixels = 64 * 48
body = data[:18 + n + 8] + struct.pack("<Q", 1) + struct.pack("<QQQ", 0, pixels, 1)
body += struct.pack("<%df" % (3 * pixels), *([0.25] * (3 * pixels)))
body += struct.pack("<%dh" % pixels, *([0] * pixels))
h = 14695981039346656037
for b in body:
    h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
open(sys.argv[3], "wb").write(body + struct.pack("<Q", h))
PY
    touch "ck.tmp-4194303-0"  # a dead run's half-written checkpoint
    run $slow --workers 2 -o out.pfm --checkpoint ck --resume --report r.json
    [ "$status" -eq 0 ] || fail "a complete checkpoint: exit $status: $(cat err.txt)"
    [ -f out.pfm ] && [ ! -f ck ] || fail "a complete checkpoint: no image, or the checkpoint kept"
    ! grep -q '"missing_summaries": [1-9]' r.json || fail "summaries waited for in vain: $(grep missing r.json)"
    [ ! -f "ck.tmp-4194303-0" ] || fail "a dead run's temporary checkpoint was left"
    ;;
  hostile-*)
    # A local render of one worker, slowed to last a few seconds, with a TCP door; then the
    # hostile joiner (tests/faults/hostile_joiner.cpp) joins it. Every wait is bounded.
    [ -x "$hostile" ] || fail "no hostile joiner given"
    size="--width 32 --height 24 --spp 16 --drt 2"
    pixels=768
    # shellcheck disable=SC2086
    "$prt" render "$scene" -q $size -o serial.pfm
    start_render() {
      rm -f port out.pfm r.json ck out.pfm.ckpt
      # shellcheck disable=SC2086
      timeout -k 2 "$limit" "$prt" render "$scene" -q $size --workers 1 --speed-index none \
        --slowdown 300 --batch "${batch:-16}" --accept-workers "$work/port" -o out.pfm --report r.json \
        "$@" 2>render-err.txt &
      render=$!
      for _ in $(seq 100); do [ -s port ] && return 0; sleep 0.05; done
      fail "no port file: $(cat render-err.txt)"
    }
    # Waits for the render; fails if it hung (the limit) or failed.
    end_render() {
      set +e
      wait "$render"
      status=$?
      set -e
      [ "$status" -ne 124 ] && [ "$status" -ne 137 ] || fail "$1: the render hung"
      [ "$status" -eq 0 ] || fail "$1: exit $status: $(cat render-err.txt)"
      cmp serial.pfm out.pfm || fail "$1: the image differs"
    }
    # Waits until the hostile joiner has seen the Stop (at most 30 s).
    await_stop() {
      for _ in $(seq 600); do grep -q stopped joiner-out.txt 2>/dev/null && return 0; sleep 0.05; done
      fail "the joiner never saw the Stop: $(cat render-err.txt)"
    }
    limit=40
    case $mode in
      hostile-notice)
        for strategy in adaptive stealing self; do
          start_render --strategy "$strategy" --worker-timeout 2
          "$hostile" port forge-notice $pixels 30 >joiner-out.txt 2>&1 || fail "not admitted: $(cat joiner-out.txt)"
          end_render "$strategy, forged notice"
          python3 - <<'PY' || fail "$strategy: the forger is not rejected in the report"
import json
r = json.load(open("r.json"))
assert [x["worker"] for x in r["rejected_workers"]] == [1], r["rejected_workers"]
assert "no order asked for" in r["rejected_workers"][0]["reason"], r["rejected_workers"]
PY
          echo "ok: $strategy"
        done
        ;;
      hostile-tasks)
        for strategy in adaptive stealing; do
          start_render --strategy "$strategy" --worker-timeout 2
          "$hostile" port huge-tasks $pixels 30 >joiner-out.txt 2>&1 || fail "not admitted: $(cat joiner-out.txt)"
          end_render "$strategy, 2^40 copies relayed"
          python3 - <<'PY' || fail "$strategy: the report counts more pixels than the image"
import json
r = json.load(open("r.json"))
assert sum(w["pixels"] for w in r["workers"]) == 32 * 24, [w["pixels"] for w in r["workers"]]
PY
          echo "ok: $strategy"
        done
        ;;
      hostile-linger)
        # The goodbye lasts at most the lease (2 s) from the Stop, the joiner heartbeating on.
        start_render --worker-timeout 2
        "$hostile" port linger $pixels 60 >joiner-out.txt 2>&1 &
        joiner=$!
        await_stop
        for _ in $(seq 200); do kill -0 "$render" 2>/dev/null || break; sleep 0.05; done
        if kill -0 "$render" 2>/dev/null; then
          fail "the render still waits for a joiner 10 s after its last pixel"
        fi
        end_render "a joiner that never says goodbye"
        wait "$joiner" || true
        # A lease of 30 s: SIGTERM in the goodbye ends it at once, with the image.
        start_render --worker-timeout 30 --checkpoint "$work/ck"
        "$hostile" port linger $pixels 60 >joiner-out.txt 2>&1 &
        joiner=$!
        await_stop
        kill -TERM "$render"
        for _ in $(seq 100); do kill -0 "$render" 2>/dev/null || break; sleep 0.05; done
        if kill -0 "$render" 2>/dev/null; then fail "SIGTERM in the goodbye: still running 5 s later"; fi
        end_render "SIGTERM in the goodbye"
        [ ! -f ck ] || fail "SIGTERM in the goodbye: the checkpoint of a finished image was kept"
        wait "$joiner" || true
        ;;
      hostile-hoard)
        # A hoarding joiner (the hostile joiner's mode $2, staying $3 s) against a strategy:
        # the render ends with the serial image, the joiner lost by its task lease alone.
        hoard() {
          # shellcheck disable=SC2086
          start_render --strategy $1 --worker-timeout 2
          "$hostile" port "$2" $pixels "$3" >joiner-out.txt 2>&1 &
          joiner=$!
          end_render "$1, $4"
          kill "$joiner" 2>/dev/null || true
          wait "$joiner" 2>/dev/null || true
          python3 - <<'PY' || fail "$1: $4 is not lost by its task lease"
import json
r = json.load(open("r.json"))
lost = r["lost_workers"]
assert [l["worker"] for l in lost] == [1] and "task lease" in lost[0]["reason"], lost
PY
          echo "ok: $1, $4"
        }
        # The joiner stays 60 s; the render must not wait for it (the limit is 40 s).
        for strategy in adaptive stealing "adaptive --endgame on"; do
          hoard "$strategy" hoard 60 "a joiner that keeps its tasks"
        done
        # One that claims to be a million times slower buys no lease without end: at most ten
        # batches of ten times the longest batch returned (batches of 4 pixels: 18-21 s on a
        # quiet machine; the longest batch, and so the lease, grows with the machine's load,
        # past 60 s under two busy loops). The joiner stays longer than the render may last,
        # so that only its task lease can end its part.
        limit=150 batch=4
        hoard stealing hoard-slow 200 "a joiner that keeps its tasks and claims to be slow"
        ;;
    esac
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
echo "ok: $mode"
