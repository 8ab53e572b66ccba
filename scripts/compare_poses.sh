#!/usr/bin/env bash
# Do two roadscale builds give the same poses, to the byte? Runs both on KITTI 00/200 and
# 07/160 (the shared network on keyframes, the default) and on rendered drives with their
# label masks (urban, stop_and_go, traffic_jam, hills; seed 1, 150 frames), then compares
# each poses_kitti.txt with cmp. For changes that must not move the poses (restructuring,
# speed work). Exit status 1 when any differs.
#
#   scripts/compare_poses.sh OLD/roadscale build/roadscale [WORK_DIR]
set -euo pipefail
if [[ $# -lt 2 ]]; then
  sed -n '2,8p' "$0" >&2
  exit 2
fi
old="$1"
new="$2"
work="${3:-$(mktemp -d)}"
shared="${ROADSCALE_SHARED:-$(cd "$(dirname "$0")/../.." && pwd)/shared}"
mkdir -p "$work"

runs=()
if [[ -d "$shared/kitti/sequences/00" ]]; then
  runs+=("kitti00|--kitti $shared/kitti/sequences/00 --frames 0:200"
         "kitti07|--kitti $shared/kitti/sequences/07 --frames 0:160")
else
  echo "compare_poses: no shared KITTI frames in $shared: rendered drives only" >&2
fi
for preset in urban stop_and_go traffic_jam hills; do
  data="$work/data/$preset"
  [[ -d "$data" ]] || "$new" synth --preset "$preset" --frames 150 --seed 1 --out "$data" >/dev/null
  runs+=("$preset|--kitti $data/sequences/00 --labels $data/sequences/00/semantic")
done

different=0
for run in "${runs[@]}"; do
  name="${run%%|*}"
  read -r -a arguments <<<"${run#*|}"
  "$old" run "${arguments[@]}" --out "$work/old/$name" >/dev/null 2>&1
  "$new" run "${arguments[@]}" --out "$work/new/$name" >/dev/null 2>&1
  if cmp -s "$work/old/$name/poses_kitti.txt" "$work/new/$name/poses_kitti.txt"; then
    echo "$name: same poses ($(wc -l <"$work/new/$name/poses_kitti.txt") frames)"
  else
    echo "$name: DIFFERENT poses"
    different=1
  fi
done
exit "$different"
