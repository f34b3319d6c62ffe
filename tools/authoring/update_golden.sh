#!/usr/bin/env bash
# Usage: update_golden.sh TEST_BINARY LOG (./workbook golden NN runs it with the solution's tests).
set -euo pipefail
# Runs a solution's tests with --update-golden (which rewrites tests/golden/NN_*/: the images and the
# reference's calls, tests/golden/NN_*/calls/; the held-out ones under tests/hidden/NN_*/), keeping
# their whole output in LOG. Not `tests | grep '^updated'`: the grep hid gtest's messages when a test
# failed, and under pipefail a run that updated nothing failed too, silently (grep found no line).
update_golden() {  # TEST_BINARY LOG
  local tests=$1 log=$2 status=0 count
  mkdir -p "$(dirname "$log")"
  "$tests" --update-golden >"$log" 2>&1 || status=$?
  awk '/^updated / && !seen[$0]++' "$log"  # a file that several tests update is listed once
  count=$(awk '/^updated / && !seen[$0]++' "$log" | wc -l)
  if [ "$status" -ne 0 ]; then
    # Everything but the tests that passed: start-up errors, the failing tests, a crash, the summary.
    awk '/^\[ RUN      \]/ { inside = 1; buf = $0 "\n"; next }
         inside && /^\[       OK \]/ { inside = 0; buf = ""; next }
         inside && /^\[  FAILED  \]/ { inside = 0; printf "%s%s\n", buf, $0; buf = ""; next }
         inside { buf = buf $0 "\n"; next }
         { print }
         END { if (inside) printf "%s", buf }' "$log" >&2
    echo "workbook: regenerating the golden data failed ($tests exited with $status; $count files were" \
         "updated before that; full log: $log)" >&2
    exit "$status"
  fi
  [ "$count" -gt 0 ] || echo "workbook: the scene tests passed but updated no golden file (full log: $log)" >&2
  echo "workbook: updated $count golden files (full log: $log); look at them before committing"
}

update_golden "$@"
