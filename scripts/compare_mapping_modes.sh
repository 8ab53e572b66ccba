#!/usr/bin/env bash
# The keyframe back end against the frame-to-frame host on rendered drives with label masks:
# renders each preset and seed once, runs both modes on it, prints one row per run with the
# KITTI error, ATE, length ratio, share of frames with a road scale and frames/s.
#
#   scripts/compare_mapping_modes.sh OUT FRAMES "urban bumpy" "1 2 3" [extra run options...]
set -euo pipefail
cd "$(dirname "$0")/.."
out=$1 frames=$2 presets=$3 seeds=$4
shift 4
roadscale=${ROADSCALE:-build/roadscale}
mkdir -p "$out"
printf '%-12s %4s %-15s %8s %8s %8s %7s %7s\n' preset seed mode t_err% ate_se3 ratio ok% fps
for preset in $presets; do
  for seed in $seeds; do
    data="$out/data_${preset}_$seed"
    [[ -f "$data/sequences/00/times.txt" ]] ||
      "$roadscale" synth --preset "$preset" --frames "$frames" --seed "$seed" --out "$data" >/dev/null
    for mode in keyframe frame_to_frame; do
      run="$out/${preset}_${seed}_$mode"
      printf 'Mapping:\n  mode: %s\n' "$mode" >"$out/mode_$mode.yaml"
      "$roadscale" run --kitti "$data/sequences/00" --labels "$data/sequences/00/semantic" \
        --config "$out/mode_$mode.yaml" --out "$run" "$@" >"$run.log" 2>&1 || {
        echo "$preset $seed $mode: run failed, see $run.log"
        continue
      }
      python3 - "$run" "$preset" "$seed" "$mode" <<'PY'
import csv, json, sys
run, preset, seed, mode = sys.argv[1:]
m = json.load(open(run + "/metrics.json"))
rows = list(csv.DictReader(open(run + "/frames.csv")))
ok = sum(r["status"] == "ok" for r in rows) / len(rows)
fps = next((l.split(",")[1].split()[0] for l in open(run + ".log") if l.startswith("Wall clock")), "?")
t = m["kitti"]["t_err_pct"]
t = "-" if t is None else f"{t:.3f}"  # no 100 m segment in a short or slow drive
print(f"{preset:<12} {seed:>4} {mode:<15} {t:>8} "
      f"{m['ate_m']['se3']:8.3f} {m['length_ratio']:8.4f} {100 * ok:7.1f} {fps:>7}")
PY
    done
  done
done
