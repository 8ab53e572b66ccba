#!/usr/bin/env bash
# The run report renders in headless Chromium: 600 frames with ground truth, and a single
# frame without.
# Usage: report_render_test.sh EXAMPLE_PROGRAM CHECK_SCRIPT
# Exit 77 (skipped) when chromium is not installed.
set -euo pipefail
example="$1"
check="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for variant in with_ground_truth one_frame_no_ground_truth; do
  args=()
  [[ "$variant" == one_frame_no_ground_truth ]] && args=(--no-ground-truth --frames 1)
  "$example" "$out/$variant.html" "${args[@]}"
  status=0
  "$check" "$out/$variant.html" "$out/$variant.png" || status=$?
  if ((status != 0)); then
    exit "$status"
  fi
done
echo "report renders: all checks passed"
