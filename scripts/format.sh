#!/usr/bin/env bash
# clang-format every C++ file of the project; with --check, change nothing and fail when a
# file is not formatted (CTest runs this as the `style.clang_format` test).
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cc' '*.h')
if [[ "${1:-}" == "--check" ]]; then
  clang-format --dry-run -Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
