# Checks shared by the CLI test scripts; source it after setting `scratch` to a temporary
# folder (expect_failure keeps the command's stdout and stderr there).

fail() {
  echo "FAILED: $*"
  exit 1
}
expect_line() {  # FILE REGEX
  grep -Eq -- "$2" "$1" || fail "no line matching '$2' in: $(cat "$1")"
}
# The command must fail with exactly one line on stderr, matching REGEX.
expect_failure() {  # REGEX COMMAND...
  local regex="$1"
  shift
  if "$@" >"$scratch/stdout.txt" 2>"$scratch/stderr.txt"; then
    fail "succeeded but should fail: $*"
  fi
  [[ "$(wc -l <"$scratch/stderr.txt")" -eq 1 ]] ||
    fail "not one line on stderr: $(cat "$scratch/stderr.txt")"
  expect_line "$scratch/stderr.txt" "$regex"
}
