#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# A throwaway single-node Slurm (munged + slurmctld + slurmd, Debian's
# slurm-wlm 22.05) in a scratch folder, without systemd, for the Slurm tests.
#
#   slurm_cluster.sh start DIR   writes DIR/slurm.conf, starts the daemons,
#                                waits until `sinfo` shows the node idle;
#                                prints `export SLURM_CONF=DIR/slurm.conf`
#   slurm_cluster.sh stop DIR    kills every daemon started in DIR
#   slurm_cluster.sh ctld-stop DIR | ctld-start DIR   controller outage
#
# The node is this host under the name "gf<port>", eight CPUs or more; job
# records go to DIR/jobcomp.log (jobcomp/filetxt: Slurm's own record of every
# job that ended, read by the tests to count runs). There is no slurmdbd, so
# `sacct` is unavailable, as on many small clusters. Must run as root (slurmd
# starts jobs as their submitting user). The two ports are chosen below the
# kernel's ephemeral range (so no outgoing connection can hold them), among
# those no socket on this host uses, from the PID so that two runs at once
# start apart; if slurmctld or slurmd still finds its port taken, start picks
# the next pair and tries again (five pairs).
set -eu
cmd=${1:?usage: slurm_cluster.sh start|stop|ctld-stop|ctld-start DIR}
dir=${2:?usage: slurm_cluster.sh start|stop|ctld-stop|ctld-start DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
conf=$dir/slurm.conf

kill_pid() {  # kill_pid PIDFILE: KILL at once (the cluster is thrown away)
  [ -f "$1" ] || return 0
  pid=$(cat "$1" 2>/dev/null || true)
  rm -f "$1"
  [ -n "$pid" ] || return 0
  kill -9 "$pid" 2>/dev/null || return 0
  i=0
  while kill -0 "$pid" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.05; i=$((i + 1)); done
}

stop_pid() {  # stop_pid PIDFILE: TERM, then KILL after 5 s
  [ -f "$1" ] || return 0
  pid=$(cat "$1" 2>/dev/null || true)
  rm -f "$1"
  [ -n "$pid" ] || return 0
  kill "$pid" 2>/dev/null || return 0
  i=0
  while kill -0 "$pid" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
  kill -9 "$pid" 2>/dev/null || true
}

wait_for() {  # wait_for SECONDS COMMAND...: until COMMAND succeeds
  limit=$(($1 * 10)); shift
  i=0
  until "$@" >/dev/null 2>&1; do
    i=$((i + 1))
    if [ $i -ge $limit ]; then return 1; fi
    sleep 0.1
  done
}

port_in_use() {  # port_in_use PORT: some TCP socket (any state) has it as its local port
  hex=$(printf '%04X' "$1")
  cat /proc/net/tcp /proc/net/tcp6 2>/dev/null | awk -v p=":$hex" 'NR > 1 && substr($2, length($2) - 4) == p { found = 1 } END { exit !found }'
}

pick_ports() {  # pick_ports ATTEMPT: sets port (even) with port and port + 1 free
  low=$(($(cut -f1 /proc/sys/net/ipv4/ip_local_port_range 2>/dev/null || echo 32768) - 2))
  [ "$low" -gt 12000 ] || low=32766
  span=$(((low - 10000) / 2))
  k=0
  while [ $k -lt 200 ]; do
    port=$((10000 + (($$ + 7919 * ($1 * 200 + k)) % span) * 2))
    port_in_use $port || port_in_use $((port + 1)) || return 0
    k=$((k + 1))
  done
  echo "slurm_cluster.sh: no free pair of ports found" >&2
  return 1
}

node_idle() { SLURM_CONF=$conf sinfo -h -o %T 2>/dev/null | grep -qx idle; }
ctld_up() { SLURM_CONF=$conf scontrol ping 2>/dev/null | grep -q UP; }

try_ctld() {  # try_ctld: start slurmctld and wait until it answers (or cannot bind)
  slurmctld -f "$conf" -i -L "$dir/slurmctld.log"
  wait_for 30 ctld_up_or_port_taken
  ctld_up
}

start_ctld() {
  try_ctld || {
    echo "slurmctld did not answer; log:" >&2
    tail -20 "$dir/slurmctld.log" >&2
    "$0" stop "$dir"
    exit 1
  }
}

port_taken() {  # port_taken LOG: the daemon writing LOG could not bind its port
  grep -q "Address already in use" "$1" 2>/dev/null
}
ctld_up_or_port_taken() { ctld_up || port_taken "$dir/slurmctld.log"; }
node_idle_or_slurmd_port_taken() { node_idle || port_taken "$dir/slurmd.log"; }

write_conf() {  # write_conf: slurm.conf for the node gf$port on ports $port and $port + 1
  node=gf$port
  # Eight CPUs or the real count if larger (config_overrides lets slurmd
  # believe the configuration), so that -j 8 runs eight tiny jobs at once.
  cpus=${GRIDFREE_SLURM_CPUS:-$(nproc)}; [ "$cpus" -ge 8 ] || cpus=8
  mem=$(awk '/MemTotal/ { print int($2 / 1024 / 2) }' /proc/meminfo)
  cat > "$conf" <<CONF
ClusterName=gridfree-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$short/munge.socket
SlurmdParameters=config_overrides
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/spool/ctld
SlurmdSpoolDir=$short/d
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.log
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=${GRIDFREE_SLURM_MIN_JOB_AGE:-300}
DefMemPerCPU=64
MaxJobCount=100000
MaxArraySize=100001
SchedulerParameters=sched_min_interval=0,batch_sched_delay=0,default_queue_depth=1000
SlurmctldTimeout=30
SlurmdTimeout=60
MessageTimeout=10
InactiveLimit=0
KillWait=2
SlurmctldDebug=info
SlurmdDebug=info
SlurmdLogFile=$dir/slurmd.log
NodeName=$node NodeHostname=$(hostname) NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
PartitionName=short Nodes=$node Default=NO MaxTime=1 State=UP
CONF
}

case $cmd in
start)
  [ "$(id -u)" = 0 ] || { echo "slurm_cluster.sh: must run as root" >&2; exit 1; }
  for tool in munged slurmctld slurmd sinfo sbatch; do
    command -v $tool >/dev/null || { echo "slurm_cluster.sh: $tool not found (install slurmctld slurmd munge)" >&2; exit 1; }
  done
  # Unix socket paths may not exceed 108 bytes: munged's socket and slurmd's
  # spool (which holds the step sockets) go to a short folder of their own.
  short=$(mktemp -d /tmp/gfslurm.XXXXXX)
  echo "$short" > "$dir/short_dir"
  mkdir -p "$dir/spool/ctld" "$short/d" "$dir/munge"
  chmod 700 "$dir/munge"
  [ -f "$dir/munge/munge.key" ] || { dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 2>/dev/null; chmod 400 "$dir/munge/munge.key"; }
  munged -f --socket="$short/munge.socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed"
  wait_for 10 test -S "$short/munge.socket"
  attempt=0
  while :; do
    pick_ports $attempt || { "$0" stop "$dir"; exit 1; }
    write_conf
    rm -rf "$dir/slurmctld.log" "$dir/slurmd.log" "$dir/spool/ctld"
    mkdir -p "$dir/spool/ctld"
    if try_ctld; then
      slurmd -f "$conf" -N "$node" -L "$dir/slurmd.log"
      wait_for 60 node_idle_or_slurmd_port_taken || true
      node_idle && break
      why="node never became idle"
    else
      why="slurmctld did not answer"
    fi
    if { port_taken "$dir/slurmctld.log" || port_taken "$dir/slurmd.log"; } && [ $attempt -lt 4 ]; then
      stop_pid "$dir/slurmd.pid"
      stop_pid "$dir/slurmctld.pid"
      attempt=$((attempt + 1))
      continue
    fi
    echo "$why; logs:" >&2
    tail -20 "$dir/slurmd.log" "$dir/slurmctld.log" >&2 2>/dev/null
    "$0" stop "$dir"
    exit 1
  done
  echo "export SLURM_CONF=$conf"
  ;;
stop)
  # Each daemon takes about 2 s to exit on TERM; a test's cluster keeps
  # nothing, so its teardown kills them.
  kill_pid "$dir/slurmd.pid"
  kill_pid "$dir/slurmctld.pid"
  kill_pid "$dir/munge/munged.pid"
  if [ -f "$dir/short_dir" ]; then
    short=$(cat "$dir/short_dir")
    case $short in /tmp/gfslurm.*) rm -rf "$short" ;; esac
    rm -f "$dir/short_dir"
  fi
  ;;
ctld-stop) stop_pid "$dir/slurmctld.pid" ;;
ctld-start) start_ctld ;;
*) echo "slurm_cluster.sh: unknown command $cmd" >&2; exit 2 ;;
esac
