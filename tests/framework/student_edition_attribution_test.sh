#!/usr/bin/env bash
# check in the student edition, which has no solution shaders: a scene there draws every GLSL
# exercise with the student's own, so a wrong 09.2 spills into 09.3's scenes. check must then say
# "blocked by 09.2" for 09.3, never "wrong". Run with the solution's tests as the student edition
# runs them (--as-student-edition) on GLSL mutants (WB_SUBMISSION_DIR), in ctest's direct mode.
# Usage: student_edition_attribution_test.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: student_edition_attribution_test.sh BUILD_DIR}
failures=0
for mutant in 09_shadow_volumes/w_ignored:09.2 10_cascades/interval_off_by_one:10.5; do
  lab=${mutant%%/*} name=${mutant#*/} && name=${name%%:*} id=${mutant##*:} nn=${lab:0:2}
  out="$build/test-output/student-edition-attribution/$nn-$name" && rm -rf "$out" && mkdir -p "$out"
  WB_TEST_OUTPUT_DIR="$out" WB_SUBMISSION_DIR="$build/mutants/$lab/$name" \
    "$build/lab${nn}_solution_tests" --as-student-edition --check >"$out/check.log" 2>&1 || true
  wrong=$(awk '$1 ~ /^[0-9][0-9]\.[0-9x]$/ && $2 == "wrong" { print $1 }' "$out/check.log" | tr '\n' ' ')
  if [ "$wrong" = "$id " ]; then
    echo "ok: $lab/$name: check marks $id alone wrong; $(grep -c "blocked by $id" "$out/check.log") blocked by it"
  else
    echo "FAIL: $lab/$name (a mistake in $id), as the student edition: check marks wrong: '${wrong}'"
    sed -n '/^Lab /,$p' "$out/check.log"
    failures=$((failures + 1))
  fi
done
exit "$failures"
