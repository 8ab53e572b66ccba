#!/usr/bin/env bash
# `cmake --install` of the build tree into a temporary folder (DESTDIR), then what a user of
# the installed roadscale does: every library, header, the CMake package, the command, the
# config files and the Python module are there; the module imports from there; the example
# examples/cpp_odometry/ builds against the package (find_package(roadscale)) and gives, on
# the first 20 frames of the shared KITTI 00, the bytes of the installed `roadscale run`'s
# poses_kitti.txt; the installed command takes its default model from PREFIX/share/roadscale.
# Skipped (status 77) after the checks without data when the shared frames are missing.
# Usage: install_consumer_test.sh CMAKE CXX_COMPILER BUILD_DIR SOURCE_DIR SHARED_DIR [PYTHON]
#   PYTHON: the interpreter of the Python module, when it is built
# The install's layout comes from the build's configuration, as absolute paths in
# ROADSCALE_INSTALL_{PREFIX,BINDIR,LIBDIR,INCLUDEDIR,DATADIR,PYTHONDIR}.
set -euo pipefail
cmake="$1"
cxx="$2"
build="$3"
source_dir="$4"
shared="${ROADSCALE_SHARED:-$5}"
python="${6:-}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"

stage="$scratch/stage"
DESTDIR="$stage" "$cmake" --install "$build" >"$scratch/install.txt" 2>&1 ||
  fail "cmake --install failed: $(cat "$scratch/install.txt")"
prefix="$stage$ROADSCALE_INSTALL_PREFIX"
libdir="$stage$ROADSCALE_INSTALL_LIBDIR"
includedir="$stage$ROADSCALE_INSTALL_INCLUDEDIR"
datadir="$stage$ROADSCALE_INSTALL_DATADIR"

expect_file() {  # PATH
  [[ -f "$1" ]] || fail "not installed: ${1#"$stage"}"
}
# Every folder of the library but the test support: its library and each of its headers.
for dir in "$source_dir"/src/roadscale/*/; do
  folder="$(basename "$dir")"
  [[ "$folder" != testing ]] || continue
  expect_file "$libdir/libroadscale_$folder.a"
  for header in "$dir"*.h; do expect_file "$includedir/roadscale/$folder/$(basename "$header")"; done
done
[[ ! -e "$includedir/roadscale/testing" ]] || fail "the test support's headers are installed"
for file in roadscaleConfig.cmake roadscaleConfigVersion.cmake roadscaleTargets.cmake; do
  expect_file "$libdir/cmake/roadscale/$file"
done
# OpenCV's image readers, which the library opens on first use (io/codecs_plugin.h). Staged
# under DESTDIR it is not where the installed programs look, so they are pointed at it: the
# runs below read every image through the installed plugin.
codecs="$libdir/roadscale/libroadscale_codecs.so"
expect_file "$codecs"
roadscale="$stage$ROADSCALE_INSTALL_BINDIR/roadscale"
[[ -x "$roadscale" ]] || fail "not installed: ${roadscale#"$stage"}"
# Without the variable an installed program looks in its prefix only, never in the build
# tree, whose plugin may be of another version by then.
LD_DEBUG=files "$roadscale" synth --frames 1 --out "$scratch/one" >/dev/null 2>"$scratch/loads.txt" || true
! grep -q "file=$build/.*libroadscale_codecs" "$scratch/loads.txt" ||
  fail "the installed roadscale opened the build tree's image codecs plugin"
grep -q "file=$ROADSCALE_INSTALL_LIBDIR/roadscale/libroadscale_codecs.so" "$scratch/loads.txt" ||
  grep -q "plugin is missing (looked for $ROADSCALE_INSTALL_LIBDIR/roadscale/libroadscale_codecs.so;" \
    "$scratch/loads.txt" ||
  fail "the installed roadscale did not look for its plugin in its prefix: $(grep -v '^ *[0-9]*:' "$scratch/loads.txt")"
export ROADSCALE_CODECS_PLUGIN="$codecs"
model="$datadir/roadscale/config/models/espnetv2_512x256.yaml"
expect_file "$datadir/roadscale/config/kitti.yaml"
expect_file "$model"

if [[ -n "$python" ]]; then
  module_dir="$stage$ROADSCALE_INSTALL_PYTHONDIR"
  PYTHONPATH="$module_dir" "$python" -c 'import roadscale; print(roadscale.__file__)' \
    >"$scratch/module.txt" 2>&1 || fail "the installed module does not import: $(cat "$scratch/module.txt")"
  [[ "$(cat "$scratch/module.txt")" == "$module_dir"/roadscale*.so ]] ||
    fail "the module imported is not the installed one: $(cat "$scratch/module.txt")"
fi

example="$scratch/example"
{ "$cmake" -S "$source_dir/examples/cpp_odometry" -B "$example" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release && "$cmake" --build "$example" -j2; } \
  >"$scratch/example.txt" 2>&1 || fail "the example does not build: $(cat "$scratch/example.txt")"
echo "installed files, Python module and the example's build: checked"

sequence="$shared/kitti/sequences/00"
if [[ ! -f "$sequence/calib.txt" ]]; then
  echo "SKIPPED: no shared KITTI 00 frames in $sequence (set ROADSCALE_SHARED)"
  exit 77
fi
"$example/cpp_odometry" "$sequence" 20 >"$scratch/example_poses.txt" 2>"$scratch/example_log.txt" ||
  fail "the example failed: $(cat "$scratch/example_log.txt")"
"$roadscale" run --kitti "$sequence" --frames 0:20 --no-segmentation --out "$scratch/run" \
  >"$scratch/run.txt" 2>&1 || fail "the installed roadscale run failed: $(cat "$scratch/run.txt")"
[[ "$(wc -l <"$scratch/example_poses.txt")" -eq 20 ]] || fail "the example printed no 20 rows"
cmp "$scratch/example_poses.txt" "$scratch/run/poses_kitti.txt" ||
  fail "the example's poses differ from roadscale run's"

# Without --model: the installed model file, whether or not the network it names is there
# (config_used.yaml names it, or the note that segmentation is off does).
"$roadscale" run --kitti "$sequence" --frames 0:2 --out "$scratch/default_model" \
  >"$scratch/default_model.txt" 2>&1 ||
  fail "the installed roadscale run failed: $(cat "$scratch/default_model.txt")"
grep -qF "$model" "$scratch/default_model/config_used.yaml" "$scratch/default_model.txt" ||
  fail "the installed command does not take ${model#"$stage"}: $(cat "$scratch/default_model.txt")"
echo "install: the example's 20 poses are run's, byte for byte; the default model is installed"
