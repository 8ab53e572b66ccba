#!/usr/bin/env bash
# End-to-end tests of `roadscale rescale`.
# Usage: rescale_cli_test.sh ROADSCALE_BINARY [synth|errors]
#   synth:  a 30-frame synthetic street; its ground truth shrunk to 0.3 times (KITTI rows, all
#           frames) and, from that run's metric output, every 3rd pose at half scale (TUM,
#           keyframes associated by time): both come back with one output row per input pose,
#           one rescale.csv row per step, and a length ratio within 5 % of the truth; the
#           exact input is said to agree with the road, one with steps 20 % off is not;
#   errors: more poses than frames, a timestamp matching no frame, an unknown row format, no
#           input, --images without a camera: each fails with one line saying what is wrong.
set -euo pipefail
roadscale="$1"
mode="${2:-errors}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"
# The "rescaled" length ratio of a run's evaluation summary must be within 5 % of 1.
expect_ratio_near_one() {  # LOG
  awk '$1 == "rescaled" { found = 1; if ($2 < 0.95 || $2 > 1.05) exit 1 } END { exit !found }' \
    "$1" || fail "rescaled length ratio not within 5 % of 1: $(cat "$1")"
}

if [[ "$mode" == "synth" ]]; then
  "$roadscale" synth --preset urban --frames 30 --seed 1 --out "$out/data" >/dev/null 2>&1 ||
    fail "synth failed"
  sequence="$out/data/sequences/00"
  # A constant scale of 0.3: every position times 0.3 (frame 0 is the origin).
  awk '{ $4 *= 0.3; $8 *= 0.3; $12 *= 0.3; print }' "$out/data/poses/00.txt" >"$out/ext.txt"
  "$roadscale" rescale --trajectory "$out/ext.txt" --kitti "$sequence" \
    --labels "$sequence/semantic" --out "$out/all" >"$out/log.txt" 2>&1 ||
    fail "rescale failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  expect_line "$out/log.txt" "^Trajectory: .*\(KITTI, 30 poses on frames 0\.\.29 of 30\)"
  expect_line "$out/log.txt" "^Segmentation: label images"
  expect_line "$out/log.txt" "^  input +0\.3000 "
  expect_ratio_near_one "$out/log.txt"
  [[ "$(wc -l <"$out/all/poses_kitti.txt")" -eq 30 ]] || fail "expected 30 KITTI rows"
  awk 'NF != 12 { exit 1 }' "$out/all/poses_kitti.txt" || fail "a KITTI row without 12 numbers"
  [[ "$(wc -l <"$out/all/poses_tum.txt")" -eq 30 ]] || fail "expected 30 TUM rows"
  awk 'NF != 8 { exit 1 }' "$out/all/poses_tum.txt" || fail "a TUM row without 8 numbers"
  [[ "$(wc -l <"$out/all/rescale.csv")" -eq 30 ]] || fail "expected a header and 29 steps"
  expect_line "$out/all/rescale.csv" '^pose,frame_a,frame_b,timestamp,status,.*,total_ms$'
  expect_line "$out/all/rescale.csv" '^29,28,29,[^,]+,"(ok|held)",'
  [[ "$(grep -c ',"ok",' "$out/all/rescale.csv")" -ge 20 ]] || fail "fewer than 20 road-scaled steps"
  # An exact input: its steps agree with the road within the fixes' noise, and it is said.
  expect_line "$out/log.txt" "^Agreement: "
  expect_line "$out/log.txt" "warning: the input's step lengths agree with the road"

  # Each step's length off by up to 20 % (directions kept): the default takes the road's
  # lengths without a warning; --smooth-ratio is told that it keeps the errors.
  awk 'BEGIN { srand(7) }
       { f = 0.3 * (1 + 0.4 * (rand() - 0.5))
         if (NR > 1) { x += f * ($4 - px); y += f * ($8 - py); z += f * ($12 - pz) }
         px = $4; py = $8; pz = $12; $4 = x + 0; $8 = y + 0; $12 = z + 0; print }' \
    "$out/data/poses/00.txt" >"$out/jitter.txt"
  "$roadscale" rescale --trajectory "$out/jitter.txt" --kitti "$sequence" \
    --labels "$sequence/semantic" --out "$out/jitter" >"$out/log.txt" 2>&1 ||
    fail "rescale of the jittered input failed: $(cat "$out/log.txt")"
  expect_line "$out/log.txt" "^Agreement: "
  if grep -q "warning: the input's step lengths agree" "$out/log.txt"; then
    fail "a jittered input was taken for one as good as the road: $(cat "$out/log.txt")"
  fi
  expect_ratio_near_one "$out/log.txt"
  "$roadscale" rescale --trajectory "$out/jitter.txt" --kitti "$sequence" \
    --labels "$sequence/semantic" --smooth-ratio --out "$out/jitter_smooth" >"$out/log.txt" 2>&1 ||
    fail "rescale --smooth-ratio of the jittered input failed: $(cat "$out/log.txt")"
  expect_line "$out/log.txt" "warning: the input's step lengths vary by about .* --smooth-ratio keeps"

  # Keyframes: every 3rd pose of the metric output, at half scale, as TUM rows.
  awk 'NR % 3 == 1 { $2 *= 0.5; $3 *= 0.5; $4 *= 0.5; print }' "$out/all/poses_tum.txt" \
    >"$out/keyframes.txt"
  "$roadscale" rescale --trajectory "$out/keyframes.txt" --kitti "$sequence" \
    --labels "$sequence/semantic" --out "$out/keyframes" >"$out/log.txt" 2>&1 ||
    fail "rescale of keyframes failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  expect_line "$out/log.txt" "^Trajectory: .*\(TUM, 10 poses associated by time with frames 0\.\.27 of 30\)"
  expect_ratio_near_one "$out/log.txt"
  [[ "$(wc -l <"$out/keyframes/poses_kitti.txt")" -eq 10 ]] || fail "expected 10 rows"
  expect_line "$out/keyframes/rescale.csv" '^1,0,3,'
  expect_line "$out/keyframes/rescale.csv" '^9,24,27,'
  echo "rescale on a synthetic street (all frames, keyframes): all checks passed"
  exit 0
fi

"$roadscale" synth --frames 3 --out "$out/data" >/dev/null 2>&1 || fail "synth failed"
sequence="$out/data/sequences/00"
cp "$out/data/poses/00.txt" "$out/three.txt"
{ cat "$out/three.txt"; tail -1 "$out/three.txt"; } >"$out/four.txt"
expect_failure "four.txt: has 4 poses but there are only 3 frames" \
  "$roadscale" rescale --trajectory "$out/four.txt" --kitti "$sequence" --out "$out/run"
printf '0 0 0 0 0 0 0 1\n0.1 0 0 1 0 0 0 1\n0.75 0 0 2 0 0 0 1\n' >"$out/late.txt"
expect_failure "late.txt: pose 2 \(timestamp 0.75 s\) matches no frame" \
  "$roadscale" rescale --trajectory "$out/late.txt" --kitti "$sequence" --out "$out/run"
printf '0 0 0 0 0 0 0 1\n0.05 0 0 1 0 0 0 1\n' >"$out/between.txt"
expect_failure "matches no frame" \
  "$roadscale" rescale --trajectory "$out/between.txt" --kitti "$sequence" --out "$out/run"
printf '1 2 3 4 5\n' >"$out/five.txt"
expect_failure "five.txt:1: cannot tell the format from a row of 5 numbers" \
  "$roadscale" rescale --trajectory "$out/five.txt" --kitti "$sequence" --out "$out/run"
expect_failure "needs --kitti SEQ_DIR or --images DIR" \
  "$roadscale" rescale --trajectory "$out/three.txt" --out "$out/run"
expect_failure "--images needs --camera" \
  "$roadscale" rescale --trajectory "$out/three.txt" --images "$sequence/image_0" --out "$out/run"
expect_failure "no-such-labels: label folder not found" \
  "$roadscale" rescale --trajectory "$out/three.txt" --kitti "$sequence" \
  --labels "$out/no-such-labels" --out "$out/run"
echo "rescale errors: all checks passed"
