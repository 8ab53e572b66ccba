#!/usr/bin/env bash
# The library's folders only include the folders below them (docs/development.md: util <-
# geometry <- io, frontend, segmentation, scale <- mapping <- pipeline <- config, report <-
# odometry, batch; rescale on io, frontend, segmentation, scale, and config on rescale; eval
# and synth are leaves the estimator never includes). A file that includes a folder above its own fails here, naming
# the file and the include.
# Usage: layering_test.sh [SOURCE_ROOT]   (default: the repository this script is in)
set -euo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

# What each folder's library code may include besides itself. report/ and odometry/ include
# eval/ for the run's report and metrics; the estimator (frontend, scale, mapping, pipeline)
# never does.
declare -A allowed=(
  [util]=""
  [geometry]="util"
  [io]="util geometry"
  [frontend]="util geometry"
  [segmentation]="util io"
  [scale]="util geometry"
  [mapping]="util geometry frontend scale"
  [eval]="util geometry io"
  [synth]="util geometry io"
  [pipeline]="util geometry io frontend segmentation scale mapping"
  [config]="util geometry io frontend segmentation scale mapping pipeline rescale"
  [report]="util geometry io eval pipeline"
  [rescale]="util geometry io frontend segmentation scale"
  [odometry]="util geometry io frontend segmentation scale mapping eval pipeline config report"
  [batch]="util geometry io frontend segmentation pipeline config"
)
# A new folder has to take its place in the layers before its code is checked.
for dir in "$root"/src/roadscale/*/; do
  folder="$(basename "$dir")"
  [[ "$folder" == testing || -v "allowed[$folder]" ]] ||
    fail "src/roadscale/$folder/ has no place in the layers of $0"
done

violations=0
checked=0
for folder in "${!allowed[@]}"; do
  [[ -d "$root/src/roadscale/$folder" ]] || fail "no folder src/roadscale/$folder under $root"
  for file in "$root/src/roadscale/$folder"/*.h "$root/src/roadscale/$folder"/*.cc; do
    # Tests are programs beside the library, not part of it: they may use any folder.
    [[ -e "$file" && "$file" != *_test.cc ]] || continue
    checked=$((checked + 1))
    permitted=" $folder ${allowed[$folder]} "
    while IFS= read -r included; do
      if [[ "$permitted" != *" $included "* ]]; then
        echo "${file#"$root"/}: includes roadscale/$included/, above src/roadscale/$folder/"
        violations=$((violations + 1))
      fi
    done < <(sed -n 's|^#include "roadscale/\([a-z_]*\)/.*|\1|p' "$file" | sort -u)
  done
done
[[ $checked -gt 100 ]] || fail "only $checked files checked under $root/src/roadscale"
[[ $violations -eq 0 ]] || fail "$violations includes across the layers"
echo "layering: $checked files, every include within its layer"
