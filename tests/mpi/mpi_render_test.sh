#!/bin/sh
# End-to-end tests of `prt render` under mpirun.
#   mpi_render_test.sh PRT MPIEXEC SCENE WORKDIR MODE NP [ARG]
# MODE
#   image STRATEGY  the image is byte-identical to the serial render of the same scene
#   report [FLAG]   --report JSON has the run's measures and one entry per worker (with FLAG,
#                   e.g. --speed-index=probe, added to the command line)
#   fault KIND      --inject-fault 1:0:KIND (crash|hang) fails the job, naming the rank
#   singleton       one rank is refused with a clear message
#   slowdown        a --slowdown list not matching the worker count is refused
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
  timeout -k 5 90 "$mpiexec" $launcher_flags -np "$np" "$prt" render "$scene" $size -q "$@" \
    >out.txt 2>err.txt
  status=$?
  set -e
  cat out.txt
  cat err.txt >&2
  return 0
}

case $mode in
  image)
    # shellcheck disable=SC2086
    "$prt" render "$scene" $size -q -o serial.pfm
    mpi_prt --strategy "$arg" --batch 16 -o mpi.pfm
    [ "$status" -eq 0 ] || fail "mpirun exited with $status"
    cmp serial.pfm mpi.pfm || fail "the MPI image differs from the serial one"
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
for key in ("elapsed_s", "efficiency", "masu", "messages", "bytes", "rays", "workers"):
    assert key in r, "missing " + key
assert r["driver"] == "mpi", r["driver"]
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
    start=$(date +%s)
    mpi_prt --strategy reservoir --batch 16 -o mpi.pfm --inject-fault "1:0:$arg" \
      --worker-timeout 2
    elapsed=$(($(date +%s) - start))
    [ "$status" -ne 0 ] || fail "a $arg worker did not fail the run"
    [ "$status" -ne 124 ] && [ "$status" -ne 137 ] || fail "the run hung (killed by timeout)"
    [ "$elapsed" -lt 60 ] || fail "the failure took $elapsed s to detect"
    grep -q "rank 2" err.txt || fail "stderr does not name the failed rank (2)"
    if [ "$arg" = hang ]; then
      grep -q "prt: error: worker rank 2 (worker 1) stopped answering" err.txt ||
        fail "the master did not report the silent worker"
    fi
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
