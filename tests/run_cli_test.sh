#!/usr/bin/env bash
# End-to-end tests of `roadscale run`.
# Usage: run_cli_test.sh ROADSCALE_BINARY DEFAULT_SHARED_DIR [kitti|road|full|traffic|slow|errors]
#   kitti:  --scale oracle on the first 30 shared KITTI 00 frames writes 30 pose rows and 30
#           frame records, and the trajectory moves forward about as far as the ground truth
#           (skipped, exit 77, without the shared data);
#   road:   the default --scale road on the same frames: every step scaled from the road plane
#           ("ok"), its diagnostics columns in frames.csv, and the trajectory 20-30 m ahead;
#   full:   the whole system (the shared network, road scale) on the 200 shared frames: its
#           KITTI error, ATE and length ratio within tolerances of the measured values
#           (skipped, exit 77, without the frames, their poses or the network);
#   traffic: the real city drive in dense traffic (../shared/kitti_raw, no ground truth): every
#           frame scaled, every step a creeping car's, the stop at its end standing still;
#   slow:   KITTI 07's first 160 frames (pulling away, slow driving): length ratio and ATE
#           within tolerances of the measured values;
#   errors: a missing sequence, --scale oracle without ground truth, an unknown detector and
#           an unknown scale source each fail with one line saying what is wrong.
set -euo pipefail
roadscale="$1"
shared="${ROADSCALE_SHARED:-$2}"
mode="${3:-errors}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

# Skips the test (exit 77, as CTest's SKIP_RETURN_CODE) when a shared file it needs is missing.
skip_unless_shared() {  # FILE...
  local needed
  for needed in "$@"; do
    [[ -f "$needed" ]] || { echo "$needed missing (set ROADSCALE_SHARED): skipped"; exit 77; }
  done
}

sequence="$shared/kitti/sequences/00"
if [[ "$mode" == "kitti" ]]; then
  if [[ ! -f "$sequence/calib.txt" || ! -f "$shared/kitti/poses/00.txt" ]]; then
    echo "$sequence or its poses missing (set ROADSCALE_SHARED): skipped"
    exit 77
  fi
  "$roadscale" run --kitti "$sequence" --scale oracle --no-segmentation --frames 0:30 \
    --out "$out/run" >"$out/log.txt" 2>&1 || fail "run failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  [[ "$(wc -l <"$out/run/poses_kitti.txt")" -eq 30 ]] || fail "expected 30 pose rows"
  awk 'NF != 12 { exit 1 }' "$out/run/poses_kitti.txt" || fail "a pose row without 12 numbers"
  [[ "$(wc -l <"$out/run/frames.csv")" -eq 31 ]] || fail "expected a header and 30 records"
  expect_line "$out/run/frames.csv" "^0,0,first_frame,first,"
  expect_line "$out/run/frames.csv" "^29,[^,]+,ok,motion,"
  expect_line "$out/log.txt" "^Frames: 30 "
  # First row identity; after 30 frames (about 26 m) the camera is ahead along z.
  head -1 "$out/run/poses_kitti.txt" | awk '{ if ($1 != 1 || $4 != 0 || $12 != 0) exit 1 }' ||
    fail "first pose is not the identity"
  tail -1 "$out/run/poses_kitti.txt" | awk '{ if ($12 < 20 || $12 > 30) exit 1 }' ||
    fail "last pose is not 20-30 m ahead: $(tail -1 "$out/run/poses_kitti.txt")"
  [[ "$(wc -l <"$out/run/gt_poses_kitti.txt")" -eq 30 ]] || fail "expected 30 ground-truth rows"
  echo "run on KITTI 00 frames 0:30: all checks passed"
  exit 0
fi

if [[ "$mode" == "full" ]]; then
  skip_unless_shared "$sequence/image_0/000199.png" "$shared/kitti/poses/00.txt" \
    "$shared/models/espnetv2/espnetv2_s2.0_city_512x256.onnx"
  "$roadscale" run --kitti "$sequence" --out "$out/run" >"$out/log.txt" 2>&1 ||
    fail "run failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  expect_line "$out/log.txt" "^Segmentation: onnx espnetv2_s2.0_city_512x256.onnx"
  expect_line "$out/log.txt" "^Mapping: keyframe"
  # Measured (docs/benchmark-history.md, "Segmenting keyframes only"): t_err 1.12 %, ATE se3 0.33 m,
  # length ratio 0.987 (network on keyframes, the default); on every frame 1.24 %, 0.52 m,
  # 0.987; the frame-to-frame host 1.31 %, 0.62 m, 0.991. Changes that carry no information
  # move t_err on these 200 frames between 1.2 and 1.7 % (same section).
  python3 - "$out/run/metrics.json" <<'PY' || fail "metrics out of tolerance: $(cat "$out/run/metrics.json")"
import json, sys
m = json.load(open(sys.argv[1]))
assert m["frames"] == 200, m["frames"]
assert m["kitti"]["t_err_pct"] < 1.45, m["kitti"]["t_err_pct"]
assert m["ate_m"]["se3"] < 0.65, m["ate_m"]["se3"]
assert abs(m["length_ratio"] - 1.0) < 0.02, m["length_ratio"]
PY
  echo "run on the 200 shared KITTI 00 frames with the network: all checks passed"
  exit 0
fi

# The car creeps behind the traffic (steps of 0-0.3 m by either segmentation schedule,
# docs/benchmark-history.md, "A step that predicts the next") and stands still over its last 23 frames;
# the road alignment measures the road between the cars (docs/benchmark-history.md, "Shadows that move
# with the cars").
check_traffic_drive() {
  python3 - "$out/run/frames.csv" "$out/run/poses_kitti.txt" <<'PY' || fail "implausible traffic drive (config $1)"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 78, len(rows)
unscaled = [r["index"] for r in rows if r["map_scale"] == "none"]
assert not unscaled, f"frames without a scale: {unscaled}"
centres = [[float(v) for v in line.split()[3::4]] for line in open(sys.argv[2])]
steps = [math.dist(a, b) for a, b in zip(centres, centres[1:])]
assert max(steps) < 0.5, f"a step of {max(steps):.2f} m in a creep (frame {steps.index(max(steps)) + 1})"
assert max(steps[-18:]) < 0.02, f"the stopped car moves: {steps[-18:]}"
# A car brakes at up to 1 g, 0.1 m a frame at 10 Hz, and the frames' localisation adds a few
# centimetres of noise (0.02-0.10 m measured). Before the ground under a stopping pair kept its
# normal (SteadyRoadNormal) a keyframe stepped 0.38 m between steps of 0.11 and 0.13 m: the map
# had lost the landmarks the frames before it saw.
jumps = [abs(b - a) for a, b in zip(steps, steps[1:])]
assert max(jumps) < 0.15, f"the speed jumps by {max(jumps):.2f} m a frame (frame {jumps.index(max(jumps)) + 2})"
assert 6.0 < sum(steps) < 12.0, f"path of {sum(steps):.2f} m (measured 7.7-9.2 m over five seeds of the road plane's RANSAC)"
# The shadows of the cars ahead move with them: on the whole road the alignment found a plane
# on 0 of 13 keyframe pairs, without the shadows on 6 of 15 (9 of 13 with road cap 8).
keyframes = [r for r in rows if r["keyframe"] == "1"]
aligned = sum(1 for r in keyframes if float(r["alignment_scale"]) > 0)
assert 4 * aligned >= len(keyframes), f"road alignments on {aligned} of {len(keyframes)} keyframes"
PY
}

if [[ "$mode" == "traffic" ]]; then
  drive="$shared/kitti_raw/2011_09_26_city_traffic"
  skip_unless_shared "$drive/camera.yaml" "$drive/image_02/0000000077.png" \
    "$shared/models/espnetv2/espnetv2_s2.0_city_512x256.onnx"
  # The default, and twice the features on the road: before the prediction after a keyframe
  # was mended, the second made the frames that the map could not localise after one keyframe
  # each move 0.67 m while the car was stopping (16.5 m in all).
  printf 'Frontend: {road_max_per_cell: 8}\n' >"$out/road_features.yaml"
  for config in none "$out/road_features.yaml"; do
    options=()
    [[ "$config" != none ]] && options=(--config "$config")
    rm -rf "$out/run"
    "$roadscale" run --images "$drive/image_02" --camera "$drive/camera.yaml" "${options[@]}" \
      --out "$out/run" >"$out/log.txt" 2>&1 || fail "run failed: $(cat "$out/log.txt")"
    cat "$out/log.txt"
    check_traffic_drive "$config"
  done
  echo "run on the real dense-traffic drive: all checks passed"
  exit 0
fi

if [[ "$mode" == "slow" ]]; then
  slow="$shared/kitti/sequences/07"
  skip_unless_shared "$slow/image_0/000159.png" "$shared/kitti/poses/07.txt" \
    "$shared/models/espnetv2/espnetv2_s2.0_city_512x256.onnx"
  "$roadscale" run --kitti "$slow" --frames 0:160 --out "$out/run" >"$out/log.txt" 2>&1 ||
    fail "run failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  # Measured (docs/benchmark-history.md, "Shadows that move with the cars"): length ratio 0.986, ATE
  # se3 0.59 m (0.965 and 0.95 m before fresh masks where the carried road runs out); the issue's
  # target is within 2 % of 1 with no 8-frame window more than 5 % off, not yet met (the
  # pull-away is 9-12 % short), so this holds the line at 5 %.
  python3 - "$out/run/metrics.json" <<'PY' || fail "metrics out of tolerance: $(cat "$out/run/metrics.json")"
import json, sys
m = json.load(open(sys.argv[1]))
assert m["frames"] == 160, m["frames"]
assert abs(m["length_ratio"] - 1.0) < 0.05, m["length_ratio"]
assert m["ate_m"]["se3"] < 1.3, m["ate_m"]["se3"]
PY
  echo "run on the 160 shared KITTI 07 frames with the network: all checks passed"
  exit 0
fi

if [[ "$mode" == "road" ]]; then
  if [[ ! -f "$sequence/calib.txt" || ! -f "$shared/kitti/poses/00.txt" ]]; then
    echo "$sequence or its poses missing (set ROADSCALE_SHARED): skipped"
    exit 77
  fi
  # The frame-to-frame host: every step is its own frame pair's road scale.
  printf 'Mapping:\n  mode: frame_to_frame\n' >"$out/frame_to_frame.yaml"
  "$roadscale" run --kitti "$sequence" --h0 1.65 --frames 0:30 --config "$out/frame_to_frame.yaml" \
    --out "$out/run" >"$out/log.txt" 2>&1 || fail "run failed: $(cat "$out/log.txt")"
  cat "$out/log.txt"
  expect_line "$out/log.txt" "^Scale:  road \(h0 = 1.65"
  expect_line "$out/run/frames.csv" "^index,.*,road_raw_scale,road_scale,.*,road_plane_h$"
  # A reader that looks columns up by name must find each once.
  duplicate="$(head -1 "$out/run/frames.csv" | tr ',' '\n' | sort | uniq -d)"
  [[ -z "$duplicate" ]] || fail "frames.csv names a column twice: $duplicate"
  [[ "$(grep -c '"ok",' "$out/run/frames.csv")" -ge 25 ]] || fail "fewer than 25 road-scaled steps"
  tail -1 "$out/run/poses_kitti.txt" | awk '{ if ($12 < 20 || $12 > 30) exit 1 }' ||
    fail "last pose is not 20-30 m ahead: $(tail -1 "$out/run/poses_kitti.txt")"
  echo "run --scale road on KITTI 00 frames 0:30: all checks passed"
  exit 0
fi

expect_failure "sequence folder not found" \
  "$roadscale" run --kitti "$out/no-such-sequence" --scale oracle --no-segmentation \
  --out "$out/run"
# A sequence without poses: a short synthetic one with its poses file removed.
"$roadscale" synth --frames 3 --out "$out/data" >/dev/null 2>&1 || fail "synth failed"
rm "$out/data/poses/00.txt"
# --no-segmentation: without the shared network a note would add a line to stderr.
expect_failure "--scale oracle needs ground-truth poses" \
  "$roadscale" run --kitti "$out/data/sequences/00" --scale oracle --no-segmentation --out "$out/run"
expect_failure "unknown detector 'surf'" \
  "$roadscale" run --kitti "$out/data/sequences/00" --scale oracle --detector surf --out "$out/run"
expect_failure "unknown --scale 'magic'" \
  "$roadscale" run --kitti "$out/data/sequences/00" --scale magic --out "$out/run"
"$roadscale" run --help >"$out/help.txt"
expect_line "$out/help.txt" "--no-segmentation"
expect_line "$out/help.txt" "--labels"
echo "run errors: all checks passed"
