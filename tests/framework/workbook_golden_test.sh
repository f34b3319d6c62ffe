#!/usr/bin/env bash
# ./workbook golden NN runs the solution's scene tests with --update-golden
# (tools/authoring/update_golden.sh). Held here with fake test binaries that print what gtest
# prints: when a test fails, its messages are shown (not those of the tests that passed) and the exit
# code is not 0; when all pass, the updated files are listed and the exit code is 0.
# Usage: workbook_golden_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: workbook_golden_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

cat >"$tmp/failing_tests" <<'EOF'
#!/usr/bin/env bash
[ "$1" = --update-golden ] || exit 99
cat <<'OUT'
Note: Google Test filter = *Scene*
[==========] Running 2 tests from 1 test suite.
[ RUN      ] Lab01.Ex01_3_SceneMatchesGolden
updated tests/golden/01_depth_map/ex01_3.pfm
[       OK ] Lab01.Ex01_3_SceneMatchesGolden (812 ms)
[ RUN      ] Lab01.Ex01_4_SceneMatchesGolden
tests/lab01_test.cpp:88: Failure
ERROR: the lab exited with code 3: no OpenGL 4.1 context
[  FAILED  ] Lab01.Ex01_4_SceneMatchesGolden (35 ms)
[==========] 2 tests from 1 test suite ran. (847 ms total)
[  FAILED  ] 1 test, listed below:
[  FAILED  ] Lab01.Ex01_4_SceneMatchesGolden
OUT
exit 1
EOF
cat >"$tmp/passing_tests" <<'EOF'
#!/usr/bin/env bash
[ "$1" = --update-golden ] || exit 99
printf '%s\n' "[ RUN      ] Lab01.Ex01_3_SceneMatchesGolden" "updated tests/golden/01_depth_map/ex01_3.pfm" \
  "[       OK ] Lab01.Ex01_3_SceneMatchesGolden (812 ms)" "[  PASSED  ] 1 test."
EOF
chmod +x "$tmp/failing_tests" "$tmp/passing_tests"

run() {  # BINARY: update_golden's output (stdout and stderr) in $out, its exit code in $code
  code=0
  out=$("$root/tools/authoring/update_golden.sh" "$1" "$tmp/golden.log" 2>&1) || code=$?
}

run "$tmp/failing_tests"
[ "$code" != 0 ] || fail "a failing regeneration exited 0"
for want in "tests/lab01_test.cpp:88: Failure" "ERROR: the lab exited with code 3: no OpenGL 4.1 context" \
            "[  FAILED  ] Lab01.Ex01_4_SceneMatchesGolden (35 ms)" "updated tests/golden/01_depth_map/ex01_3.pfm" \
            "regenerating the golden data failed"; do
  grep -qF -- "$want" <<<"$out" || fail "a failing regeneration does not show '$want'"
done
! grep -qF -- "[       OK ]" <<<"$out" || fail "a failing regeneration shows the tests that passed too"
[ -s "$tmp/golden.log" ] || fail "no log"

run "$tmp/passing_tests"
[ "$code" = 0 ] || fail "a passing regeneration exited $code: $out"
grep -qF "updated tests/golden/01_depth_map/ex01_3.pfm" <<<"$out" || fail "the updated file is not listed: $out"
grep -qF "updated 1 golden files" <<<"$out" || fail "no count of updated files: $out"

[ "$failures" = 0 ] && echo "workbook golden: every check passed" || exit 1
