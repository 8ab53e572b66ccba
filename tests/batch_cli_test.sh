#!/usr/bin/env bash
# End-to-end tests of `roadscale batch` on this machine (no Slurm).
# Usage: batch_cli_test.sh ROADSCALE_BINARY [errors|resume|failure|slurm_script]
#   errors:       bad manifests and options fail with one line naming the file, line or option;
#   resume:       two rendered drives run with --jobs 2; the summary's numbers are each drive's
#                 metrics.json; run again, both are skipped and their files untouched; a drive
#                 whose frames or config file changed runs again, the other is skipped;
#                 --summarize rebuilds the same summary;
#   failure:      a drive whose run fails (a bad config) is listed at the end with exit 1 and
#                 its error, while the other drive's outputs and the summary are intact;
#   slurm_script: --slurm writes the job array for the manifest's drives and runs nothing.
set -euo pipefail
roadscale="$1"
mode="${2:-errors}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scratch="$work"
# shellcheck source=cli_checks.sh
source "$(dirname "$0")/cli_checks.sh"
render() {  # FOLDER PRESET FRAMES: a short rendered drive with ground truth and label images
  "$roadscale" synth --preset "$2" --frames "$3" --out "$work/$1" >/dev/null 2>&1 ||
    fail "synth $1 failed"
}
drive() {  # NAME FOLDER [more manifest lines]: a manifest entry for a drive rendered in FOLDER
  printf '  - name: %s\n    kitti: %s/sequences/00\n    labels: %s/sequences/00/semantic\n' \
    "$1" "$2" "$2"
  shift 2
  for line in "$@"; do printf '    %s\n' "$line"; done
}
# The summary's numbers against each drive's metrics.json: the same doubles.
check_summary() {  # BATCH_DIR DRIVE...
  python3 - "$@" <<'PY' || fail "summary does not match the drives' metrics.json"
import csv, json, sys
batch, drives = sys.argv[1], sys.argv[2:]
rows = {row["name"]: row for row in csv.DictReader(open(f"{batch}/summary.csv"))}
summary = json.load(open(f"{batch}/summary.json"))
assert [d["name"] for d in summary["drives"]] == drives, summary["drives"]
for name in drives:
    m = json.load(open(f"{batch}/{name}/metrics.json"))
    expected = {"frames": m["frames"], "t_err_pct": m["kitti"]["t_err_pct"],
                "r_err_deg_per_m": m["kitti"]["r_err_deg_per_m"], "ate_se3_m": m["ate_m"]["se3"],
                "ate_sim3_m": m["ate_m"]["sim3"], "length_ratio": m["length_ratio"]}
    for key, value in expected.items():
        text = rows[name][key]
        assert (text == "" if value is None else float(text) == value), (name, key, text, value)
    in_json = next(d for d in summary["drives"] if d["name"] == name)
    assert in_json["t_err_pct"] == m["kitti"]["t_err_pct"], in_json
    assert in_json["report"] == f"{name}/report.html"
t_errs = [json.load(open(f"{batch}/{n}/metrics.json"))["kitti"]["t_err_pct"] for n in drives]
t_errs = [t for t in t_errs if t is not None]
if t_errs:
    assert abs(float(rows["mean"]["t_err_pct"]) - sum(t_errs) / len(t_errs)) < 1e-12, rows["mean"]
lengths = [json.load(open(f"{batch}/{n}/metrics.json"))["length_ratio"] for n in drives]
assert abs(float(rows["mean"]["length_ratio"]) - sum(lengths) / len(lengths)) < 1e-12, rows["mean"]
print("summary matches metrics.json of", ", ".join(drives))
PY
}

if [[ "$mode" == "errors" ]]; then
  mkdir -p "$work/seq"
  printf 'drives:\n  - name: a\n    kitti: seq\n    frame: "0:10"\n' >"$work/unknown.yaml"
  expect_failure "unknown.yaml:4: unknown key 'frame'" \
    "$roadscale" batch --manifest "$work/unknown.yaml" --out "$work/out"
  printf 'drives:\n  - name: a\n    kitti: nowhere\n' >"$work/missing.yaml"
  expect_failure "missing.yaml:3: kitti folder '$work/nowhere' does not exist" \
    "$roadscale" batch --manifest "$work/missing.yaml" --out "$work/out"
  printf 'drives:\n  - name: a\n    kitti: seq\n  - name: a\n    kitti: seq\n' >"$work/twice.yaml"
  expect_failure "twice.yaml:4: drive name 'a' appears twice \(first on line 2\)" \
    "$roadscale" batch --manifest "$work/twice.yaml" --out "$work/out"
  expect_failure "no-such.yaml: cannot open batch manifest" \
    "$roadscale" batch --manifest "$work/no-such.yaml" --out "$work/out"
  printf 'drives:\n  - name: a\n    kitti: seq\n' >"$work/good.yaml"
  expect_failure "--only-index 1: the batch has 1 drives" \
    "$roadscale" batch --manifest "$work/good.yaml" --out "$work/out" --only-index 1
  expect_failure "--only-index -1: the batch has 1 drives \(0\.\.0\)" \
    "$roadscale" batch --manifest "$work/good.yaml" --out "$work/out" --only-index -1
  expect_failure "give exactly one of --manifest FILE and --kitti-root ROOT" \
    "$roadscale" batch --out "$work/out"
  expect_failure "sequences/03: no such KITTI sequence folder" \
    "$roadscale" batch --kitti-root "$work" --sequences 03 --out "$work/out"
  expect_failure "--sequences '0-x'" "$roadscale" batch --kitti-root "$work" --sequences 0-x \
    --out "$work/out"
  expect_failure "no-batch: not a batch output folder" \
    "$roadscale" batch --summarize "$work/no-batch"
  expect_failure "--submit goes with --slurm" \
    "$roadscale" batch --manifest "$work/good.yaml" --out "$work/out" --submit
  [[ ! -e "$work/out" ]] || fail "a refused batch created its output folder"
  # A drive named after the batch's own files (issue 30).
  for name in batch.json summary.md Summary.HTML; do
    printf 'drives:\n  - name: %s\n    kitti: seq\n' "$name" >"$work/reserved.yaml"
    expect_failure "reserved.yaml:2: drive '$name': '.*' is a file of the batch itself" \
      "$roadscale" batch --manifest "$work/reserved.yaml" --out "$work/out"
  done
  # One drive that cannot start (its folder is a file) does not stop the next one (issue 30).
  printf 'drives:\n  - name: a\n    kitti: seq\n  - name: b\n    kitti: seq\n' >"$work/two.yaml"
  mkdir -p "$work/started" && touch "$work/started/a"
  expect_failure "^roadscale: error: 2 of 2 drives failed: a \(.*started/a: cannot create the drive's folder.*\); b \(exit status 1: " \
    "$roadscale" batch --manifest "$work/two.yaml" --out "$work/started"
  expect_line "$scratch/stdout.txt" "a: FAILED before starting: .*started/a: cannot create"
  [[ -s "$work/started/b/run.log" && -f "$work/started/summary.md" ]] ||
    fail "the batch stopped at the drive that could not start"
  # --summarize refuses a batch.json whose names no drive can have (they became paths).
  mkdir -p "$work/forged"
  printf '{"drives": ["../../../etc"]}\n' >"$work/forged/batch.json"
  expect_failure "forged/batch.json: drive '\.\./\.\./\.\./etc': a drive's name must" \
    "$roadscale" batch --summarize "$work/forged"
  [[ ! -e "$work/forged/summary.md" ]] || fail "a forged batch.json was summarised"
  # The same for a config the user cannot read (root reads every file: run as nobody).
  if [[ $(id -u) -eq 0 ]] && setpriv --reuid=65534 --regid=65534 --clear-groups true 2>/dev/null; then
    chmod 755 "$work" "$work/seq"
    printf 'Scale:\n  filter_window: 5\n' >"$work/secret.yaml"
    chmod 000 "$work/secret.yaml"
    printf 'drives:\n  - name: a\n    kitti: seq\n    config: secret.yaml\n  - name: b\n    kitti: seq\n' \
      >"$work/secret_m.yaml"
    mkdir -m 777 "$work/secret_out"
    expect_failure "2 of 2 drives failed: a \(.*secret\.yaml: cannot open .*permission denied\); b \(exit" \
      setpriv --reuid=65534 --regid=65534 --clear-groups \
      "$roadscale" batch --manifest "$work/secret_m.yaml" --out "$work/secret_out"
  fi
  echo "batch errors: all checks passed"
  exit 0
fi

if [[ "$mode" == "resume" ]]; then
  render d1 urban 40     # 30 m: too short for the KITTI metric (null)
  render d2 highway 50  # 120 m: a KITTI t_err
  cd "$work"
  printf 'Scale:\n  filter_window: 5\n' >run.yaml
  { echo "drives:"; drive one d1; drive two d2 "config: run.yaml"; } >manifest.yaml
  "$roadscale" batch --manifest manifest.yaml --out out --jobs 2 >log1.txt 2>&1 ||
    fail "batch failed: $(cat log1.txt)"
  cat log1.txt
  expect_line log1.txt "^\[2/2\] (one|two): done in"
  for name in one two; do
    for file in poses_kitti.txt frames.csv report.html metrics.json run.log batch_drive.json; do
      [[ -f "out/$name/$file" ]] || fail "out/$name/$file missing"
    done
  done
  for file in summary.md summary.csv summary.json summary.html; do
    [[ -f "out/$file" ]] || fail "out/$file missing"
  done
  check_summary out one two
  expect_line out/summary.md '^\| \[one\]\(one/report.html\) \| 40 \|'
  python3 -c "import csv,sys; r={x['name']: x for x in csv.DictReader(open('out/summary.csv'))}; sys.exit(r['two']['t_err_pct'] == '')" ||
    fail "drive two has no t_err in the summary"
  expect_line out/summary.html '<a href="two/report.html">two</a>'

  # The same batch again: nothing runs, nothing is rewritten.
  touch -d '2000-01-01' out/one/poses_kitti.txt out/two/poses_kitti.txt
  "$roadscale" batch --manifest manifest.yaml --out out --jobs 2 >log2.txt 2>&1 ||
    fail "second batch failed: $(cat log2.txt)"
  cat log2.txt
  [[ "$(grep -c 'skipped (finished before with the same config)' log2.txt)" -eq 2 ]] ||
    fail "expected both drives skipped"
  [[ -z "$(find out -name poses_kitti.txt -newer manifest.yaml)" ]] || fail "a skipped drive ran"

  # A changed frame range reruns drive one; a changed config file reruns drive two.
  { echo "drives:"; drive one d1 'frames: "0:30"'; drive two d2 "config: run.yaml"; } >manifest.yaml
  "$roadscale" batch --manifest manifest.yaml --out out >log3.txt 2>&1 ||
    fail "third batch failed: $(cat log3.txt)"
  cat log3.txt
  expect_line log3.txt "one: done in"
  expect_line log3.txt "two: skipped"
  [[ "$(wc -l <out/one/poses_kitti.txt)" -eq 30 ]] || fail "drive one did not rerun on 30 frames"
  printf 'Scale:\n  filter_window: 7\n' >run.yaml
  "$roadscale" batch --manifest manifest.yaml --out out >log4.txt 2>&1 ||
    fail "fourth batch failed: $(cat log4.txt)"
  cat log4.txt
  expect_line log4.txt "one: skipped"
  expect_line log4.txt "two: done in"
  expect_line out/two/config_used.yaml "filter_window: 7"
  check_summary out one two

  # --summarize rebuilds the same files from the finished drives.
  mkdir kept && cp out/summary.* kept/ && rm out/summary.*
  "$roadscale" batch --summarize out >log5.txt 2>&1 || fail "--summarize failed: $(cat log5.txt)"
  for file in summary.md summary.csv summary.json summary.html; do
    cmp -s "kept/$file" "out/$file" || fail "--summarize wrote a different $file"
  done
  echo "batch resume: all checks passed"
  exit 0
fi

if [[ "$mode" == "failure" ]]; then
  render d1 urban 40
  cd "$work"
  printf 'Scale:\n  no_such_key: 1\n' >bad.yaml
  { echo "drives:"; drive bad d1 "config: bad.yaml"; drive good d1; } >manifest.yaml
  if "$roadscale" batch --manifest manifest.yaml --out out --jobs 2 >log.txt 2>err.txt; then
    fail "a batch with a failing drive exited 0"
  fi
  cat log.txt err.txt
  [[ "$(wc -l <err.txt)" -eq 1 ]] || fail "not one line on stderr"
  expect_line err.txt "^roadscale: error: 1 of 2 drives failed: bad \(exit status 1: .*bad.yaml:2: unknown key 'Scale.no_such_key'"
  expect_line log.txt "bad: FAILED after"
  expect_line log.txt "good: done in"
  [[ "$(wc -l <out/good/poses_kitti.txt)" -eq 40 ]] || fail "the good drive's poses are incomplete"
  check_summary out good
  expect_line out/summary.md "^- bad: failed \(exit status 1\): .*unknown key"
  python3 -c "import json,sys; u=json.load(open('out/summary.json'))['unfinished']; sys.exit(u[0]['name'] != 'bad')" ||
    fail "summary.json does not list the failed drive"
  # Fixing the config reruns the failed drive and skips the good one.
  printf 'Scale:\n  filter_window: 5\n' >bad.yaml
  "$roadscale" batch --manifest manifest.yaml --out out >log2.txt 2>&1 ||
    fail "the fixed batch failed: $(cat log2.txt)"
  expect_line log2.txt "bad: done in"
  expect_line log2.txt "good: skipped"
  check_summary out bad good
  echo "batch failure: all checks passed"
  exit 0
fi

if [[ "$mode" == "slurm_script" ]]; then
  mkdir -p "$work/seq1" "$work/seq2"
  printf 'drives:\n  - name: a\n    kitti: seq1\n  - name: b\n    kitti: seq2\n' >"$work/m.yaml"
  "$roadscale" batch --manifest "$work/m.yaml" --out "$work/out" --slurm --partition short \
    --time 1:00:00 >"$work/log.txt" 2>&1 || fail "--slurm failed: $(cat "$work/log.txt")"
  cat "$work/log.txt"
  expect_line "$work/out/slurm/drives.sbatch" "^#SBATCH --array=0-1$"
  expect_line "$work/out/slurm/drives.sbatch" "^#SBATCH --partition=short$"
  expect_line "$work/out/slurm/drives.sbatch" \
    "^exec $roadscale batch --manifest $work/m.yaml --out $work/out --only-index \"\\\$SLURM_ARRAY_TASK_ID\"$"
  expect_line "$work/out/slurm/summary.sbatch" "^exec $roadscale batch --summarize $work/out$"
  [[ -x "$work/out/slurm/submit.sh" ]] || fail "submit.sh is not executable"
  expect_line "$work/log.txt" "must be on a filesystem every node of the cluster sees"
  [[ ! -e "$work/out/a" ]] || fail "--slurm ran a drive"
  # Values that would end their #SBATCH line and run the rest as a command in every task
  # (issue 30): refused with one line, before any file is written.
  cd "$work"
  for option in "--sbatch-option=--account=lab"$'\n'"touch PWNED" \
    "--partition=short"$'\n'"touch PWNED" "--time=1:00:00"$'\n'"touch PWNED" \
    "--partition=a b" "--time=an hour" "--sbatch-option=--comment=\$(touch PWNED)"; do
    name="${option%%=*}"
    expect_failure "^roadscale: error: $name '" \
      "$roadscale" batch --manifest "$work/m.yaml" --out "$work/refused" --slurm "$option"
  done
  expect_failure "^roadscale: error: --sbatch-option '--account=lab\\\\ntouch PWNED': expected" \
    "$roadscale" batch --manifest "$work/m.yaml" --out "$work/refused" --slurm \
    "--sbatch-option=--account=lab"$'\n'"touch PWNED"
  expect_failure "^roadscale: error: --out '$work/100%a': Slurm scripts need" \
    "$roadscale" batch --manifest "$work/m.yaml" --out "$work/100%a" --slurm
  [[ ! -e "$work/refused" && ! -e "$work/100%a" ]] || fail "a refused --slurm wrote files"
  [[ ! -e PWNED ]] || fail "an option ran as a command"
  echo "batch slurm script: all checks passed"
  exit 0
fi
fail "unknown mode $mode"
