# Shared helpers for the end-to-end tests (sourced; tests/CMakeLists.txt
# excludes this file from the tests it registers).
# Usage in a test:  source "$(dirname "$0")/lib.sh"; e2e_begin "$@"
set -euo pipefail

e2e_begin() {
  LIGHTCONE="$1"
  SRC="$2"
  WORK="$3"
  rm -rf "$WORK"
  mkdir -p "$WORK"
  cd "$WORK"
  FAILURES=0
  CHECKS=0
}

fail() {
  echo "FAIL: $*" >&2
  FAILURES=$((FAILURES + 1))
}

# expect_error NAME EXPECTED_SUBSTRING -- command...
# The command must exit non-zero (not by a signal) and print the substring on stderr.
expect_error() {
  local name="$1" want="$2"
  shift 3
  CHECKS=$((CHECKS + 1))
  local rc=0
  "$@" >"$WORK/$name.out" 2>"$WORK/$name.err" || rc=$?
  if [ "$rc" -eq 0 ]; then
    fail "$name: exit 0, expected an error"
  elif [ "$rc" -gt 128 ]; then
    fail "$name: died with signal $((rc - 128))"
  elif ! grep -qF -- "$want" "$WORK/$name.err"; then
    fail "$name: stderr lacks '$want'; got: $(cat "$WORK/$name.err")"
  fi
}

e2e_end() {
  echo "$CHECKS error checks; $FAILURES failures"
  [ "$FAILURES" -eq 0 ]
}
