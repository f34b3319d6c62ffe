#!/usr/bin/env bash
# check in the student edition, which has no solution shaders: a scene there draws every GLSL
# exercise with the student's own, so a wrong 09.2 spills into 09.3's scenes. check must then say
# that 09.3 passes its own tests and that its scene is checked once 09.2 passes, never "wrong" or
# "error", and count it in the summary as the grader will (which draws 09.2 with the reference). Run with the solution's tests as the student edition
# runs them (--as-student-edition) on GLSL mutants (WB_SUBMISSION_DIR), in ctest's direct mode.
# Usage: student_edition_attribution_test.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: student_edition_attribution_test.sh BUILD_DIR}
# (its own folder under a log stand-in: ctest runs both variants of this test at once)
outs="$build/test-output/student-edition-attribution${WB_SHADER_LOG_AS:+-$WB_SHADER_LOG_AS}"
failures=0
for mutant in 09_shadow_volumes/w_ignored:09.2 10_cascades/interval_off_by_one:10.5; do
  lab=${mutant%%/*} name=${mutant#*/} && name=${name%%:*} id=${mutant##*:} nn=${lab:0:2}
  out="$outs/$nn-$name" && rm -rf "$out" && mkdir -p "$out"
  WB_TEST_OUTPUT_DIR="$out" WB_SUBMISSION_DIR="$build/mutants/$lab/$name" \
    "$build/lab${nn}_solution_tests" --as-student-edition --check >"$out/check.log" 2>&1 || true
  wrong=$(awk '$1 ~ /^[0-9][0-9]\.([0-9x]|H[0-9])$/ && $2 == "wrong" { print $1 }' "$out/check.log" | tr '\n' ' ')
  errors=$(awk '$1 ~ /^[0-9][0-9]\.([0-9x]|H[0-9])$/ && $2 == "error" { print $1 }' "$out/check.log" | tr '\n' ' ')
  waiting=$(grep -c "its scene is checked once $id passes" "$out/check.log" || true)
  # Every other exercise is the solution's: the summary must count all of them, as the grader does.
  summary=$(grep -o "[0-9]* of [0-9]* exercises pass their tests" "$out/check.log" || true)
  passing=${summary%% of *} total=${summary#* of } && total=${total%% *}
  if [ "$wrong" = "$id " ] && [ -z "$errors" ] && [ "$passing" = $((total - 1)) ]; then
    echo "ok: $lab/$name: check marks $id alone wrong; $waiting pass their own tests and wait on it:" \
      "$(grep "exercises pass their tests" "$out/check.log")"
  else
    echo "FAIL: $lab/$name (a mistake in $id), as the student edition: check marks wrong: '${wrong}', error:" \
      "'${errors}', and says '$summary' (want $((total - 1)) of $total)"
    sed -n '/^Lab /,$p' "$out/check.log"
    failures=$((failures + 1))
  fi
done
# A missing ';' in 02.5 (the student edition has no reference to compile the others with): the app
# names 02.5 by compiling each chunk alone; the other GLSL exercises are tried with the stub's 02.5,
# the C++ ones need no GLSL of 02.5's, and every scene waits on 02.5; so 02.5 alone is an error, the
# summary counts the others that have tests of their own, and the bug hunts, measured by their scenes
# alone, wait on 02.5: neither passed nor failed.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out="$outs/02-missing-semicolon" && rm -rf "$out" && mkdir -p "$out/sub/shaders"
sed 's/\(return worldPos + normal \* (scale \* texelWorld \* slope)\);/\1/' \
  "$root/solutions/02_bias/shaders/exercise.glsl" >"$out/sub/shaders/exercise.glsl"
if cmp -s "$root/solutions/02_bias/shaders/exercise.glsl" "$out/sub/shaders/exercise.glsl"; then
  echo "FAIL: the test could not take the ';' out of 02.5 (the solution's line changed?)"
  failures=$((failures + 1))
else
  WB_TEST_OUTPUT_DIR="$out" WB_SUBMISSION_DIR="$out/sub" \
    "$build/lab02_solution_tests" --as-student-edition --check >"$out/check.log" 2>&1 || true
  errors=$(awk '$1 ~ /^02\.([0-9]|H[0-9])$/ && ($2 == "error" || $2 == "wrong") { print $1 }' "$out/check.log" | tr '\n' ' ')
  total=$(grep -c '"id":' "$root/labs/02_bias/exercises.json")
  hunts=$(grep -c '"kind": "hunt"' "$root/labs/02_bias/exercises.json")
  waiting=$(awk '$1 ~ /^02\.H[0-9]$/ && $2 == "waiting" { print $1 }' "$out/check.log" | wc -l)
  if [ "$errors" = "02.5 " ] && grep -q "$((total - 1 - hunts)) of $total exercises pass their tests" "$out/check.log" &&
     [ "$waiting" = "$hunts" ] && grep -q "exercise.glsl:20: error" "$out/check.log"; then
    echo "ok: a missing ';' in 02.5: 02.5 alone is an error, at exercise.glsl:20; $((total - 1 - hunts)) count," \
      "the $hunts hunts wait on it"
  else
    echo "FAIL: a missing ';' in 02.5, as the student edition: errors or wrong: '$errors' (want 02.5 alone," \
      "$((total - 1 - hunts)) of $total passing and the $hunts hunts waiting; $waiting wait)"
    sed -n '/^Lab /,$p' "$out/check.log"
    failures=$((failures + 1))
  fi
fi
exit "$failures"
