#!/usr/bin/env bash
# The endless-loop hints, proven by a mutant: 07.2's blocker search without ++k runs until the loop
# guard stops it (common/platform/loop_guard.hpp: 50000 steps, on any GL implementation), far longer
# than the reference's, and check must name an endless loop in 07.2 alone (by the time it took, or
# by the count of 50000).
# Usage: endless_loop_named_test.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: endless_loop_named_test.sh BUILD_DIR}
out="$build/test-output/endless-loop-named" && rm -rf "$out" && mkdir -p "$out"
WB_TEST_OUTPUT_DIR="$out" WB_SUBMISSION_DIR="$build/mutants/07_pcss/blocker_loop_endless" \
  "$build/lab07_solution_tests" --check --gtest_filter='*Ex07_2_*' >"$out/check.log" 2>&1 || true
row=$(sed -n '/^  07\.2 /,/^  07\.3 /p' "$out/check.log")
others=$(grep -cE "^  07\.[134] +(wrong|error)" "$out/check.log" || true)
if grep -q "^  07.2  wrong" <<<"$row" && grep -qE "an endless loop\? \(a GPU would hang on it\)|looks like an endless loop: it ran 50000 steps" <<<"$row" &&
   [ "$others" = 0 ]; then
  echo "ok: 07.2 without ++k is wrong, and named an endless loop"
else
  echo "FAIL: 07.2 without ++k: check did not name an endless loop in 07.2:"
  sed -n '/^Lab /,$p' "$out/check.log"
  exit 1
fi
