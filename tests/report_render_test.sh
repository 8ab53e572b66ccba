#!/usr/bin/env bash
# The run report renders in headless Chromium, with and without ground truth.
# Usage: report_render_test.sh EXAMPLE_PROGRAM CHECK_SCRIPT
# Exit 77 (skipped) when chromium is not installed.
set -euo pipefail
example="$1"
check="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for variant in with_ground_truth no_ground_truth; do
  args=()
  [[ "$variant" == no_ground_truth ]] && args=(--no-ground-truth)
  "$example" "$out/$variant.html" "${args[@]}"
  status=0
  "$check" "$out/$variant.html" "$out/$variant.png" || status=$?
  if ((status != 0)); then
    exit "$status"
  fi
done
echo "report renders: all checks passed"
