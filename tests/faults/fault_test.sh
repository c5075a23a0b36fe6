#!/bin/sh
# End-to-end fault tests of `prt render` without MPI (the local driver and the serial render).
#   fault_test.sh PRT SCENE WORKDIR MODE
# MODE
#   deadlocks      the runs that once waited for ever end, with the serial image, for every
#                  strategy: a lost worker holding every task, an initial share of nothing
#   resume-local   SIGKILL of a local parallel run mid-render; --resume gives the serial image
#   resume-serial  SIGKILL of a serial render with --checkpoint; --resume gives its image
#   refusals       a checkpoint of another render, or one left without --resume, is refused
#                  with exit code 2 and no image
set -eu

prt=$1 scene=$2 work=$3 mode=$4
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
    grep -q "add --resume" err.txt || fail "no hint: $(cat err.txt)"
    run $slow -o out.pfm --resume
    [ "$status" -eq 2 ] || fail "--resume without --checkpoint: exit $status"
    [ ! -f out.pfm ] || fail "a refused run wrote an image"
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
echo "ok: $mode"
