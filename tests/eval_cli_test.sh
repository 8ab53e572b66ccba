#!/usr/bin/env bash
# End-to-end tests of `roadscale eval`.
# Usage: eval_cli_test.sh ROADSCALE_BINARY DEFAULT_SHARED_DIR [self|cli]
#   self: KITTI 00's ground truth against itself prints zeros (skipped without shared data);
#   cli:  a generated trajectory: known answers for a 10 % scale error, --json, --plot, a TUM
#         estimate associated by time, short trajectories, and malformed or mismatched files
#         failing with one line naming the file (and line).
set -euo pipefail
roadscale="$1"
shared="${ROADSCALE_SHARED:-$2}"
mode="${3:-cli}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

if [[ "$mode" == "self" ]]; then
  gt="$shared/kitti/poses/00.txt"
  if [[ ! -f "$gt" ]]; then
    echo "$gt missing (set ROADSCALE_SHARED): skipped"
    exit 77
  fi
  "$roadscale" eval --gt "$gt" --est "$gt" >"$out/table.txt"
  cat "$out/table.txt"
  expect_line "$out/table.txt" "^Frames evaluated: 4541$"
  expect_line "$out/table.txt" "t_err 0\.0000 %"
  # As in the devkit, the error poses' diagonals (double) round to exactly 1 in float.
  expect_line "$out/table.txt" "r_err 0\.000000 deg/m   \(3283 segments"
  expect_line "$out/table.txt" "none 0\.0000 m   se3 0\.0000 m   sim3 0\.0000 m \(scale 1\.000000\)"
  expect_line "$out/table.txt" "translation 0\.00000 m   rotation 0\.00000 deg"
  expect_line "$out/table.txt" "est/gt 1\.000000"
  expect_line "$out/table.txt" "^Final drift: 0\.0000 m \(0\.0000 %"
  echo "eval GT vs itself: all checks passed"
  exit 0
fi

# 300 poses about 1 m apart, turning left and right (yaw about the camera's y axis).
awk 'BEGIN { x = 0; z = 0; yaw = 0;
  for (i = 0; i < 300; i++) {
    c = cos(yaw); s = sin(yaw);
    printf "%.12e 0 %.12e %.12e 0 1 0 0 %.12e 0 %.12e %.12e\n", c, s, x, -s, c, z;
    yaw += 0.02 * sin(i / 30.0); x += s; z += c;
  } }' >"$out/gt.txt"
# The same with every position 10 % further from the start.
awk -v CONVFMT="%.12e" '{ $4 *= 1.1; $8 *= 1.1; $12 *= 1.1; print }' "$out/gt.txt" >"$out/est.txt"

"$roadscale" eval --gt "$out/gt.txt" --est "$out/est.txt" >"$out/table.txt"
cat "$out/table.txt"
expect_line "$out/table.txt" "^Paired:       pose i with pose i$"
expect_line "$out/table.txt" "^Frames evaluated: 300$"
# Each segment's error is 10 % of its chord, a little shorter than its 101 or 201 m of path.
expect_line "$out/table.txt" "t_err 9\.[0-9]+ %   r_err 0\.0000[0-9]+ deg/m   \(30 segments"
expect_line "$out/table.txt" "no segment of 300 m fits a 299\.0 m trajectory"
expect_line "$out/table.txt" "sim3 0\.0000 m \(scale 0\.909091\)"
expect_line "$out/table.txt" "est/gt 1\.100000"

# --json: exactly the documented keys; stdout is pure JSON, the plot paths go to stderr.
"$roadscale" eval --gt "$out/gt.txt" --est "$out/est.txt" --json --plot "$out/plots" \
  >"$out/metrics.json" 2>"$out/json.err"
expect_line "$out/metrics.json" '^  "frames": 300,$'
expect_line "$out/metrics.json" '"sim3_scale": 0\.90909'
expect_line "$out/metrics.json" '"length_m": 300,'
expect_line "$out/metrics.json" '"t_err_pct": null'
expect_line "$out/json.err" "^Plots: "
if command -v python3 >/dev/null; then
  python3 - "$out/metrics.json" <<'PY' || fail "JSON shape"
import json, sys
m = json.load(open(sys.argv[1]))
assert list(m) == ["frames", "kitti", "ate_m", "rpe", "length_ratio", "final_drift_m",
                   "final_drift_pct"], list(m)
assert list(m["kitti"]) == ["t_err_pct", "r_err_deg_per_m", "n_segments", "per_length"]
assert [l["length_m"] for l in m["kitti"]["per_length"]] == list(range(100, 900, 100))
assert list(m["ate_m"]) == ["none", "se3", "sim3", "sim3_scale"]
assert list(m["rpe"]) == ["trans_rmse_m", "rot_rmse_deg"]
assert abs(m["length_ratio"] - 1.1) < 1e-9
PY
fi

# --plot writes a PNG and an SVG of each figure.
for name in trajectory_top_view t_err_vs_length r_err_vs_length; do
  [[ "$(head -c 4 "$out/plots/$name.png" | tail -c 3)" == "PNG" ]] || fail "$name.png not a PNG"
  grep -q "<svg" "$out/plots/$name.svg" || fail "$name.svg not an SVG"
done

# A TUM estimate with timestamps, associated by time with the KITTI ground truth (--times):
# frames 5..294, stamped 3 ms late.
awk '{ printf "%.9f\n", 0.1 * (NR - 1) }' "$out/gt.txt" >"$out/times.txt"
awk 'NR > 5 && NR <= 295 {
  yaw = atan2($3, $1);
  printf "%.9f %s %s %s 0 %.12e 0 %.12e\n", 0.1 * (NR - 1) + 0.003, $4, $8, $12,
    sin(yaw / 2), cos(yaw / 2) }' "$out/est.txt" >"$out/est_tum.txt"
"$roadscale" eval --gt "$out/gt.txt" --gt-format kitti --times "$out/times.txt" \
  --est "$out/est_tum.txt" --format tum >"$out/tum.txt"
expect_line "$out/tum.txt" "^Paired:       by time: 290 pairs with timestamps within 0\.01 s$"
expect_line "$out/tum.txt" "^Frames evaluated: 290$"
expect_line "$out/tum.txt" "scale 0\.909091"

# A trajectory shorter than 100 m: the KITTI metric is undefined, and says so.
head -n 46 "$out/gt.txt" >"$out/short.txt"
"$roadscale" eval --gt "$out/short.txt" --est "$out/short.txt" >"$out/short_table.txt"
expect_line "$out/short_table.txt" "undefined: no segment of 100 m fits a 45\.0 m trajectory"
"$roadscale" eval --gt "$out/short.txt" --est "$out/short.txt" --json >"$out/short.json"
expect_line "$out/short.json" '^    "t_err_pct": null,$'

# Failures: exit code 1 and one line on stderr naming the file (and the line).
expect_failure() {  # REGEX ARGS...
  local regex="$1"
  shift
  local status=0
  "$roadscale" eval "$@" >/dev/null 2>"$out/err.txt" || status=$?
  [[ $status -eq 1 ]] || fail "exit code $status (expected 1) for: $*"
  [[ $(wc -l <"$out/err.txt") -eq 1 ]] || fail "not one line: $(cat "$out/err.txt")"
  expect_line "$out/err.txt" "$regex"
}
sed '5s/ [^ ]*$//' "$out/gt.txt" >"$out/bad.txt"
expect_failure "bad\.txt:5: expected 12 numbers \(a row-major 3x4 pose\), found 11" \
  --gt "$out/gt.txt" --est "$out/bad.txt"
expect_failure "est_tum\.txt has 290 poses but .*gt\.txt has 300" \
  --gt "$out/gt.txt" --gt-format kitti --est "$out/est_tum.txt" --format tum
head -n 10 "$out/times.txt" >"$out/short_times.txt"
expect_failure "short_times\.txt: has 10 timestamps but .*gt\.txt has 300 poses" \
  --gt "$out/gt.txt" --gt-format kitti --times "$out/short_times.txt" --est "$out/est_tum.txt" \
  --format tum
expect_failure "missing\.txt: cannot open trajectory file" \
  --gt "$out/gt.txt" --est "$out/missing.txt"
expect_failure "unknown trajectory format 'csv'" \
  --gt "$out/gt.txt" --est "$out/est.txt" --format csv
: >"$out/empty.txt"
expect_failure "empty\.txt: no poses in the file" --gt "$out/empty.txt" --est "$out/est.txt"
echo "eval CLI: all checks passed"
