#!/bin/bash
# PRT under a real Slurm cluster of three network-namespace hosts (scripts/slurm-cluster.sh),
# through the job script users submit (examples/slurm/render.sbatch). Needs root, network
# namespaces and Slurm; skipped (exit 77) otherwise.
#   slurm_test.sh PRT SCENE WORKDIR SOURCE_DIR MODE
# MODE:
#   render     sbatch renders across the 3 hosts: the serial image, one worker per host, each
#              with the threads of its host's CPUs in Slurm (2, 1, 1)
#   node-lost  a host dies mid-render (every process on it SIGKILLed, its link down): the job
#              finishes with the serial image, the worker on it reported lost
#   scancel    scancel mid-render leaves the checkpoint; the same sbatch again resumes it
#   requeue    scontrol requeue mid-render: the job runs again, resumes, and ends with the
#              serial image
#   join       a render on 2 hosts with --accept-workers; a second job (join.sbatch) on the
#              third host joins it over TCP: the serial image, the joiner's pixels in it, both
#              jobs exit 0
set -u

prt=$1 scene=$2 work=$3 src=$4 mode=$5
cluster=$src/scripts/slurm-cluster.sh
job_script=$src/examples/slurm/render.sbatch
skip() { echo "SKIP: $*"; exit 77; }
fail() {
  echo "FAIL ($mode): $*" >&2
  for f in "$work"/prt-*.out; do [ -f "$f" ] && { echo "--- $f" >&2; grep -v "PMIX ERROR" "$f" >&2; }; done
  exit 1
}
[ "$(id -u)" -eq 0 ] || skip "a Slurm cluster of network namespaces needs root"
for tool in ip unshare nsenter slurmctld slurmd munged sbatch mpirun; do
  command -v "$tool" >/dev/null || skip "no $tool (scripts/install-deps.sh installs Slurm)"
done
mpirun --version 2>/dev/null | grep -qiE "open ?mpi|openrte" || skip "the job script needs Open MPI"

rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
slurm_dir=$work/cluster
cleanup() {
  status=$?
  bash "$cluster" down "$slurm_dir" >/dev/null 2>&1 || true
  exit "$status"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP
bash "$cluster" up 3 "$slurm_dir" >up.txt 2>&1 || { cat up.txt >&2; fail "the cluster did not come up"; }
# shellcheck disable=SC1091
. "$slurm_dir/env"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# The hosts reach each other on the bridge only.
export OMPI_MCA_btl=tcp,self OMPI_MCA_btl_tcp_if_include=10.232.0.0/24 \
  OMPI_MCA_oob_tcp_if_include=10.232.0.0/24
export PRT=$prt PRT_MPIRUN=$src/scripts/prt-mpirun

geometry="--width 64 --height 48 --spp 16 --drt 2"
# shellcheck disable=SC2086
"$prt" render "$scene" $geometry -q -o serial.pfm || fail "the serial render failed"

# Waits for job $1 to leave the queue ($2 seconds at most).
wait_job() {
  for _ in $(seq $((${2:-120} * 5))); do
    [ -z "$(squeue -h -j "$1" -o %T 2>/dev/null)" ] && return 0
    sleep 0.2
  done
  fail "job $1 still in the queue after ${2:-120} s: $(squeue -h -j "$1" -o '%T %R')"
}
# Waits until the render has a checkpoint, then $1 seconds more (mid-render).
wait_checkpoint() {
  for _ in $(seq 300); do
    [ -f out.pfm.ckpt ] && { sleep "$1"; return 0; }
    sleep 0.2
  done
  fail "no checkpoint appeared within 60 s"
}
submit() {
  # shellcheck disable=SC2086
  sbatch --parsable "$job_script" "$scene" out.pfm $geometry -q --checkpoint-every 0.2 "$@" ||
    fail "sbatch refused the job"
}
report() { python3 - "$@" <<'PY'
import json, sys
r = json.load(open("out.pfm.report.json"))
mode = sys.argv[1]
hosts = sorted(w["host"] for w in r["workers"])
assert hosts == ["prt-s0", "prt-s1", "prt-s2"], hosts
if mode == "render":
    threads = {w["host"]: w["threads"] for w in r["workers"]}
    # prt-s0 has 2 CPUs in Slurm and the master beside its worker; the others 1 each.
    assert threads == {"prt-s0": 2, "prt-s1": 1, "prt-s2": 1}, threads
if mode == "node-lost":
    lost = [l["worker"] for l in r["lost_workers"]]
    on_s1 = [w["worker"] for w in r["workers"] if w["host"] == "prt-s1"]
    assert lost == on_s1, (lost, on_s1, r["lost_workers"])
if mode in ("scancel", "requeue"):
    assert r["resumed_pixels"] > 0, r["resumed_pixels"]
PY
}
# Slow workers (the throttle sleeps: no CPU is needed for it), so that the render lasts long
# enough to be hit mid-way: about 10 s of work each.
slow="--slowdown 600,600,600 --speed-index none --strategy scatter"

case $mode in
  render)
    job=$(submit)
    wait_job "$job" 120
    cmp serial.pfm out.pfm || fail "the image differs from the serial render"
    report render || fail "the report does not show one worker per host with its CPUs"
    ;;
  node-lost)
    # shellcheck disable=SC2086
    job=$(submit $slow --worker-timeout 2)
    wait_checkpoint 2
    bash "$cluster" kill-node 1 || fail "could not kill host prt-s1"
    wait_job "$job" 120
    cmp serial.pfm out.pfm || fail "the image differs from the serial render"
    report node-lost || fail "the report does not name the worker on prt-s1 as lost"
    ;;
  scancel)
    # shellcheck disable=SC2086
    job=$(submit $slow)
    wait_checkpoint 2
    scancel "$job"
    wait_job "$job" 60
    [ -f out.pfm.ckpt ] || fail "scancel left no checkpoint"
    [ ! -f out.pfm ] || fail "a cancelled job wrote an image"
    # shellcheck disable=SC2086
    job=$(submit $slow)
    wait_job "$job" 120
    grep -q "resuming from out.pfm.ckpt" "prt-$job.out" || fail "the second job did not resume"
    cmp serial.pfm out.pfm || fail "the resumed image differs from the serial render"
    report scancel || fail "the report shows no resumed pixels"
    [ ! -f out.pfm.ckpt ] || fail "the checkpoint was left after the image was written"
    ;;
  requeue)
    # shellcheck disable=SC2086
    job=$(submit $slow)
    wait_checkpoint 2
    scontrol requeue "$job" || fail "scontrol requeue failed"
    wait_job "$job" 150
    grep -q "(run 2): resuming from out.pfm.ckpt" "prt-$job.out" ||
      fail "the requeued job did not resume"
    cmp serial.pfm out.pfm || fail "the image of the requeued job differs from the serial render"
    report requeue || fail "the report shows no resumed pixels"
    ;;
  join)
    # shellcheck disable=SC2086
    job=$(sbatch --parsable --nodes=2 --nodelist=prt-s0,prt-s1 "$job_script" "$scene" out.pfm \
      $geometry -q --slowdown 600,600 --speed-index none --accept-workers "$work/port") ||
      fail "sbatch refused the render"
    for _ in $(seq 300); do [ -s port ] && break; sleep 0.2; done
    [ -s port ] || fail "the render wrote no port file"
    grep -q "^tcp 10.232.0.10:" port || fail "the port file names no address on the bridge: $(grep tcp port)"
    joiner=$(sbatch --parsable --nodes=1 --nodelist=prt-s2 "$src/examples/slurm/join.sbatch" \
      "$work/port") || fail "sbatch refused the join"
    wait_job "$job" 120
    wait_job "$joiner" 60
    cmp serial.pfm out.pfm || fail "the image differs from the serial render"
    for j in "$job" "$joiner"; do
      scontrol show job "$j" | grep -q "ExitCode=0:0" ||
        fail "job $j: $(scontrol show job "$j" | grep -o 'JobState=[A-Z]* .*ExitCode=[0-9:]*')"
    done
    python3 - <<'PY' || fail "the report does not show the joiner's work"
import json
r = json.load(open("out.pfm.report.json"))
joined = [w for w in r["workers"] if w["joined_at_s"] is not None]
assert len(joined) == 1 and joined[0]["host"] == "prt-s2", r["workers"]
assert joined[0]["pixels"] > 0, joined
assert not r["lost_workers"], r["lost_workers"]
PY
    ;;
  *) fail "unknown mode" ;;
esac
echo "ok: $mode"
