#!/usr/bin/env bash
# check's own path (runner, then judge, as ./workbook check runs them) on mutants whose C++ exercise
# feeds the other exercises' scenes: only the mutant's exercise may be marked wrong. The runner's app
# replays the reference's results for the other C++ exercises while it records the graded one
# (common/judge/reference_calls.hpp); before that, 10.1's integer fraction made 10.2-10.4 wrong.
# Usage: check_attribution_test.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${1:?usage: check_attribution_test.sh BUILD_DIR SCRATCH_DIR}
scratch=${2:?usage: check_attribution_test.sh BUILD_DIR SCRATCH_DIR}
failures=0
for mutant in 10_cascades/fraction_integer_division:10.1 09_shadow_volumes/corners_then_neighbours:09.1; do
  lab=${mutant%%/*} name=${mutant#*/} && name=${name%%:*} id=${mutant##*:} nn=${lab:0:2}
  tape="$scratch/$nn-$name" && rm -rf "$tape" && mkdir -p "$tape"
  WB_RECORD_SHADERS="$root/solutions/$lab/shaders" WB_RUN_TIMEOUT=60 \
    "$build/lab${nn}_mutant_${name}_tests" --runner "$tape" >"$tape/runner.log" 2>&1 || true
  WB_SUBMISSION_DIR="$build/mutants/$lab/$name" \
    "$build/lab${nn}_solution_tests" --judge "$tape" --check >"$tape/judge.log" 2>&1 || true
  wrong=$(awk '$1 ~ /^[0-9][0-9]\.([0-9x]|H[0-9])$/ && $2 == "wrong" { print $1 }' "$tape/judge.log" | tr '\n' ' ')
  if [ "$wrong" = "$id " ]; then
    echo "ok: $lab/$name: check marks $id alone"
  else
    echo "FAIL: $lab/$name (a mistake in $id): check marks wrong: '${wrong}'"
    sed -n '/^Lab /,$p' "$tape/judge.log"
    failures=$((failures + 1))
  fi
done
exit "$failures"
