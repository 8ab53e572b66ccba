#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, every file of it under one folder: for the live
# test of `roadscale batch --slurm` (tests/batch_slurm_test.sh) and its benchmark
# (docs/benchmark-history.md, "Batch"). Needs root and Debian's slurm-wlm and munge.
#
#   scripts/local_slurm.sh start DIR   # munged, slurmctld, slurmd; waits until the node is idle
#   export SLURM_CONF=DIR/slurm.conf   # then sbatch, squeue, sinfo talk to it
#   scripts/local_slurm.sh stop DIR    # stops the daemons it started, by their process ids
#
# munged gets its own 1 KiB random key and socket in DIR (the machine's /etc/munge is left
# alone); slurm.conf: auth/munge, proctrack/linuxproc, task/none, select/cons_tres with CPUs
# the only consumable resource (CR_CPU: with memory counted too, every job would take the
# node's whole memory and the tasks would run one at a time), SlurmUser root, one node
# `hostname -s` with CPUs=2 in one partition "roadscale", ports 16817-16818.
# `start` fails with the reason on stderr (and the daemons' last log lines), stopping what it
# started, when a daemon does not come up.
set -euo pipefail
command="${1:-}"
dir="${2:-}"
[[ -n "$dir" && ( "$command" == start || "$command" == stop ) ]] ||
  { echo "usage: $0 start|stop DIR" >&2; exit 2; }
export PATH="$PATH:/usr/sbin"
pids="$dir/daemons.pids"

if [[ "$command" == stop ]]; then
  [[ -f "$pids" ]] || exit 0
  mapfile -t started <"$pids"
  for pid in "${started[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${started[@]}"; do  # wait until they are gone
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
  done
  rm -f "$pids"
  exit 0
fi

fail() {
  echo "local_slurm: $*" >&2
  for log in munged.log slurmctld.log slurmd.log; do
    [[ -f "$dir/$log" ]] && { echo "--- $log" >&2; tail -n 15 "$dir/$log" >&2; }
  done
  [[ -f "$pids" ]] && "$0" stop "$dir"  # the daemons that did start
  exit 1
}
[[ $(id -u) -eq 0 ]] || fail "needs root (slurmd runs jobs as their users)"
for tool in munged slurmctld slurmd sinfo; do
  command -v "$tool" >/dev/null 2>&1 || fail "$tool not found: install slurm-wlm and munge (scripts/setup.sh does)"
done
mkdir -p "$dir/state" "$dir/spool"
dir="$(cd "$dir" && pwd)"
pids="$dir/daemons.pids"
chmod 755 "$dir"  # munged wants its socket's folder readable by every user
: >"$pids"
remember() {  # PID_FILE: the daemon's process id, once it has written it
  for _ in $(seq 50); do
    [[ -s "$dir/$1" ]] && { cat "$dir/$1" >>"$pids"; return 0; }
    sleep 0.1
  done
  return 1
}

head -c 1024 /dev/urandom >"$dir/munge.key"
chmod 400 "$dir/munge.key"
munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" \
  --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" &&
  remember munged.pid || fail "munged did not start"

host="$(hostname -s)"
cat >"$dir/slurm.conf" <<CONF
ClusterName=roadscalelocal
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=roadscale Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"
slurmctld -f "$SLURM_CONF" && remember slurmctld.pid || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" && remember slurmd.pid || fail "slurmd did not start"
for _ in $(seq 100); do
  [[ "$(sinfo -h -o %t 2>/dev/null)" == "idle" ]] && exit 0
  sleep 0.2
done
fail "the node did not become idle in 20 s (sinfo: $(sinfo 2>&1 | tr '\n' ' '))"
