#!/usr/bin/env bash
# examples/python_odometry.py on the first 30 frames of the shared KITTI 00 (skipped, status
# 77, without them): it runs, collects 30 poses and evaluates them against the ground truth.
# Usage: python_example_test.sh PYTHON BUILD_DIR SOURCE_DIR SHARED_DIR
set -euo pipefail
python="$1"
build="$2"
source_dir="$3"
shared="${ROADSCALE_SHARED:-$4}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

sequence="$shared/kitti/sequences/00"
if [[ ! -d "$sequence/image_0" ]]; then
  echo "SKIPPED: no shared KITTI 00 frames in $sequence"
  exit 77
fi
"$python" "$source_dir/examples/python_odometry.py" "$build" "$sequence" 30 >"$scratch/out.txt" 2>&1 ||
  fail "the example failed: $(cat "$scratch/out.txt")"
cat "$scratch/out.txt"
expect_line "$scratch/out.txt" "^30 poses, "
awk '/^against the ground truth: length ratio/ { found = 1; ratio = $6 + 0
       if (ratio < 0.9 || ratio > 1.1) exit 1 }
     END { exit !found }' "$scratch/out.txt" ||
  fail "no evaluation, or a length ratio beyond 10 %: $(cat "$scratch/out.txt")"
echo "python example: all checks passed"
