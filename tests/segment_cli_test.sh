#!/usr/bin/env bash
# End-to-end test of `roadscale segment`: runs the smallest shared network on a few KITTI 00
# frames every 2nd frame, reads the labels back through the label-image backend (labels.yaml)
# and checks they are the same, and checks that bad models and missing label files fail with
# one line naming the file before any output is written.
# Usage: segment_cli_test.sh ROADSCALE_BINARY SOURCE_DIR DEFAULT_SHARED_DIR
set -euo pipefail
roadscale="$1"
source_dir="$2"
shared="${ROADSCALE_SHARED:-$3}"
sequence="$shared/kitti/sequences/00"
if [[ ! -f "$shared/models/espnetv2/espnetv2_s2.0_city_640x192.onnx" || ! -d "$sequence" ]]; then
  echo "shared data missing under $shared (set ROADSCALE_SHARED): skipped"
  exit 77
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

"$roadscale" segment --kitti "$sequence" --model "$source_dir/config/models/espnetv2_640x192.yaml" \
  --out "$out/net" --frames 10:14 --every 2
for name in 000010 000011 000012 000013; do
  [[ -s "$out/net/labels/$name.png" ]] || fail "no label image $name"
  [[ -s "$out/net/overlays/$name.png" ]] || fail "no overlay $name"
done
# Every 2nd frame: frame 11 reuses frame 10's labels, frame 12 is segmented afresh.
cmp -s "$out/net/labels/000010.png" "$out/net/labels/000011.png" || fail "frame 11 not reused"
cmp -s "$out/net/labels/000011.png" "$out/net/labels/000012.png" && fail "frame 12 not fresh"

# An image folder needs no camera YAML here: the size comes from the images. Same labels.
"$roadscale" segment --images "$sequence/image_0" --model \
  "$source_dir/config/models/espnetv2_640x192.yaml" --out "$out/folder" --frames 10:12
cmp -s "$out/net/labels/000010.png" "$out/folder/labels/000010.png" || fail "--images labels differ"

# The labels read back through the label-image backend are the same labels.
"$roadscale" segment --kitti "$sequence" --model "$out/net/labels.yaml" --out "$out/back" \
  --frames 10:14
for name in 000010 000011 000012 000013; do
  cmp -s "$out/net/labels/$name.png" "$out/back/labels/$name.png" || fail "labels $name differ"
done

# A frame without a label file: one error line naming it, before anything is written.
if "$roadscale" segment --kitti "$sequence" --model "$out/net/labels.yaml" --out "$out/missing" \
  --frames 12:15 2>"$out/missing.err"; then
  fail "a missing label file was accepted"
fi
grep -q "000014.png: label image of frame 000014 not found" "$out/missing.err" ||
  fail "unexpected message: $(cat "$out/missing.err")"
[[ ! -e "$out/missing" ]] || fail "output written before the error"

# A garbage .onnx: one error line naming the file, exit code 1.
head -c 5000 /dev/urandom >"$out/garbage.onnx"
sed "s|^file: .*|file: garbage.onnx|" "$source_dir/config/models/espnetv2_640x192.yaml" \
  >"$out/garbage.yaml"
status=0
"$roadscale" segment --kitti "$sequence" --model "$out/garbage.yaml" --out "$out/garbage" \
  --frames 0:1 2>"$out/garbage.err" || status=$?
[[ $status -eq 1 ]] || fail "garbage model: exit code $status, expected 1"
[[ $(wc -l <"$out/garbage.err") -eq 1 ]] || fail "garbage model: not one line: $(cat "$out/garbage.err")"
grep -q "garbage.onnx: OpenCV DNN cannot load" "$out/garbage.err" ||
  fail "unexpected message: $(cat "$out/garbage.err")"
echo "segment CLI: all checks passed"
