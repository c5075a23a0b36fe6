#!/usr/bin/env bash
# A real Slurm cluster on this machine, for testing PRT under the scheduler clusters use: the
# hosts of scripts/netns-cluster.sh (network namespaces on a bridge, each with its own
# hostname and address), a munge daemon, slurmctld on the bridge's address, and one slurmd per
# host running inside that host's namespace. Needs root and Slurm (slurm-wlm, munge).
#
#   scripts/slurm-cluster.sh up N [DIR]    hosts prt-s0 .. prt-s(N-1); DIR (default
#                                          /tmp/prt-slurm) gets slurm.conf, `env` (source it
#                                          to use sbatch, squeue, scancel, srun against this
#                                          cluster) and the daemons' logs and state
#   scripts/slurm-cluster.sh kill-node I   host I dies: its slurmd and everything it started
#                                          are SIGKILLed and its link goes down
#   scripts/slurm-cluster.sh down [DIR]    stop every daemon, remove the hosts and DIR
#
# The hosts get different CPU counts (2, 1, 1, 2, 1, 1, ...: a mixed cluster). This machine
# may have fewer cores than they add up to; slurmd is told to take the configured counts
# (SlurmdParameters=config_overrides), so Slurm hands out what the configuration says.
#
# Each slurmd is started as `slurmd -D` in its host's namespace with that host's name as its
# hostname (a UTS namespace of its own), so it finds its own NodeName as on a real node; no
# multiple-slurmd build is needed. Job steps it starts run in that namespace: an mpirun in a
# batch script reaches the other hosts over the bridge, as on a real network.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
netns=$here/netns-cluster.sh
# Hosts of their own (prt-s0, ... on 10.232.0.0/24): the plain netns cluster of the MPI tests
# (prt-h0, ... on 10.231.0.0/24) can stand beside this one.
prefix=prt-s
subnet=10.232.0
export PRT_NETNS_PREFIX=$prefix PRT_NETNS_SUBNET=$subnet

host_ip() { echo "$subnet.$((10 + $1))"; }
cpus_of() { case $(($1 % 3)) in 0) echo 2 ;; *) echo 1 ;; esac; }

die() {
  echo "slurm-cluster: $*" >&2
  exit 1
}

wait_for() {  # wait_for SECONDS DESCRIPTION COMMAND...
  local limit=$1 what=$2
  shift 2
  for ((t = 0; t < limit * 10; t++)); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.1
  done
  die "$what did not happen within $limit s (logs in $dir/log)"
}

write_conf() {
  local n=$1
  cat >"$dir/slurm.conf" <<EOF
# Written by scripts/slurm-cluster.sh: a test cluster of $n hosts on network namespaces.
ClusterName=prt
SlurmctldHost=prt-ctl($subnet.1)
AuthType=auth/munge
CredType=cred/munge
# cred_expire: a requeued job waits this long before it starts again (default 120 s).
AuthInfo=socket=$dir/munge/munge.socket,cred_expire=10
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool/%n
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd-%n.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd-%n.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroups here: processes are tracked by their parent, tasks are not bound.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SlurmdParameters=config_overrides
ReturnToService=2
# Short timeouts, so that a lost host is noticed within a test's time.
SlurmdTimeout=10
SlurmctldTimeout=10
MessageTimeout=5
KillWait=10
InactiveLimit=0
MinJobAge=60
JobRequeue=1
EOF
  for ((i = 0; i < n; i++)); do
    echo "NodeName=$prefix$i NodeAddr=$(host_ip "$i") NodeHostname=$prefix$i CPUs=$(cpus_of "$i") RealMemory=1024 State=UNKNOWN" >>"$dir/slurm.conf"
  done
  echo "PartitionName=prt Nodes=ALL Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO" >>"$dir/slurm.conf"
}

up() {
  local n=$1
  dir=${2:-/tmp/prt-slurm}
  command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null ||
    die "Slurm is not installed (apt-get install slurm-wlm munge)"
  down "$dir" >/dev/null 2>&1 || true
  mkdir -p "$dir"/{ctld,spool,run,log,munge}
  bash "$netns" up "$n" "$dir/hosts" >/dev/null
  # Names resolve on every host as on a real cluster: ip netns exec puts /etc/netns/NS/hosts
  # over /etc/hosts inside the namespace.
  for ((i = 0; i < n; i++)); do
    mkdir -p "/etc/netns/$prefix$i"
    {
      echo "127.0.0.1 localhost"
      echo "$subnet.1 prt-ctl"
      for ((j = 0; j < n; j++)); do echo "$(host_ip "$j") $prefix$j"; done
    } >"/etc/netns/$prefix$i/hosts"
  done

  # Munge, on its own socket and key: the machine's own munged (if any) is left alone.
  chown munge:munge "$dir/munge"
  chmod 0755 "$dir/munge"  # clients (slurmd, srun) reach the socket in it
  runuser -u munge -- mungekey --create --keyfile "$dir/munge/munge.key" >/dev/null
  runuser -u munge -- munged --socket "$dir/munge/munge.socket" --key-file "$dir/munge/munge.key" \
    --pid-file "$dir/munge/munged.pid" --log-file "$dir/munge/munged.log" \
    --seed-file "$dir/munge/munged.seed"

  write_conf "$n"
  cat >"$dir/env" <<EOF
export SLURM_CONF=$dir/slurm.conf
EOF
  export SLURM_CONF=$dir/slurm.conf
  # The controller, on the bridge's address in this namespace, under its own hostname.
  setsid unshare --uts sh -c "hostname prt-ctl; exec slurmctld -D -i -f $dir/slurm.conf" \
    >"$dir/log/slurmctld.out" 2>&1 </dev/null &
  wait_for 20 "slurmctld answering" scontrol ping
  # Each slurmd in its host's network namespace, with the host's name and /etc/hosts (a mount
  # namespace of its own). Not `ip netns exec`: that mounts a /sys of the namespace's own,
  # without the cgroup file systems slurmd requires.
  for ((i = 0; i < n; i++)); do
    mkdir -p "$dir/spool/$prefix$i"
    setsid nsenter --net="/run/netns/$prefix$i" unshare --mount --uts sh -c \
      "mount --bind /etc/netns/$prefix$i/hosts /etc/hosts && hostname $prefix$i &&
       exec slurmd -D -f $dir/slurm.conf" \
      >"$dir/log/slurmd-$prefix$i.out" 2>&1 </dev/null &
  done
  wait_for 30 "every host idle" all_idle "$n"
  echo "slurm-cluster: $n hosts up (${prefix}0..$prefix$((n - 1))); source $dir/env to use them"
}

all_idle() {
  local idle
  idle=$(sinfo -h -N -t idle -o %N | sort -u | wc -l)
  [ "$idle" -eq "$1" ]
}

kill_node() {
  local i=$1 ns=$prefix$1
  ip netns pids "$ns" 2>/dev/null | xargs -r kill -9 2>/dev/null || true
  bash "$netns" link-down "$i"
}

down() {
  dir=${1:-/tmp/prt-slurm}
  # Every process of every host, then the controller and munged of this cluster.
  for ns in $(ip netns list 2>/dev/null | awk '{print $1}' | grep "^$prefix" || true); do
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -9 2>/dev/null || true
  done
  pkill -9 -f "slurmctld -D -i -f $dir/slurm.conf" 2>/dev/null || true
  if [ -f "$dir/munge/munged.pid" ]; then
    kill "$(cat "$dir/munge/munged.pid")" 2>/dev/null || true
  fi
  bash "$netns" down "$dir/hosts" >/dev/null 2>&1 || true
  rm -rf /etc/netns/${prefix}[0-9]*
  case $dir in
    /tmp/*) rm -rf "$dir" ;;
    *) rm -rf "$dir"/{ctld,spool,run,log,munge,slurm.conf,env} ;;
  esac
}

case ${1:-} in
  up) up "${2:?number of hosts}" "${3:-}" ;;
  kill-node) kill_node "${2:?host index}" ;;
  down) down "${2:-}" ;;
  *)
    echo "usage: $0 up N [DIR] | kill-node I | down [DIR]" >&2
    exit 2
    ;;
esac
