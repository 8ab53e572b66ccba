#!/usr/bin/env bash
# The bad-input matrix of issue 12: every input a user or a hostile tester can get wrong, and
# every fault part way through a run, ends with the documented exit code, exactly one line on
# stderr naming the file (and line) or option at fault, and the rows written before the fault
# intact. Prints how many cases ran.
# Usage: bad_input_cli_test.sh ROADSCALE_BINARY [files|runs|concurrent]
#   files: eval, YAML, calib/times/images/trajectories, output folder, command line (fast);
#   runs:  faults part way through `run` and `rescale` on a rendered sequence: a re-run into a
#          used folder failing at a corrupt frame, SIGTERM and SIGINT while frames wait for the
#          first scale, SIGTERM and SIGINT during `rescale`;
#   concurrent: a second run, rescale or batch into an output folder in use refuses, naming
#          the holder; the lock of a holder killed with -9 is taken over.
# Permission cases run the command as `nobody` when the test runs as root (root reads every
# file); they are skipped when neither works.
set -euo pipefail
roadscale="$1"
mode="${2:-files}"
out="$(mktemp -d)"
cases=0
# The shared fail says what is wrong; a failing exit also says in which case (of the $cases
# begun) it stopped, so that one of the many cases with the same message can be found.
report_case() {
  local status=$?
  [[ $status -eq 0 ]] || echo "FAILED in case $cases"
}
trap 'report_case; rm -rf "$out"' EXIT
chmod 755 "$out"  # readable by `nobody` for the permission cases
scratch="$out"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"
rows() { wc -l <"$1" | tr -d ' '; }

# expect_error CODE REGEX COMMAND...: exit code CODE, one line on stderr matching REGEX.
expect_error() {
  local code="$1" regex="$2"
  shift 2
  cases=$((cases + 1))
  local status=0
  "$@" >"$out/stdout.txt" 2>"$out/stderr.txt" || status=$?
  [[ $status -eq $code ]] || fail "exit $status, expected $code: $* -- $(cat "$out/stderr.txt")"
  [[ "$(rows "$out/stderr.txt")" -eq 1 ]] || fail "not one line on stderr: $* -- $(cat "$out/stderr.txt")"
  expect_line "$out/stderr.txt" "$regex"
}
# expect_ok COMMAND...: exit code 0 and nothing on stderr.
expect_ok() {
  cases=$((cases + 1))
  "$@" >"$out/stdout.txt" 2>"$out/stderr.txt" || fail "failed: $* -- $(cat "$out/stderr.txt")"
  [[ ! -s "$out/stderr.txt" ]] || fail "stderr not empty: $* -- $(cat "$out/stderr.txt")"
}
# The command as a user without root's right to read every file, or nothing when impossible.
as_user=()
can_deny=true
if [[ $(id -u) -eq 0 ]]; then
  if command -v setpriv >/dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups true 2>/dev/null; then
    as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  else
    can_deny=false
  fi
fi
# check_pose_rows DIR N: N KITTI and N TUM pose rows, each complete.
check_pose_rows() {
  [[ "$(rows "$1/poses_kitti.txt")" -eq "$2" ]] || fail "$1/poses_kitti.txt: $(rows "$1/poses_kitti.txt") rows, expected $2"
  [[ "$(rows "$1/poses_tum.txt")" -eq "$2" ]] || fail "$1/poses_tum.txt: not $2 rows"
  awk 'NF != 12 { exit 1 }' "$1/poses_kitti.txt" || fail "$1: a KITTI row without 12 numbers"
  awk 'NF != 8 { exit 1 }' "$1/poses_tum.txt" || fail "$1: a TUM row without 8 numbers"
  "$roadscale" eval --gt "$1/poses_kitti.txt" --est "$1/poses_kitti.txt" >/dev/null ||
    fail "$1/poses_kitti.txt does not read back"
}

"$roadscale" synth --frames 40 --out "$out/data" >/dev/null 2>&1 || fail "synth failed"
seq="$out/data/sequences/00"

# $long: 400 frames (the 40 rendered ones there and back, $out/long/trajectory.txt with them),
# so that no machine finishes a run before its signal; noroad.yaml keeps every frame waiting
# for a first scale.
make_long() {
  printf 'Scale:\n  ransac_min_points: 100000\nMapping:\n  mode: frame_to_frame\n' >"$out/noroad.yaml"
  long="$out/long/sequences/00"
  mkdir -p "$long/image_0"
  cp "$seq/calib.txt" "$seq/camera.yaml" "$long/"
  for i in $(seq 0 399); do
    k=$((i % 78))
    ((k < 40)) || k=$((78 - k))
    ln -s "$seq/image_0/$(printf %06d $k).png" "$long/image_0/$(printf %06d "$i").png"
    sed -n "$((k + 1))p" "$out/data/poses/00.txt" >>"$out/long/trajectory.txt"
  done
  awk 'BEGIN { for (i = 0; i < 400; i++) printf "%e\n", i * 0.1 }' >"$long/times.txt"
}

if [[ "$mode" == "files" ]]; then
  # --- eval: pose rows that are not rigid, unreadable files ---------------------------------
  cp "$out/data/poses/00.txt" "$out/gt.txt"
  bad_row() {  # NAME LINE AWK-PROGRAM: gt.txt with line LINE rewritten
    awk -v n="$2" "NR == n { $3 } { print }" "$out/gt.txt" >"$out/$1"
  }
  bad_row zero.txt 5 '$1 = $2 = $3 = $5 = $6 = $7 = $9 = $10 = $11 = 0'
  expect_error 1 "zero\.txt:5: the 3x3 part is not a rotation" \
    "$roadscale" eval --gt "$out/gt.txt" --est "$out/zero.txt"
  bad_row scaled.txt 7 'for (i = 1; i <= 11; i++) if (i % 4 != 0) $i *= 1.1'
  expect_error 1 "scaled\.txt:7: the 3x3 part is not a rotation" \
    "$roadscale" eval --gt "$out/gt.txt" --est "$out/scaled.txt"
  bad_row mirrored.txt 3 '$1 = -$1; $5 = -$5; $9 = -$9'
  expect_error 1 "mirrored\.txt:3: the 3x3 part is not a rotation .*det\(R\) = -1" \
    "$roadscale" eval --gt "$out/gt.txt" --est "$out/mirrored.txt"
  bad_row far.txt 4 '$4 = 1e30'
  expect_error 1 "far\.txt:4: the position \(1e\+30, .*\) is beyond 1e\+08 m" \
    "$roadscale" eval --gt "$out/far.txt" --est "$out/gt.txt"
  bad_row nan.txt 6 '$8 = "nan"'
  expect_error 1 "nan\.txt:6: expected a number, found 'nan'" \
    "$roadscale" eval --gt "$out/gt.txt" --est "$out/nan.txt"
  printf '0 0 0 0 0 0 0 1\n0.1 0 0 1 0 0 0 0\n' >"$out/zero_q.tum"
  expect_error 1 "zero_q\.tum:2: the quaternion \(qx qy qz qw\) has length 0" \
    "$roadscale" eval --gt "$out/zero_q.tum" --est "$out/zero_q.tum" --format tum
  mkdir "$out/a_dir"
  expect_error 1 "a_dir: cannot open trajectory file: is a directory" \
    "$roadscale" eval --gt "$out/gt.txt" --est "$out/a_dir"
  ln -s "$out/loop_b" "$out/loop_a"
  ln -s "$out/loop_a" "$out/loop_b"
  expect_error 1 "loop_a: cannot open trajectory file: too many levels of symbolic links" \
    "$roadscale" eval --gt "$out/loop_a" --est "$out/gt.txt"
  expect_error 1 "a_dir: cannot open timestamps file: is a directory" \
    "$roadscale" eval --gt "$out/gt.txt" --times "$out/a_dir" --est "$out/gt.txt"
  if $can_deny; then
    cp "$out/gt.txt" "$out/secret.txt"
    chmod 000 "$out/secret.txt"
    expect_error 1 "secret\.txt: cannot open trajectory file: permission denied" \
      "${as_user[@]}" "$roadscale" eval --gt "$out/gt.txt" --est "$out/secret.txt"
  fi
  # OpenCV's image readers are a plugin opened on the first image (io/codecs_plugin.h): a
  # command that reads none runs without it, one that does names what is missing.
  expect_ok env ROADSCALE_CODECS_PLUGIN="$out/no_codecs.so" "$roadscale" eval --gt "$out/gt.txt" \
    --est "$out/gt.txt"
  expect_error 1 "ROADSCALE_CODECS_PLUGIN=.*/no_codecs\.so: no such file \(roadscale's image codecs plugin\)" \
    env ROADSCALE_CODECS_PLUGIN="$out/no_codecs.so" "$roadscale" run --kitti "$seq" \
    --no-segmentation --scale oracle --out "$out/no_codecs_run"
  : >"$out/empty_codecs.so"
  expect_error 1 "cannot load roadscale's image codecs plugin .*/empty_codecs\.so: " \
    env ROADSCALE_CODECS_PLUGIN="$out/empty_codecs.so" "$roadscale" run --kitti "$seq" \
    --no-segmentation --scale oracle --out "$out/empty_codecs_run"
  # A pipe is read once; a UTF-8 byte order mark is skipped.
  expect_ok "$roadscale" eval --gt "$out/gt.txt" --est <(cat "$out/gt.txt")
  grep -q "^Frames evaluated: 40$" "$out/stdout.txt" || fail "pipe: $(cat "$out/stdout.txt")"
  { printf '\xef\xbb\xbf'; cat "$out/gt.txt"; } >"$out/bom.txt"
  expect_ok "$roadscale" eval --gt "$out/bom.txt" --est "$out/gt.txt"

  # --- run: config, camera and model YAML ---------------------------------------------------
  run_kitti() { "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle "$@"; }
  expect_error 1 "a_dir: cannot open config file: is a directory" \
    run_kitti --config "$out/a_dir" --out "$out/r"
  expect_error 1 "loop_a: cannot open config file: too many levels of symbolic links" \
    run_kitti --config "$out/loop_a" --out "$out/r"
  printf 'Frontend:\n  detector: orb\n  detector: sift\n' >"$out/twice.yaml"
  expect_error 1 "twice\.yaml:3: key 'detector' appears twice in one mapping \(first on line 2\)" \
    run_kitti --config "$out/twice.yaml" --out "$out/r"
  printf 'Scale:\n  filter_window: 3\nFrontend:\n  detector: orb\nScale:\n  use_filter: false\n' \
    >"$out/blocks.yaml"
  expect_error 1 "blocks\.yaml:5: key 'Scale' appears twice in one mapping \(first on line 1\)" \
    run_kitti --config "$out/blocks.yaml" --out "$out/r"
  printf 'Scale:\n  use_filter: true\n  filter_window: -3\n' >"$out/range.yaml"
  expect_error 1 "range\.yaml:3: Scale\.filter_window: invalid option" \
    run_kitti --config "$out/range.yaml" --out "$out/r"
  printf 'Camera:\n  h0: 1e308\n' >"$out/h0.yaml"
  expect_error 1 "h0\.yaml:2: Camera\.h0: invalid option camera\.h0: .* got 1e\+308" \
    run_kitti --config "$out/h0.yaml" --out "$out/r"
  expect_error 1 "invalid option h0: the camera height above the road must be in \[0\.05, 100\] metres, got 1e\+308" \
    run_kitti --h0 1e308 --out "$out/h0run"
  [[ ! -e "$out/h0run/poses_kitti.txt" ]] || fail "poses written despite --h0 1e308"
  expect_error 1 "invalid option h0: .* got 0" run_kitti --h0 0 --out "$out/h0run"
  printf 'Camera:\n  fx: 0\n  fy: 700\n  cx: 300\n  cy: 200\n  width: 640\n  height: 480\n' \
    >"$out/fx.yaml"
  expect_error 1 "fx\.yaml:2: Camera\.fx: invalid option camera\.fx" \
    "$roadscale" run --images "$seq/image_0" --config "$out/fx.yaml" --out "$out/r"
  expect_error 1 "a_dir: cannot open camera YAML file: is a directory" \
    "$roadscale" run --images "$seq/image_0" --camera "$out/a_dir" --no-segmentation --out "$out/r"
  # Issue 30: a camera YAML's unknown key, a lens whose undistortion blanks or folds the frames,
  # a height or focal length no camera has (each ran before, every frame `ok`).
  camera() {  # NAME LINES...: the rendered camera.yaml with Camera: lines added
    local name="$1"
    shift
    { cat "$seq/camera.yaml"; printf '  %s\n' "$@"; } >"$out/$name"
  }
  run_images() { "$roadscale" run --images "$seq/image_0" --no-segmentation "$@"; }
  for key in K1 s1 k7; do
    camera "$key.yaml" "$key: 0.01"
    expect_error 1 "$key\.yaml:11: unknown key 'Camera\.$key'" \
      run_images --camera "$out/$key.yaml" --out "$out/r"
  done
  camera blank.yaml "k1: 1e6"
  expect_error 1 "blank\.yaml:4: Camera: invalid option camera\.k1: 1e\+06 leaves 100 % of" \
    run_images --camera "$out/blank.yaml" --out "$out/r"
  camera fold.yaml "k1: -1"
  expect_error 1 "fold\.yaml:4: Camera: invalid option camera\.k1: -1 folds the undistortion map" \
    run_images --camera "$out/fold.yaml" --out "$out/r"
  camera pole.yaml "k4: -1.5"
  expect_error 1 "pole\.yaml:4: Camera: invalid option camera\.k4: -1\.5 makes the rational" \
    run_images --camera "$out/pole.yaml" --out "$out/r"
  expect_error 1 "invalid option h0: the camera height above the road must be in \[0\.05, 100\] metres, got 1e-300" \
    run_kitti --h0 1e-300 --out "$out/r"
  sed 's/^  fx: .*/  fx: 7.2e7/' "$seq/camera.yaml" >"$out/long_fx.yaml"
  expect_error 1 "long_fx\.yaml:4: Camera: invalid option camera\.fx: 7\.2e\+07 px over an image side of 1241 px is no lens's focal length" \
    run_images --camera "$out/long_fx.yaml" --out "$out/r"
  for fx in 1e308 1e-300; do
    cp -r "$seq" "$out/calib_$fx"
    sed -i "s/^P0: [^ ]*/P0: $fx/" "$out/calib_$fx/calib.txt"
    expect_error 1 "calib_$fx/calib\.txt: invalid option camera\.fx: .* is no lens's focal length" \
      "$roadscale" run --kitti "$out/calib_$fx" --no-segmentation --out "$out/r"
  done
  cp -r "$seq" "$out/calib_pp"
  sed -i 's/^P0: \([^ ]*\) \([^ ]*\) [^ ]*/P0: \1 \2 1e5/' "$out/calib_pp/calib.txt"
  expect_error 1 "calib_pp/calib\.txt: invalid option camera\.cx/cy: the principal point" \
    "$roadscale" run --kitti "$out/calib_pp" --no-segmentation --out "$out/r"
  # config_used.yaml keeps the lens: repeating the run with it gives the same poses.
  camera lens.yaml "k1: -0.05" "p2: 0.0001"
  cases=$((cases + 1))
  run_images --camera "$out/lens.yaml" --out "$out/lens1" >/dev/null 2>&1 || fail "lens run failed"
  grep -q "^  k1: -0.05$" "$out/lens1/config_used.yaml" || fail "config_used.yaml has no k1"
  run_images --config "$out/lens1/config_used.yaml" --out "$out/lens2" >/dev/null 2>&1 ||
    fail "the run from config_used.yaml failed"
  cmp -s "$out/lens1/poses_kitti.txt" "$out/lens2/poses_kitti.txt" ||
    fail "config_used.yaml of a distorted camera does not repeat its run"
  { cat "$seq/camera.yaml"; echo "  fx: 1"; } >"$out/cam_twice.yaml"
  expect_error 1 "cam_twice\.yaml:[0-9]+: key 'fx' appears twice in one mapping" \
    "$roadscale" run --images "$seq/image_0" --camera "$out/cam_twice.yaml" --no-segmentation \
    --out "$out/r"
  expect_error 1 "a_dir: cannot open segmentation model file: is a directory" \
    "$roadscale" run --kitti "$seq" --model "$out/a_dir" --out "$out/r"
  echo "placeholder" >"$out/net.onnx"
  model() {  # NAME EXTRA-KEYS: a model YAML for the placeholder network
    printf 'backend: onnx\nfile: net.onnx\ninput_size: [%s]\nchannel_order: rgb\nnum_classes: 20\n%s' \
      "$2" "$3" >"$out/$1"
  }
  printf 'Scale:\n  filter_window: [3\n' >"$out/syntax.yaml"
  expect_error 1 "syntax\.yaml:[0-9]+: invalid YAML" run_kitti --config "$out/syntax.yaml" --out "$out/r"
  model garbage.yaml "64, 32" ""
  expect_error 1 "net\.onnx: OpenCV DNN cannot load" \
    "$roadscale" run --kitti "$seq" --model "$out/garbage.yaml" --out "$out/r"
  model ids.yaml "64, 32" $'road_ids: [25]\n'
  expect_error 1 "ids\.yaml:6: 'road_ids' holds 25, a train id the network never outputs" \
    "$roadscale" run --kitti "$seq" --model "$out/ids.yaml" --out "$out/r"
  model huge.yaml "100000, 100000" ""
  expect_error 1 "huge\.yaml:3: 'input_size' sides must be <= 4096" \
    "$roadscale" run --kitti "$seq" --model "$out/huge.yaml" --out "$out/r"

  # --- KITTI sequence files, images, video ----------------------------------------------------
  copy_sequence() {  # NAME: a copy of the rendered dataset; prints its sequence folder
    cp -r "$out/data" "$out/$1"
    echo "$out/$1/sequences/00"
  }
  s="$(copy_sequence calib_dir)"
  rm "$s/calib.txt" && mkdir "$s/calib.txt"
  expect_error 1 "calib\.txt: cannot open KITTI calibration file: is a directory" \
    "$roadscale" run --kitti "$s" --no-segmentation --out "$out/r"
  s="$(copy_sequence times_dir)"
  rm "$s/times.txt" && mkdir "$s/times.txt"
  expect_error 1 "times\.txt: cannot open timestamps file: is a directory" \
    "$roadscale" run --kitti "$s" --no-segmentation --out "$out/r"
  s="$(copy_sequence short_calib)"
  sed -i '1s/ [^ ]*$//' "$s/calib.txt"
  expect_error 1 "calib\.txt:1: expected 12 numbers \(a row-major 3x4 matrix\) after 'P0:', found 11" \
    "$roadscale" run --kitti "$s" --no-segmentation --out "$out/r"
  s="$(copy_sequence backwards_times)"
  sed -i '4s/.*/0.0/' "$s/times.txt"
  expect_error 1 "times\.txt:4: timestamps must increase" \
    "$roadscale" run --kitti "$s" --no-segmentation --out "$out/r"
  s="$(copy_sequence bom)"
  { printf '\xef\xbb\xbf'; cat "$seq/calib.txt"; } >"$s/calib.txt"
  expect_ok "$roadscale" run --kitti "$s" --no-segmentation --scale oracle --frames 0:3 \
    --out "$out/bom_run"
  check_pose_rows "$out/bom_run" 3
  s="$(copy_sequence bad_gt)"
  awk 'NR == 3 { $1 = 2 } { print }' "$out/data/poses/00.txt" >"$out/bad_gt/poses/00.txt"
  expect_error 1 "poses/00\.txt:3: the 3x3 part is not a rotation" \
    "$roadscale" run --kitti "$s" --no-segmentation --out "$out/r"
  # A fault at frame 5: the five rows before it are written and read back.
  for fault in zero_byte truncated wrong_size; do
    s="$(copy_sequence "$fault")"
    if [[ "$fault" == zero_byte ]]; then
      : >"$s/image_0/000005.png"
      regex="000005\.png: cannot decode image \(the file is empty\)"
    elif [[ "$fault" == truncated ]]; then
      head -c 3000 "$seq/image_0/000005.png" >"$s/image_0/000005.png"
      regex="000005\.png: cannot decode image \(truncated in chunk IDAT\)"
    else
      python3 -c "import zlib,struct,sys
w,h=16,8
raw=b''.join(b'\x00'+bytes(w) for _ in range(h))
c=lambda t,d: struct.pack('>I',len(d))+t+d+struct.pack('>I',zlib.crc32(t+d))
sys.stdout.buffer.write(b'\x89PNG\r\n\x1a\n'+c(b'IHDR',struct.pack('>IIBBBBB',w,h,8,0,0,0,0))+c(b'IDAT',zlib.compress(raw))+c(b'IEND',b''))" \
        >"$s/image_0/000005.png"
      regex="000005\.png: image is 16x8 but"
    fi
    expect_error 1 "$regex" "$roadscale" run --kitti "$s" --no-segmentation --scale oracle \
      --sequential --out "$out/$fault.run"
    check_pose_rows "$out/$fault.run" 5
  done
  s="$(copy_sequence bad_label)"
  head -c 200 "$seq/semantic/000003.png" >"$s/semantic/000003.png"
  # Every frame's labels read: the default schedule reads only the keyframes' (frame 3 is none).
  printf 'Segmentation:\n  schedule: every_frame\n' >"$out/every_frame.yaml"
  expect_error 1 "semantic/000003\.png: cannot decode label image \(truncated in chunk IDAT\)" \
    "$roadscale" run --kitti "$s" --labels "$s/semantic" --scale oracle --sequential \
    --config "$out/every_frame.yaml" --out "$out/bad_label.run"
  check_pose_rows "$out/bad_label.run" 3
  if $can_deny; then
    s="$(copy_sequence denied)"
    chmod 000 "$s/image_0/000005.png"
    mkdir -m 777 "$out/denied.run"
    expect_error 1 "000005\.png: cannot open image: permission denied" \
      "${as_user[@]}" "$roadscale" run --kitti "$s" --no-segmentation --scale oracle --sequential \
      --out "$out/denied.run"
    check_pose_rows "$out/denied.run" 5
    mkdir -m 555 "$out/read_only"
    expect_error 1 "read_only/(\.roadscale\.lock|[a-z_]+\.(txt|yaml|csv)): cannot" \
      "${as_user[@]}" "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle \
      --out "$out/read_only"
  fi
  expect_error 1 "loop_a: too many levels of symbolic links" \
    "$roadscale" run --kitti "$out/loop_a" --no-segmentation --out "$out/r"
  if $can_deny; then
    mkdir -m 700 "$out/closed_folder"
    cp "$seq/image_0/000000.png" "$out/closed_folder/"
    mkdir -m 777 "$out/closed.run"
    expect_error 1 "closed_folder: permission denied" "${as_user[@]}" "$roadscale" run \
      --images "$out/closed_folder" --camera "$seq/camera.yaml" --no-segmentation \
      --out "$out/closed.run"
  fi
  mkdir "$out/no_images"
  expect_error 1 "no_images: no images" "$roadscale" run --images "$out/no_images" --camera "$seq/camera.yaml" \
    --no-segmentation --out "$out/r"
  expect_error 1 "a_dir: cannot open video file: is a directory" \
    "$roadscale" run --video "$out/a_dir" --camera "$seq/camera.yaml" --no-segmentation \
    --out "$out/r"
  # A full disk, simulated by a 4 KiB file size limit (its signal ignored, so that writes
  # fail): one line naming the file, and every file holds whole rows only.
  full_disk() { (trap '' XFSZ && ulimit -f 4 && "$@"); }
  expect_error 1 "full\.run/poses_kitti\.txt: write failed \(disk full" full_disk \
    "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle --sequential \
    --out "$out/full.run"
  n="$(rows "$out/full.run/poses_kitti.txt")"
  [[ "$n" -ge 5 && "$(tail -c 1 "$out/full.run/poses_kitti.txt" | od -An -c | tr -d ' ')" == '\n' ]] ||
    fail "full disk: $n rows or a partial last row"
  check_pose_rows "$out/full.run" "$n"
  expect_error 1 "full\.rescale/[a-z_]+\.(txt|csv): write failed \(disk full" full_disk \
    "$roadscale" rescale --trajectory "$out/gt.txt" --kitti "$seq" --no-segmentation \
    --out "$out/full.rescale"
  awk 'NF != 12 { exit 1 }' "$out/full.rescale/poses_kitti.txt" || fail "full disk: a partial row"
  # Three frames: the rows and metrics.json fit in 4 KiB, the report does not. The whole-file
  # outputs are written whole or not at all, with no temporary file left behind.
  expect_error 1 "full\.short/report\.html: write failed" full_disk \
    "$roadscale" run --kitti "$seq" --frames 0:3 --no-segmentation --scale oracle --sequential \
    --out "$out/full.short"
  [[ ! -e "$out/full.short/report.html" ]] || fail "full disk: a report.html was left"
  [[ -z "$(find "$out/full.short" -name '*.tmp*')" ]] || fail "full disk: a temporary file was left"
  python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$out/full.short/metrics.json" ||
    fail "full disk: metrics.json is not whole"
  mkdir -p "$out/stuck/report.html/inside"
  expect_error 1 "stuck/report\.html: cannot remove the previous run's file" \
    "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle --out "$out/stuck"

  # --- rescale inputs -------------------------------------------------------------------------
  head -n 5 "$out/gt.txt" >"$out/five.txt"
  expect_ok "$roadscale" rescale --trajectory <(cat "$out/five.txt") --kitti "$seq" \
    --no-segmentation --out "$out/piped"
  check_pose_rows "$out/piped" 5
  expect_error 1 "invalid option --max-time-diff: must be a non-negative number of seconds" \
    "$roadscale" rescale --trajectory "$out/five.txt" --kitti "$seq" --max-time-diff -1 \
    --no-segmentation --out "$out/r"
  expect_error 1 "invalid option --span-steps: must be >= 1" \
    "$roadscale" rescale --trajectory "$out/five.txt" --kitti "$seq" --span-steps 0 \
    --no-segmentation --out "$out/r"
  awk 'NR == 3 { $1 = $2 = $3 = 0 } { print }' "$out/five.txt" >"$out/degenerate.txt"
  expect_error 1 "degenerate\.txt:3: the 3x3 part is not a rotation" \
    "$roadscale" rescale --trajectory "$out/degenerate.txt" --kitti "$seq" --no-segmentation \
    --out "$out/r"
  expect_error 1 "a_dir: cannot open trajectory file: is a directory" \
    "$roadscale" rescale --trajectory "$out/a_dir" --kitti "$seq" --no-segmentation --out "$out/r"

  # --- the command line -------------------------------------------------------------------------
  expect_error 1 "^roadscale: error: unknown subcommand 'frobnicate' \(expected one of demo, eval" \
    "$roadscale" frobnicate
  expect_error 1 "^roadscale: error: .*--gt" "$roadscale" eval --gt
  expect_error 1 "^roadscale: error: .*--bogus" "$roadscale" run --bogus 1 --out "$out/r"
  expect_error 1 "^roadscale: error: .*--est.* is required" "$roadscale" eval --gt "$out/gt.txt"
  # A mistyped option is named, not the required one it leaves missing.
  expect_error 1 "^roadscale: error: The following arguments were not expected: .*--outt " \
    "$roadscale" run --kitti "$seq" --outt "$out/r"
  echo "bad inputs (files): $cases cases passed"
  exit 0
fi

if [[ "$mode" == "runs" ]]; then
  # A re-run into a used folder that fails part way leaves only its own files.
  expect_ok "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle --out "$out/used"
  for name in report.html metrics.json gt_poses_kitti.txt; do
    [[ -s "$out/used/$name" ]] || fail "the first run wrote no $name"
  done
  cp -r "$out/data" "$out/corrupt"
  echo "not a png" >"$out/corrupt/sequences/00/image_0/000012.png"
  expect_error 1 "000012\.png: cannot decode image" "$roadscale" run \
    --kitti "$out/corrupt/sequences/00" --no-segmentation --scale oracle --sequential \
    --out "$out/used"
  check_pose_rows "$out/used" 12
  for name in report.html metrics.json gt_poses_kitti.txt; do
    [[ ! -e "$out/used/$name" ]] || fail "the previous run's $name is still there"
  done

  # SIGTERM and SIGINT part way: no road plane ever (the frames wait for the first scale), and
  # the signal must still write every frame read so far. The frame-to-frame host writes each
  # scaled frame at once, so the wait for the first row below works.
  make_long
  for signal in TERM INT; do
    cases=$((cases + 1))
    run_dir="$out/signal_$signal"
    "$roadscale" run --kitti "$long" --no-segmentation --config "$out/noroad.yaml" --sequential \
      --out "$run_dir" >/dev/null 2>"$out/stderr.txt" &
    pid=$!
    for _ in $(seq 1 400); do
      [[ -s "$run_dir/poses_kitti.txt" ]] && break
      sleep 0.05
    done
    sleep 1
    kill -"$signal" "$pid" || fail "SIG$signal: the run ended before the signal"
    status=0
    wait "$pid" || status=$?
    [[ $status -eq 1 ]] || fail "SIG$signal: exit $status, expected 1: $(cat "$out/stderr.txt")"
    [[ "$(rows "$out/stderr.txt")" -eq 1 ]] || fail "SIG$signal: not one line: $(cat "$out/stderr.txt")"
    grep -Eq "interrupted after [0-9]+ frames: .*poses_kitti\.txt" "$out/stderr.txt" ||
      fail "SIG$signal: $(cat "$out/stderr.txt")"
    n="$(sed -E 's/.*interrupted after ([0-9]+) frames.*/\1/' "$out/stderr.txt")"
    [[ "$n" -ge 2 && "$n" -lt 400 ]] || fail "SIG$signal: $n frames"
    check_pose_rows "$run_dir" "$n"
    [[ "$(rows "$run_dir/frames.csv")" -eq $((n + 1)) ]] || fail "SIG$signal: frames.csv rows"
    [[ "$(grep -c ',unscaled,' "$run_dir/frames.csv")" -eq $((n - 1)) ]] ||
      fail "SIG$signal: the waiting frames are not all written as unscaled"
  done

  # rescale: stops after the frame in flight, its rows intact, one line, exit 1.
  for signal in TERM INT; do
    cases=$((cases + 1))
    run_dir="$out/rescale_$signal"
    "$roadscale" rescale --trajectory "$out/long/trajectory.txt" --kitti "$long" --no-segmentation \
      --out "$run_dir" >/dev/null 2>"$out/stderr.txt" &
    pid=$!
    for _ in $(seq 1 400); do
      [[ -f "$run_dir/rescale.csv" && "$(rows "$run_dir/rescale.csv")" -ge 3 ]] && break
      sleep 0.05
    done
    kill -"$signal" "$pid" || fail "rescale SIG$signal: the run ended before the signal"
    status=0
    wait "$pid" || status=$?
    [[ $status -eq 1 ]] || fail "rescale SIG$signal: exit $status: $(cat "$out/stderr.txt")"
    [[ "$(rows "$out/stderr.txt")" -eq 1 ]] || fail "rescale SIG$signal: $(cat "$out/stderr.txt")"
    grep -Eq "interrupted after [0-9]+ of 400 poses: .*poses_kitti\.txt" "$out/stderr.txt" ||
      fail "rescale SIG$signal: $(cat "$out/stderr.txt")"
    k="$(sed -E 's/.*interrupted after ([0-9]+) of.*/\1/' "$out/stderr.txt")"
    [[ "$k" -ge 3 && "$k" -lt 400 ]] || fail "rescale SIG$signal: $k poses"
    check_pose_rows "$run_dir" "$k"
    [[ "$(rows "$run_dir/rescale.csv")" -eq "$k" ]] || fail "rescale SIG$signal: rescale.csv rows"
  done
  echo "bad inputs (runs): $cases cases passed"
  exit 0
fi
if [[ "$mode" == "concurrent" ]]; then
  # Two processes into one output folder (issue 30: two batches lost rows of frames.csv and
  # overwrote batch.json): the second refuses with one line naming the holder and touches
  # nothing; the lock of a holder killed with -9 is taken over.
  make_long
  pid="" drive_pid=""
  trap 'report_case; kill -9 $pid $drive_pid 2>/dev/null || true; rm -rf "$out"' EXIT  # none left stopped
  wait_for() {  # FILE: until it exists and is not empty
    for _ in $(seq 1 400); do
      [[ -s "$1" ]] && return 0
      sleep 0.05
    done
    fail "$1 never appeared"
  }
  "$roadscale" run --kitti "$long" --no-segmentation --config "$out/noroad.yaml" --sequential \
    --out "$out/held" >/dev/null 2>&1 &
  pid=$!
  wait_for "$out/held/.roadscale.lock"
  kill -STOP "$pid"  # holds the folder for as long as the checks take, on any machine
  in_use="held: output folder in use by process $pid on $(hostname) \(roadscale run\); wait for it"
  expect_error 1 "$in_use" "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle \
    --out "$out/held"
  expect_error 1 "$in_use" "$roadscale" rescale --trajectory "$out/long/trajectory.txt" \
    --kitti "$long" --no-segmentation --out "$out/held"
  printf 'drives:\n  - name: a\n    kitti: %s\n    no_segmentation: true\n' "$seq" >"$out/m.yaml"
  expect_error 1 "$in_use" "$roadscale" batch --manifest "$out/m.yaml" --out "$out/held"
  [[ ! -e "$out/held/a" && ! -e "$out/held/batch.json" ]] ||
    fail "a refused process changed the folder in use"
  kill -9 "$pid"
  wait "$pid" 2>/dev/null || true
  [[ -s "$out/held/.roadscale.lock" ]] || fail "kill -9 left no stale lock to take over"
  expect_ok "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle --out "$out/held"
  check_pose_rows "$out/held" 40
  [[ ! -e "$out/held/.roadscale.lock" ]] || fail "the lock outlived its run"

  # Two batches into one folder, then --summarize and --slurm while the first runs; a `run`
  # into the folder of the drive the batch is running.
  printf 'drives:\n  - name: a\n    kitti: %s\n    no_segmentation: true\n    sequential: true\n    config: %s\n' \
    "$long" "$out/noroad.yaml" >"$out/long.yaml"
  "$roadscale" batch --manifest "$out/long.yaml" --out "$out/batch" >"$out/batch.log" 2>&1 &
  pid=$!
  wait_for "$out/batch/a/.roadscale.lock"
  drive_pid="$(cut -d ' ' -f 1 "$out/batch/a/.roadscale.lock")"
  kill -STOP "$pid" "$drive_pid"
  in_use="batch: output folder in use by process $pid on $(hostname) \(roadscale batch\)"
  expect_error 1 "$in_use" "$roadscale" batch --manifest "$out/m.yaml" --out "$out/batch"
  expect_error 1 "$in_use" "$roadscale" batch --summarize "$out/batch"
  expect_error 1 "$in_use" "$roadscale" batch --manifest "$out/m.yaml" --out "$out/batch" --slurm
  expect_error 1 "batch/a: output folder in use by process $drive_pid on .* \(roadscale run\)" \
    "$roadscale" run --kitti "$seq" --no-segmentation --scale oracle --out "$out/batch/a"
  [[ ! -e "$out/batch/slurm" && ! -e "$out/batch/summary.md" ]] ||
    fail "a refused batch wrote into the folder in use"
  # SIGTERM to the batch: its drive is stopped, reported as interrupted (not FAILED).
  kill -CONT "$drive_pid" "$pid"
  kill -TERM "$pid"
  wait "$pid" 2>/dev/null || true
  grep -q "a: interrupted after" "$out/batch.log" || fail "no interrupted line: $(cat "$out/batch.log")"
  ! grep -q "FAILED" "$out/batch.log" || fail "an interrupted drive shown as FAILED"
  grep -q -- "- a: interrupted: the same command runs it again" "$out/batch/summary.md" ||
    fail "the summary does not list the drive as interrupted: $(cat "$out/batch/summary.md")"
  echo "bad inputs (concurrent): $cases cases passed"
  exit 0
fi
fail "unknown mode $mode"
