#!/usr/bin/env bash
# What a failing test shows as a picture, and check's page (WB_CHECK_HTML, ./workbook check NN --html):
#   - a wrong scene (02.1 without its bias: acne) leaves one PNG of three panels (reference, yours,
#     difference), under 100 KB, and check names it under 02.1;
#   - a wrong sweep (02.2 without its clamp) leaves a plot of the bias against cos θ, under 100 KB;
#   - the page holds every exercise's row, the hint, and the pictures inside it (data: URLs).
# Usage: check_pictures_test.sh BUILD_DIR
set -uo pipefail
build=${1:?usage: check_pictures_test.sh BUILD_DIR}
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
png_ok() {  # FILE: a PNG under 100 KB
  [ -f "$1" ] && [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] &&
    [ "$(stat -c %s "$1")" -lt 102400 ]
}
for case in bias_ignored:02.1:'*Ex02_1_Scene*':'Ex02.1_*/panels.png' \
            no_clamp:02.2:'*Ex02_2_*':'Ex02_2_bias_against_cos.png'; do
  IFS=: read -r mutant id filter picture <<<"$case"
  out="$build/test-output/check-pictures/$mutant" && rm -rf "$out" && mkdir -p "$out"
  WB_TEST_OUTPUT_DIR="$out" WB_SUBMISSION_DIR="$build/mutants/02_bias/$mutant" WB_CHECK_HTML="$out/report.html" \
    "$build/lab02_solution_tests" --check --gtest_filter="$filter" >"$out/check.log" 2>&1
  # shellcheck disable=SC2086,SC2012  # (the picture's name is a pattern; ls gives its first match)
  file=$(ls $out/$picture 2>/dev/null | head -1)
  if ! png_ok "$file"; then
    fail "$mutant: no picture $picture under 100 KB in $out: $(ls -la "$out")"
    continue
  fi
  before=$failures
  # (check shows a path under the checkout as a relative one)
  sed -n "/^  $id /,/^  [0-9]/p" "$out/check.log" | grep -q "picture: .*${file#"$out"/}" ||
    fail "$mutant: check does not show $file under $id: $(sed -n '/^Lab /,$p' "$out/check.log")"
  page="$out/report.html"
  rows=$(grep -c "<tr><td class=s>02\.[1-6]</td>" "$page" 2>/dev/null)
  [ "$rows" = 6 ] || fail "$mutant: the page has $rows rows of lab 02's six exercises"
  grep -q "<td class=\"s wrong\">wrong</td>" "$page" && grep -q "data:image/png;base64,iVBORw0KGgo" "$page" &&
    grep -q "looks like a known mistake" "$page" ||
    fail "$mutant: the page lacks the wrong verdict, the hint or the picture inside it"
  [ "$failures" = "$before" ] && echo "ok: $mutant ($id): $(basename "$file"), $(stat -c %s "$file") bytes, on the page"
done
exit "$failures"
