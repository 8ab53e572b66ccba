#!/usr/bin/env bash
# End-to-end test of `roadscale synth`: a short sequence in KITTI's layout with every ground
# truth file, byte-identical when run again with the same seed (and another thread count),
# different with another seed, a scene file, and one-line errors for bad input.
# Usage: synth_cli_test.sh ROADSCALE_BINARY SOURCE_DIR
set -euo pipefail
roadscale="$1"
source_dir="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

"$roadscale" synth --preset stop_and_go --frames 4 --seed 3 --out "$out/a" --colour
seq="$out/a/sequences/00"
for name in 000000 000003; do
  for folder in image_0 image_2 semantic depth moving; do
    [[ -s "$seq/$folder/$name.png" ]] || fail "no $folder/$name.png"
  done
done
[[ -f "$seq/image_0/000004.png" ]] && fail "more frames than asked for"
for file in calib.txt times.txt road_planes.txt camera.yaml; do
  [[ -s "$seq/$file" ]] || fail "no $file"
done
[[ $(wc -l < "$out/a/poses/00.txt") -eq 4 ]] || fail "poses/00.txt should have 4 rows"
[[ $(wc -l < "$seq/times.txt") -eq 4 ]] || fail "times.txt should have 4 rows"
[[ $(grep -vc '^#' "$seq/road_planes.txt") -eq 4 ]] || fail "road_planes.txt should have 4 rows"
grep -q '^P0: ' "$seq/calib.txt" || fail "calib.txt has no P0"
grep -q 'h0: 1.65' "$seq/camera.yaml" || fail "camera.yaml has no h0"
head -1 "$out/a/poses/00.txt" | grep -q '^1 0 0 0 0 1 0 0 0 0 1 0$' || fail "frame 0 is not the world"

"$roadscale" synth --preset stop_and_go --frames 4 --seed 3 --out "$out/b" --colour --threads 1
diff -r "$out/a" "$out/b" > /dev/null || fail "same seed gave different files"
"$roadscale" synth --preset stop_and_go --frames 4 --seed 4 --out "$out/c" --sequence 07
cmp -s "$seq/image_0/000003.png" "$out/c/sequences/07/image_0/000003.png" &&
  fail "another seed gave the same frame"
[[ -f "$out/c/poses/07.txt" ]] || fail "--sequence 07 not used"

# Every scene file the project ships renders.
for scene in "$source_dir"/config/synth/*.yaml; do
  name="$(basename "$scene" .yaml)"
  "$roadscale" synth --scene "$scene" --frames 2 --out "$out/$name" >/dev/null ||
    fail "$scene did not render"
  [[ -s "$out/$name/sequences/00/image_0/000001.png" ]] || fail "$scene: no frames written"
done

# Bad input: one line on stderr, exit code 1.
expect_error() {
  local pattern="$1"
  shift
  local status=0
  "$roadscale" synth "$@" 2> "$out/err" > /dev/null || status=$?
  [[ $status -eq 1 ]] || fail "exit code $status for $*"
  [[ $(wc -l < "$out/err") -eq 1 ]] || fail "not one error line for $*: $(cat "$out/err")"
  grep -q -- "$pattern" "$out/err" || fail "error for $* does not mention $pattern: $(cat "$out/err")"
}
expect_error "unknown synthetic scene preset 'moon'" --preset moon --frames 2 --out "$out/e"
expect_error "frames" --frames 0 --out "$out/e"
expect_error "sequence name" --frames 2 --out "$out/e" --sequence x1
printf 'Road:\n  lanes: 3\n' > "$out/bad.yaml"
expect_error "bad.yaml:2" --scene "$out/bad.yaml" --frames 2 --out "$out/e"
# A lens no camera.yaml can hold is refused before any file is made (issue 30).
expect_error "camera.distortion: coefficients must be finite" --frames 2 --out "$out/lens" \
  --distortion=nan,0,0,0,0
expect_error "camera.k1: -1 folds" --frames 2 --out "$out/lens" --distortion=-1,0,0,0,0
[[ ! -e "$out/lens" ]] || fail "a refused lens left a half-made dataset"
echo "synth CLI: OK"
