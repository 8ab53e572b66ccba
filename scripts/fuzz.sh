#!/usr/bin/env bash
# Builds the libFuzzer targets of roadscale's parsers (clang, AddressSanitizer and
# UndefinedBehaviorSanitizer, in build-fuzz/) and runs each for SECONDS seconds from its seed
# corpus in fuzz/corpus/<name>/. Installs clang and its fuzzer runtime (Debian packages) when
# they are missing. Runs JOBS targets at once (default: one a core). Fails when a target
# crashes, leaks, hangs (10 s on one input) or lets anything but roadscale::Error escape; the
# input that did it is kept in $build/crashes/. Prints the executions of every target.
#
#   scripts/fuzz.sh 20              # 20 s per target
#   JOBS=1 scripts/fuzz.sh 600      # longer runs
#   FUZZ_SEED=0 scripts/fuzz.sh 60  # libFuzzer's own random seed (default 1: CI explores the
#                                   # same inputs every time, as far as its time allows)
#   scripts/fuzz.sh --install-only  # only clang and its runtimes (for a clang sanitizer build)
#   FUZZ_BUILD_DIR=build-asan scripts/fuzz.sh 10
#                                   # the targets of a build configured with ROADSCALE_FUZZ=ON
#                                   # and ROADSCALE_SANITIZE=ON (CI: one instrumented build for
#                                   # the unit tests and the fuzzers)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:?usage: scripts/fuzz.sh SECONDS | --install-only}"

PACKAGES=(clang libclang-rt-14-dev)
missing=()
for package in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]} > 0)); then
  echo "fuzz: installing ${missing[*]}"
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
fi

[[ "$seconds" == --install-only ]] && exit 0

build="${FUZZ_BUILD_DIR:-build-fuzz}"
targets=(kitti_calib kitti_times trajectory camera_yaml run_config model_yaml scene_yaml
  png_structure batch_manifest batch_json slurm_options)
if [[ -z "${FUZZ_BUILD_DIR:-}" ]]; then
  # -O1 with line tables only, as OSS-Fuzz builds: enough for the sanitizers' stack traces,
  # and the build (the whole library, instrumented) is the slow part of a short run.
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DROADSCALE_FUZZ=ON -DROADSCALE_SANITIZE=ON \
    -DROADSCALE_BUILD_TESTS=OFF -DROADSCALE_BUILD_BENCHMARKS=OFF >/dev/null
elif ! grep -q '^ROADSCALE_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "fuzz: $build is not a build configured with -DROADSCALE_FUZZ=ON" >&2
  exit 2
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/%/_fuzzer}"

mkdir -p "$build/crashes"
# The targets that read files write each input to $TMPDIR: in memory when there is /dev/shm.
scratch_parent=/dev/shm
[[ -d "$scratch_parent" && -w "$scratch_parent" ]] || scratch_parent="${TMPDIR:-/tmp}"
scratch="$(mktemp -d -p "$scratch_parent" roadscale_fuzz.XXXXXX)"
trap 'rm -rf "$scratch"' EXIT
# Runs one target; its exit status goes to $build/$name.status.
fuzz_target() {
  local name="$1" status=0
  # New inputs go to a scratch corpus, never into the repository's seeds.
  local work="$build/corpus/$name"
  mkdir -p "$work" "$scratch/$name"
  TMPDIR="$scratch/$name" ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "$build/fuzz/${name}_fuzzer" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/crashes/$name-" \
    "$work" "fuzz/corpus/$name" >"$build/$name.log" 2>&1 || status=$?
  echo "$status" >"$build/$name.status"
}

# JOBS targets at a time (default: one a core); each fuzzer is one process on one core.
jobs_at_once="${JOBS:-$(nproc)}"
if ! [[ "$jobs_at_once" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz: JOBS must be a whole number >= 1, got '$jobs_at_once'" >&2
  exit 2
fi
for name in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs_at_once)); do wait -n || true; done
  fuzz_target "$name" &
done
wait

summary=()
failed=0
for name in "${targets[@]}"; do
  log="$build/$name.log"
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")"
  if [[ "$(cat "$build/$name.status")" != 0 ]]; then
    tail -n 40 "$log"
    echo "fuzz: $name FAILED after ${runs:-?} executions (input kept in $build/crashes/)"
    failed=1
    continue
  fi
  summary+=("$(printf '%-14s %10s executions in %s s, 0 crashes' "$name" "$runs" "$seconds")")
done
((${#summary[@]} == 0)) || printf 'fuzz: %s\n' "${summary[@]}"
exit "$failed"
