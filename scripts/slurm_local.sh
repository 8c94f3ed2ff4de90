#!/usr/bin/env bash
# A single-node Slurm on this machine, localhost only, for trying the regression runner's Slurm
# path (docs/regressions.md) and for its test. Everything lives in DIR: a munge key and socket,
# slurm.conf, the daemons' state, logs and pid files; nothing under /etc or /run is touched.
#   slurm_local.sh start DIR   starts munged, slurmctld and slurmd; prints the SLURM_CONF to use
#   slurm_local.sh stop DIR    stops the three, and fails if one is still running
# Needs root (the daemons run as root here) and Debian's slurm-wlm and munge (scripts/setup.sh).
set -euo pipefail

usage() { echo "usage: $(basename "$0") start|stop DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
action=$1
dir=$(realpath -m "$2")

stop() {
  local left=()
  if [[ -f $dir/slurm.conf ]]; then
    SLURM_CONF=$dir/slurm.conf scontrol shutdown >/dev/null 2>&1 || true
  fi
  for d in slurmd slurmctld munged; do
    local pidf=$dir/$d.pid
    [[ -f $pidf ]] || continue
    local pid
    pid=$(cat "$pidf")
    [[ $d == munged ]] && munged -s --socket="$dir/munge.sock" >/dev/null 2>&1 || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      kill -9 "$pid" 2>/dev/null || true
      sleep 0.2
      kill -0 "$pid" 2>/dev/null && left+=("$d ($pid)")
    fi
    rm -f "$pidf"
  done
  if [[ ${#left[@]} -gt 0 ]]; then
    echo "slurm_local: still running: ${left[*]}" >&2
    return 1
  fi
}

case $action in
  stop) stop; exit ;;
  start) ;;
  *) usage ;;
esac

[[ $(id -u) -eq 0 ]] || { echo "slurm_local: needs root (the daemons run as root)" >&2; exit 2; }
for tool in munged slurmctld slurmd sinfo scontrol; do
  command -v "$tool" >/dev/null ||
    { echo "slurm_local: $tool is missing: run scripts/setup.sh (slurm-wlm, munge)" >&2; exit 2; }
done
mkdir -p "$dir/state" "$dir/spool"
# Two free TCP ports for the controller and the node daemon.
read -r ctld_port d_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
head -c 1024 /dev/urandom >"$dir/munge.key"
chmod 400 "$dir/munge.key"
cat >"$dir/slurm.conf" <<EOF
# slurm_local.sh: one node, this machine, localhost only.
ClusterName=zblend
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
AuthType=auth/munge
AuthInfo=socket=$dir/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=zblend Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
trap 'stop || true' ERR
munged -f --socket="$dir/munge.sock" --key-file="$dir/munge.key" --log-file="$dir/munged.log" \
  --pid-file="$dir/munged.pid" --seed-file="$dir/munged.seed"
export SLURM_CONF=$dir/slurm.conf
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for _ in $(seq 100); do
  state=$(sinfo -h -o %t 2>/dev/null || true)
  [[ $state == idle ]] && break
  sleep 0.2
done
if [[ $state != idle ]]; then
  echo "slurm_local: the node did not come up (state '${state}'); logs in $dir" >&2
  stop || true
  exit 1
fi
echo "SLURM_CONF=$SLURM_CONF"
