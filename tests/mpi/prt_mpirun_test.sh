#!/bin/sh
# Tests of scripts/prt-mpirun with stand-in mpiruns (no MPI needed):
#   - an mpirun that hangs after its ranks have ended (only zombies under it, as Open MPI
#     4.1's mpirun does when a rank is killed at start-up) is ended after PRT_MPIRUN_GRACE
#     seconds, with the exit code rank 0 wrote, else 1;
#   - an mpirun with a live rank is not ended however long it runs, until rank 0 has recorded
#     its code; then it is ended PRT_MPIRUN_GRACE seconds later with what it started (the
#     daemon of a host whose link was cut keeps mpirun waiting for ever), exit rank 0's code;
#   - mpirun's own non-zero status wins; else rank 0's recorded code; else 1;
#   - a master killed without a record, whose checkpoint exists, gets its resume command said
#     (the arguments given, with --resume); not when the checkpoint is gone or the master
#     recorded its code (it then spoke for itself);
#   - no status file is left behind.
# Usage: prt_mpirun_test.sh WRAPPER WORK
set -eu
wrapper=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

# A stand-in mpirun: `fake-mpirun -x PRT_STATUS_FILE MODE [CODE]`.
#   hang CODE      a rank that records CODE and exits; then waits for ever without reaping it
#   live SECONDS   a rank that runs SECONDS, records 0 and exits; then mpirun exits 0
#   exit CODE      mpirun exits with CODE, no record
#   record CODE    a rank records CODE; mpirun reaps it and exits 0
#   killed 1|0     rank 0 names its checkpoint ck.ckpt (1: and writes it), then mpirun exits
#                  137, as when it kills the master after another rank died
#   spoke CODE     rank 0 names ck.ckpt, writes it, records CODE; mpirun exits 0
#   unreachable CODE  rank 0 records CODE and exits; a daemon (its pid in daemon.pid) lives on
#                  and mpirun waits for it for ever, as for the daemon of a host cut off
cat >fake-mpirun <<'PY'
#!/usr/bin/env python3
import os, sys, time
mode, value = sys.argv[3], int(sys.argv[4])
def record(code):
    with open(os.environ["PRT_STATUS_FILE"], "w") as f:
        f.write(f"{code}\n")
if mode == "exit":
    sys.exit(value)
if mode in ("killed", "spoke"):
    with open(os.environ["PRT_STATUS_FILE"] + ".resume", "w") as f:
        f.write("ck.ckpt\n")
    if mode == "spoke" or value == 1:
        open("ck.ckpt", "w").close()
    if mode == "spoke":
        record(value)
        sys.exit(0)
    sys.exit(137)
if mode == "unreachable":
    daemon = os.fork()
    if daemon == 0:
        while True:
            time.sleep(60)
    with open("daemon.pid", "w") as f:
        f.write(f"{daemon}\n")
    rank = os.fork()
    if rank == 0:
        time.sleep(1)
        record(value)
        os._exit(0)
    os.waitpid(rank, 0)
    os.waitpid(daemon, 0)
    sys.exit(0)
pid = os.fork()
if pid == 0:
    if mode == "live":
        time.sleep(value)
        value = 0
    if value >= 0:
        record(value)
    os._exit(0)
if mode == "hang":
    while True:
        time.sleep(60)
os.waitpid(pid, 0)
sys.exit(0)
PY
chmod +x fake-mpirun
export MPIRUN="$PWD/fake-mpirun" PRT_MPIRUN_GRACE=2

run() {
  start=$(date +%s)
  set +e
  timeout -k 2 60 sh "$wrapper" "$@" 2>err.txt
  status=$?
  set -e
  elapsed=$(($(date +%s) - start))
}

run hang 3
[ "$status" -eq 3 ] || fail "a hung mpirun with rank 0's code 3: exit $status"
[ "$elapsed" -lt 15 ] || fail "a hung mpirun was ended after $elapsed s"
grep -q "has not ended" err.txt || fail "no word about the hung mpirun"
run hang 0
[ "$status" -eq 0 ] || fail "a hung mpirun after a success: exit $status"
run hang -1
[ "$status" -eq 1 ] || fail "a hung mpirun with no record: exit $status"
run live 5
[ "$status" -eq 0 ] || fail "an mpirun with a rank alive for 5 s (grace 2 s): exit $status"
grep -q "has not ended" err.txt && fail "an mpirun with a live rank was ended"
run unreachable 3
[ "$status" -eq 3 ] || fail "mpirun waiting for an unreachable daemon, rank 0's code 3: exit $status"
[ "$elapsed" -lt 12 ] || fail "mpirun waiting for an unreachable daemon was ended after $elapsed s"
grep -q "after rank 0 finished" err.txt || fail "no word about ending mpirun: $(cat err.txt)"
daemon=$(cat daemon.pid)
sleep 0.2
if kill -0 "$daemon" 2>/dev/null && ! grep -q '^State:.*Z' "/proc/$daemon/status" 2>/dev/null; then
  kill -9 "$daemon"
  fail "the daemon mpirun started was left running"
fi
run exit 7
[ "$status" -eq 7 ] || fail "mpirun's own status 7: exit $status"
run record 2
[ "$status" -eq 2 ] || fail "rank 0's code 2: exit $status"
run record -1
[ "$status" -eq 1 ] || fail "no record: exit $status"
run killed 1 -o "an image.png"
[ "$status" -eq 137 ] || fail "a killed master: exit $status"
grep -q "the finished pixels are in 'ck.ckpt'" err.txt || fail "no resume command: $(cat err.txt)"
grep -qF "prt-mpirun killed 1 -o 'an image.png' --resume" err.txt ||
  fail "the resume command is not the command given with --resume: $(cat err.txt)"
run killed 1 --resume
grep -qF "killed 1 --resume --resume" err.txt && fail "--resume given twice: $(cat err.txt)"
grep -qF "killed 1 --resume" err.txt || fail "no resume command after a resumed run: $(cat err.txt)"
rm -f ck.ckpt
run killed 0
[ "$status" -eq 137 ] || fail "a killed master without a checkpoint: exit $status"
grep -q "finished pixels" err.txt && fail "a resume command without a checkpoint"
run spoke 143
[ "$status" -eq 143 ] || fail "a master that recorded 143: exit $status"
grep -q "finished pixels" err.txt && fail "a resume command although the master spoke"
rm -f ck.ckpt
leftover=$(find . -name '.prt-*')
[ -z "$leftover" ] || fail "files left behind: $leftover"
PRT_MPIRUN_GRACE=soon run record 0
[ "$status" -eq 2 ] || fail "a bad PRT_MPIRUN_GRACE: exit $status"
echo "prt-mpirun: all cases pass"
