#!/usr/bin/env bash
# `roadscale batch --slurm --submit` on a real Slurm: starts a single-node cluster on this
# machine (munged, slurmctld, slurmd with a generated slurm.conf, every file under a temporary
# folder), submits three short rendered drives as a job array plus the dependent summary job,
# waits for them, and checks that the summary and every drive's poses equal those of the same
# batch run without Slurm. The daemons are stopped by their process ids on exit.
# Skipped (exit 77, saying why) when not root, when slurm-wlm or munge is not installed, or
# when the daemons do not come up; never passed without a cluster.
# Usage: batch_slurm_test.sh ROADSCALE_BINARY
set -euo pipefail
roadscale="$1"
skip() {
  echo "SKIPPED: $*"
  exit 77
}
fail() {
  echo "FAILED: $*"
  exit 1
}
[[ $(id -u) -eq 0 ]] || skip "the single-node Slurm needs root (slurmd runs jobs as their users)"
for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null 2>&1 || [[ -x "/usr/sbin/$tool" ]] ||
    skip "$tool not found: install slurm-wlm and munge (scripts/setup.sh does)"
done
export PATH="$PATH:/usr/sbin"

work="$(mktemp -d)"
chmod 755 "$work"  # munged wants its socket's folder readable by every user
daemons=()  # process ids of the daemons this test started
started() {  # PID_FILE: remembers the daemon's process id (it removes the file on exit)
  for _ in $(seq 50); do
    [[ -s "$work/$1" ]] && { daemons+=("$(cat "$work/$1")"); return 0; }
    sleep 0.1
  done
  return 1
}
cleanup() {
  for pid in "${daemons[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${daemons[@]}"; do  # wait until they are gone
    for _ in $(seq 50); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
  done
  rm -rf "$work"
}
trap cleanup EXIT
show_logs() {
  for log in munged.log slurmctld.log slurmd.log; do
    [[ -f "$work/$log" ]] && { echo "--- $log"; tail -n 15 "$work/$log"; }
  done
}

# Three short drives, then the batch without Slurm: the reference.
for seed in 1 2 3; do
  "$roadscale" synth --preset urban --frames 40 --seed "$seed" --out "$work/d$seed" >/dev/null 2>&1 ||
    fail "synth failed"
done
{
  echo "drives:"
  for seed in 1 2 3; do
    printf '  - name: drive%s\n    kitti: d%s/sequences/00\n    labels: d%s/sequences/00/semantic\n' \
      "$seed" "$seed" "$seed"
  done
} >"$work/manifest.yaml"
"$roadscale" batch --manifest "$work/manifest.yaml" --out "$work/local" --jobs 2 >"$work/local.txt" 2>&1 ||
  fail "batch without Slurm failed: $(cat "$work/local.txt")"

# The cluster: munge with its own key and socket, one node of 2 CPUs, one partition.
head -c 1024 /dev/urandom >"$work/munge.key"
chmod 400 "$work/munge.key"
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" \
  --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munged.seed" &&
  started munged.pid || { show_logs; skip "munged did not start"; }
mkdir -p "$work/state" "$work/spool"
host="$(hostname -s)"
cat >"$work/slurm.conf" <<CONF
ClusterName=roadscaletest
SlurmctldHost=$host
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=roadscale Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
slurmctld -f "$SLURM_CONF" && started slurmctld.pid || { show_logs; skip "slurmctld did not start"; }
slurmd -f "$SLURM_CONF" && started slurmd.pid || { show_logs; skip "slurmd did not start"; }
for _ in $(seq 100); do
  [[ "$(sinfo -h -o %t 2>/dev/null)" == "idle" ]] && break
  sleep 0.2
done
[[ "$(sinfo -h -o %t 2>/dev/null)" == "idle" ]] ||
  { show_logs; skip "the node did not become idle in 20 s (sinfo: $(sinfo 2>&1 | tr '\n' ' '))"; }
echo "single-node Slurm up on $host"

# Through Slurm: one array task per drive (1 CPU each, so two run at once), then the summary.
"$roadscale" batch --manifest "$work/manifest.yaml" --out "$work/slurm" --slurm --submit \
  --partition roadscale --cpus-per-task 1 >"$work/submit.txt" 2>&1 ||
  { show_logs; fail "submitting failed: $(cat "$work/submit.txt")"; }
cat "$work/submit.txt"
summary_job="$(sed -n 's/.*summary: job \([0-9]*\).*/\1/p' "$work/submit.txt")"
[[ -n "$summary_job" ]] || fail "no summary job id in: $(cat "$work/submit.txt")"
for _ in $(seq 900); do  # 180 s (about 40 s on an idle 2-core machine)
  [[ -z "$(squeue -h 2>/dev/null)" ]] && break
  sleep 0.2
done
[[ -z "$(squeue -h)" ]] || { squeue; show_logs; fail "the jobs did not end in 180 s"; }
for task in 0 1 2; do
  [[ -f "$work/slurm/slurm/drive_$task.out" ]] || fail "no output of array task $task"
done
[[ -f "$work/slurm/summary.csv" ]] ||
  fail "no summary: $(cat "$work/slurm/slurm/summary.out" 2>/dev/null)"
cat "$work/slurm/summary.md"

# Slurm's batch equals the local one: the same poses, the same summary but for frames/s.
for seed in 1 2 3; do
  cmp -s "$work/local/drive$seed/poses_kitti.txt" "$work/slurm/drive$seed/poses_kitti.txt" ||
    fail "drive$seed: the poses differ from the run without Slurm"
done
without_speed() { python3 -c "
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
speed = rows[0].index('frames_per_s')
for row in rows: print(','.join(row[:speed] + row[speed + 1:]))" "$1"; }
[[ "$(without_speed "$work/slurm/summary.csv")" == "$(without_speed "$work/local/summary.csv")" ]] ||
  fail "the summaries differ: $(cat "$work/slurm/summary.csv") vs $(cat "$work/local/summary.csv")"
[[ "$(grep -c . "$work/slurm/summary.csv")" -eq 5 ]] || fail "expected a header, 3 drives and the mean"
echo "batch through Slurm: all checks passed"
