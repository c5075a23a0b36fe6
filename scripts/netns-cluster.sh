#!/usr/bin/env bash
# A cluster of N hosts on this machine, for testing PRT's fault handling over real TCP links:
# each host is a network namespace (own hostname, own address) joined to a bridge, and mpirun
# starts its daemons in them through a launch agent instead of ssh. Needs root.
#
#   scripts/netns-cluster.sh up N [DIR]   create hosts prt-h0 .. prt-h(N-1) on 10.231.0.0/24;
#                                         DIR (default /tmp/prt-netns) gets `hostfile`,
#                                         `agent` (the launch agent) and `mpirun-flags`
#   scripts/netns-cluster.sh link-down I  cut host I off (its link on the bridge goes down)
#   scripts/netns-cluster.sh link-up I    restore it
#   scripts/netns-cluster.sh down [DIR]   remove every host, the bridge and DIR's files
#
# Run a job across the hosts with:
#   mpirun $(cat DIR/mpirun-flags) --hostfile DIR/hostfile -np 3 build/prt render ...
# Traffic stays on the bridge's private subnet, inside this machine.
#
# Two clusters can stand side by side: PRT_NETNS_PREFIX (default prt-h) names the hosts, the
# bridge (PREFIX-br) and the host ends of the links (PREFIX-vI); PRT_NETNS_SUBNET (default
# 10.231.0) is their /24. scripts/slurm-cluster.sh uses prt-s on 10.232.0.
set -euo pipefail

prefix=${PRT_NETNS_PREFIX:-prt-h}
subnet=${PRT_NETNS_SUBNET:-10.231.0}
bridge=$prefix-br
veth=$prefix-v

host_ip() { echo "$subnet.$((10 + $1))"; }

up() {
  local n=$1 dir=${2:-/tmp/prt-netns}
  down "$dir" 2>/dev/null || true
  mkdir -p "$dir"
  # No spanning tree and no forwarding delay: a port forwards as soon as it is up.
  ip link add "$bridge" type bridge stp_state 0 forward_delay 0
  ip addr add "$subnet.1/24" dev "$bridge"
  ip link set "$bridge" up
  : >"$dir/hostfile"
  for ((i = 0; i < n; i++)); do
    local ns=$prefix$i
    ip netns add "$ns"
    ip link add "$veth$i" type veth peer name eth0 netns "$ns"
    ip link set "$veth$i" master "$bridge" up
    ip -n "$ns" addr add "$(host_ip "$i")/24" dev eth0
    ip -n "$ns" link set eth0 up
    ip -n "$ns" link set lo up
    echo "$ns slots=1" >>"$dir/hostfile"
  done
  # Links come up asynchronously: an mpirun started before every port forwards fails to reach
  # its daemons ("unable to reliably start one or more daemons"). Wait for them (5 s at most).
  local ready=0
  for ((t = 0; t < 100 && ready == 0; t++)); do
    ready=1
    [ "$(cat "/sys/class/net/$bridge/operstate")" = up ] || ready=0
    for ((i = 0; i < n; i++)); do
      [ "$(cat "/sys/class/net/$veth$i/brport/state" 2>/dev/null)" = 3 ] || ready=0
      [ "$(ip netns exec "$prefix$i" cat /sys/class/net/eth0/operstate)" = up ] || ready=0
    done
    ((ready == 1)) || sleep 0.05
  done
  ((ready == 1)) || echo "netns-cluster: warning: links not all up after 5 s" >&2
  # The launch agent: mpirun calls it as `agent HOST COMMAND...` to start its daemon on HOST.
  # The daemon runs in HOST's namespace with HOST as its hostname (a UTS namespace of its own).
  cat >"$dir/agent" <<'AGENT'
#!/bin/sh
host=$1
shift
exec ip netns exec "$host" unshare --uts sh -c "hostname $host; $*"
AGENT
  chmod +x "$dir/agent"
  echo "--mca plm_rsh_agent $dir/agent --mca btl tcp,self" \
    "--mca btl_tcp_if_include $subnet.0/24 --mca oob_tcp_if_include $subnet.0/24" \
    >"$dir/mpirun-flags"
  echo "netns-cluster: $n hosts up (${prefix}0..$prefix$((n - 1))), files in $dir"
}

down() {
  local dir=${1:-/tmp/prt-netns}
  for ns in $(ip netns list 2>/dev/null | awk '{print $1}' | grep "^$prefix" || true); do
    ip netns pids "$ns" 2>/dev/null | xargs -r kill -9 2>/dev/null || true
    ip netns del "$ns" 2>/dev/null || true
  done
  for v in $(ip -o link show 2>/dev/null | awk -F': ' '{print $2}' | grep "^$veth" | cut -d@ -f1 || true); do
    ip link del "$v" 2>/dev/null || true
  done
  ip link del "$bridge" 2>/dev/null || true
  rm -f "$dir/hostfile" "$dir/agent" "$dir/mpirun-flags"
  rmdir "$dir" 2>/dev/null || true
}

case ${1:-} in
  up) up "${2:?number of hosts}" "${3:-}" ;;
  down) down "${2:-}" ;;
  link-down) ip link set "$veth${2:?host index}" down ;;
  link-up) ip link set "$veth${2:?host index}" up ;;
  *)
    echo "usage: $0 up N [DIR] | link-down I | link-up I | down [DIR]" >&2
    exit 2
    ;;
esac
