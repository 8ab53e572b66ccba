#!/usr/bin/env bash
# The rendered drives as a judge of the real-traffic targets (issue 29): renders each preset and
# seed once with network-like label errors beside the exact labels, runs both segmentation
# schedules on both kinds of masks, and prints per run the whole drive's length ratio and the
# worst 20-frame window's, then per drive and mask kind whether the two schedules agree.
#
#   scripts/judge_presets.sh OUT FRAMES "traffic_jam urban" "1 2 3" [extra run options...]
#
# The whole drive's ratio hides stretches where a wrong road fix set the scale for a hundred
# frames and a later one undid it (rendered traffic_jam 2: 0.78 of the truth over frames 20-160
# and 1.01 whole), so the worst window is printed too: windows of 20 frames in which the car
# drove at least 1 m, ratio of the estimated to the true path length.
#
# A candidate default is judged with JUDGE_CONFIG (YAML blocks other than Segmentation, e.g.
# 'Frontend: {road_max_per_cell: 8}') and JUDGE_SEGMENTATION (keys for the Segmentation block,
# e.g. 'min_carried_road_share: 0.5'), both added to every run's configuration. JUDGE_SCENE adds
# YAML blocks to the renders' scene, e.g. the real traffic drive's sunshine, in which each car
# ahead casts a dark shadow that moves with it: 'Image: {ambient: 0.25, sun_elevation_deg: 35,
# sun_azimuth_deg: 0}' (renders are kept in OUT: use a fresh OUT for another scene).
#
# JUDGE_LABEL_ERRORS=each also renders the network-like label errors one kind at a time, as two
# more mask kinds: outlines_lag (outlines 3 px small and a frame late) and missed_cars (a car
# read as road in 10 % of frames). Together they can cancel: rendered traffic_jam 2 passes with
# all three and drives 2.3 times its length with outlines_lag on keyframes
# (docs/benchmark-history.md, "The jams' label errors one at a time").
#
# Targets (issue 29): whole ratio within 1 % (3 % for traffic_jam), schedules within 1 % of each
# other. Each row says PASS or FAIL against them; the last line counts the failures. The exit
# status is 0 whatever the verdicts: this is a benchmark, not a test.
set -euo pipefail
cd "$(dirname "$0")/.."
if (($# < 4)); then
  sed -n '2,29p' "$0" >&2
  exit 2
fi
out=$1 frames=$2 presets=$3 seeds=$4
shift 4
roadscale=${ROADSCALE:-build/roadscale}
mkdir -p "$out"
# What the shared network does wrong on real frames, per docs/benchmark-history.md ("A first scale at
# 300 m/s"): outlines a few pixels small, a frame late, and now and then a car missed.
printf 'Labels: {dynamic_erosion_px: 3, dynamic_lag_frames: 1, dynamic_dropout: 0.1}\n%s\n' \
  "${JUDGE_SCENE:-}" >"$out/network_like.yaml"
printf 'Labels: {dynamic_erosion_px: 3, dynamic_lag_frames: 1, dynamic_dropout: 0}\n%s\n' \
  "${JUDGE_SCENE:-}" >"$out/outlines_lag.yaml"
printf 'Labels: {dynamic_erosion_px: 0, dynamic_lag_frames: 0, dynamic_dropout: 0.1}\n%s\n' \
  "${JUDGE_SCENE:-}" >"$out/missed_cars.yaml"
# Mask kinds: name, the render's scene file, the label folder.
kinds=("semantic network_like semantic" "network_like network_like semantic_network")
if [[ "${JUDGE_LABEL_ERRORS:-combined}" == each ]]; then
  kinds+=("outlines_lag outlines_lag semantic_network" "missed_cars missed_cars semantic_network")
elif [[ "${JUDGE_LABEL_ERRORS:-combined}" != combined ]]; then
  echo "judge_presets: JUDGE_LABEL_ERRORS must be combined or each" >&2
  exit 2
fi
for schedule in keyframes every_frame; do
  printf '%s\nSegmentation: {%sschedule: %s}\n' "${JUDGE_CONFIG:-}" \
    "${JUDGE_SEGMENTATION:+$JUDGE_SEGMENTATION, }" "$schedule" >"$out/schedule_$schedule.yaml"
done

ratios() {  # run folder -> "whole worst_window"
  python3 - "$1" <<'PY'
import sys
run = sys.argv[1]
def positions(path):
    return [tuple(float(v) for v in line.split()[3::4]) for line in open(path) if line.strip()]
est, gt = positions(run + "/poses_kitti.txt"), positions(run + "/gt_poses_kitti.txt")
def steps(p):
    return [sum((a - b) ** 2 for a, b in zip(p[i + 1], p[i])) ** 0.5 for i in range(len(p) - 1)]
e, g = steps(est), steps(gt[:len(est)])
worst = 1.0
for start in range(0, len(g), 20):
    true_length = sum(g[start:start + 20])
    if true_length < 1.0:
        continue
    ratio = sum(e[start:start + 20]) / true_length
    worst = ratio if abs(ratio - 1) > abs(worst - 1) else worst
print(f"{sum(e) / sum(g):.4f} {worst:.4f}")
PY
}

failures=0
printf '%-12s %4s %-13s %-12s %8s %8s %s\n' preset seed masks schedule ratio worst20 verdict
for preset in $presets; do
  tolerance=0.01
  [[ "$preset" == traffic_jam ]] && tolerance=0.03
  for seed in $seeds; do
    for kind in "${kinds[@]}"; do
      read -r name scene masks <<<"$kind"
      # The exact and the combined network-like labels share one render, as before.
      data="$out/data_${preset}_$seed"
      [[ $scene == network_like ]] || data="${data}_$scene"
      [[ -f "$data/sequences/00/times.txt" ]] ||
        "$roadscale" synth --preset "$preset" --scene "$out/$scene.yaml" --frames "$frames" \
          --seed "$seed" --out "$data" >/dev/null
      declare -A whole=()
      for schedule in keyframes every_frame; do
        run="$out/${preset}_${seed}_${masks}_$schedule"
        [[ $scene == network_like ]] || run="$out/${preset}_${seed}_${name}_$schedule"
        if ! "$roadscale" run --kitti "$data/sequences/00" --labels "$data/sequences/00/$masks" \
          --config "$out/schedule_$schedule.yaml" --out "$run" "$@" >"$run.log" 2>&1; then
          echo "$preset $seed $masks $schedule: run failed, see $run.log"
          failures=$((failures + 1))
          continue
        fi
        read -r ratio worst < <(ratios "$run")
        whole[$schedule]=$ratio
        verdict=$(python3 -c "print('PASS' if abs($ratio - 1) <= $tolerance else 'FAIL')")
        [[ $verdict == FAIL ]] && failures=$((failures + 1))
        printf '%-12s %4s %-13s %-12s %8s %8s %s\n' "$preset" "$seed" "$name" \
          "$schedule" "$ratio" "$worst" "$verdict"
      done
      if [[ -n "${whole[keyframes]:-}" && -n "${whole[every_frame]:-}" ]]; then
        verdict=$(python3 -c "print('PASS' if abs(${whole[keyframes]} / ${whole[every_frame]} - 1) <= 0.01 else 'FAIL')")
        [[ $verdict == FAIL ]] && failures=$((failures + 1))
        printf '%-12s %4s %-13s %-12s %8s %8s %s\n' "$preset" "$seed" "$name" \
          "schedules" "$(python3 -c "print(f'{${whole[keyframes]} / ${whole[every_frame]}:.4f}')")" "" "$verdict"
      fi
    done
  done
done
echo "judge_presets: $failures target(s) missed"
