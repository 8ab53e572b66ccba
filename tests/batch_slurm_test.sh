#!/usr/bin/env bash
# `roadscale batch --slurm --submit` on a real Slurm: starts a single-node cluster on this
# machine (scripts/local_slurm.sh: munged, slurmctld, slurmd with a generated slurm.conf, every
# file under a temporary folder), submits three short rendered drives as a job array plus the
# dependent summary job, waits for them, and checks that the summary and every drive's poses equal those of the same
# batch run without Slurm. The daemons are stopped by their process ids on exit.
# Skipped (exit 77, saying why) when not root, when slurm-wlm or munge is not installed, or
# when the daemons do not come up; never passed without a cluster.
# Usage: batch_slurm_test.sh ROADSCALE_BINARY SOURCE_DIR
set -euo pipefail
roadscale="$1"
scripts="$2/scripts"
skip() {
  echo "SKIPPED: $*"
  exit 77
}
work="$(mktemp -d)"
trap '"$scripts/local_slurm.sh" stop "$work/cluster"; rm -rf "$work"' EXIT
scratch="$work"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

# The cluster: one node of 2 CPUs on this machine (scripts/local_slurm.sh).
"$scripts/local_slurm.sh" start "$work/cluster" 2>"$work/cluster.txt" ||
  skip "the single-node Slurm did not start: $(cat "$work/cluster.txt")"
export SLURM_CONF="$work/cluster/slurm.conf"
echo "single-node Slurm up on $(hostname -s)"

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

# Through Slurm: one array task per drive (1 CPU each, so two run at once), then the summary.
"$roadscale" batch --manifest "$work/manifest.yaml" --out "$work/slurm" --slurm --submit \
  --partition roadscale --cpus-per-task 1 >"$work/submit.txt" 2>&1 ||
  fail "submitting failed: $(cat "$work/submit.txt")"
cat "$work/submit.txt"
summary_job="$(sed -n 's/.*summary: job \([0-9]*\).*/\1/p' "$work/submit.txt")"
[[ -n "$summary_job" ]] || fail "no summary job id in: $(cat "$work/submit.txt")"
for _ in $(seq 900); do  # 180 s (about 40 s on an idle 2-core machine)
  [[ -z "$(squeue -h 2>/dev/null)" ]] && break
  sleep 0.2
done
[[ -z "$(squeue -h)" ]] || { squeue; fail "the jobs did not end in 180 s"; }
for task in 0 1 2; do
  [[ -f "$work/slurm/slurm/drive_$task.out" ]] || fail "no output of array task $task"
done
grep -q "^Wrote:  $work/slurm/summary.csv" "$work/slurm/slurm/summary.out" ||
  fail "the summary job did not write the summary: $(cat "$work/slurm/slurm/summary.out" 2>/dev/null)"
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
