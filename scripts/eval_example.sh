#!/usr/bin/env bash
# Shows `roadscale eval` on real KITTI ground truth until the pipeline can produce an
# estimate of its own. The "estimate" here is a stand-in with a known error: KITTI's own
# poses with every frame-to-frame step stretched by a factor that grows linearly from 1.00
# at the first frame to 1.10 at the last (rotations untouched), the kind of scale drift a
# monocular VO without scale recovery shows. It is not roadscale's output. Prints the table
# and writes the plots.
#
#   scripts/eval_example.sh [SEQUENCE]     # default 00; needs build/roadscale (scripts/setup.sh)
#
# Files go to build/eval_example/ (OUT_DIR=... to change). ROADSCALE_SHARED as everywhere.
set -euo pipefail
cd "$(dirname "$0")/.."
sequence=${1:-00}
shared=${ROADSCALE_SHARED:-../shared}
gt="$shared/kitti/poses/$sequence.txt"
roadscale=${ROADSCALE_BIN:-build/roadscale}
out=${OUT_DIR:-build/eval_example}
if [[ ! -f "$gt" ]]; then
  echo "eval_example: $gt not found (set ROADSCALE_SHARED to the shared data folder)" >&2
  exit 1
fi
if [[ ! -x "$roadscale" ]]; then
  echo "eval_example: $roadscale not found: run scripts/setup.sh first" >&2
  exit 1
fi
mkdir -p "$out"
est="$out/${sequence}_scale_drift_10pct.txt"
# Rotations are the ground truth's, so stretching the world-frame step p[i] - p[i-1] by s is
# stretching the camera-frame step by s.
awk -v CONVFMT="%.12e" -v OFMT="%.12e" '
  { rows[NR] = $0 }
  END {
    for (i = 1; i <= NR; i++) {
      split(rows[i], v, " ")
      if (i == 1) { x = v[4]; y = v[8]; z = v[12] }
      else {
        s = 1.0 + 0.10 * (i - 2) / (NR - 2)
        x += s * (v[4] - px); y += s * (v[8] - py); z += s * (v[12] - pz)
      }
      px = v[4]; py = v[8]; pz = v[12]
      v[4] = x; v[8] = y; v[12] = z
      line = v[1]
      for (k = 2; k <= 12; k++) line = line " " v[k]
      print line
    }
  }' "$gt" >"$est"
echo "Stand-in estimate $est: KITTI $sequence's ground truth with each step stretched by"
echo "1.00 (first) to 1.10 (last frame); an example of scale drift, not roadscale's output."
echo
"$roadscale" eval --gt "$gt" --est "$est" --plot "$out/plots"
