#!/bin/bash
# Written by `roadscale batch --slurm`: submits the drives' job array, then the summary
# to run after every task has ended (afterany: it lists failed drives too).
set -euo pipefail
drives_job=$(sbatch --parsable /shared/out/slurm/drives.sbatch)
drives_job=${drives_job%%;*}  # "id;cluster" on a federation
summary_job=$(sbatch --parsable --dependency=afterany:"$drives_job" /shared/out/slurm/summary.sbatch)
echo "drives: job $drives_job (3 array tasks); summary: job ${summary_job%%;*}"
