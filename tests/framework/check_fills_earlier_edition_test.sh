#!/usr/bin/env bash
# check in the student edition, on a lab 01 file written before its bug hunt 01.H1 was added: the
# hunt's stub is put into the file from tests/stubs/ (as the grader grades it), with one line that
# says so, and nothing else of the file changes; a second check adds nothing. The build's own step
# (cmake/FillFromStubs.cmake, for check_NN where there is no ./workbook) does the same.
# Usage: check_fills_earlier_edition_test.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: check_fills_earlier_edition_test.sh BUILD_DIR}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=$(mktemp -d) && trap 'rm -rf "$tmp"' EXIT
name=01_depth_map
mkdir -p "$tmp/labs/$name" "$tmp/tests/stubs/$name" "$tmp/build"
cp "$root/labs/$name/exercise.cpp" "$tmp/tests/stubs/$name/"
ln -s "$build/wb_check" "$tmp/build/wb_check"
# The solution as it was before 01.H1: its chunk gone, the namespace's end kept.
/usr/bin/python3 - "$root/solutions/$name/exercise.cpp" "$tmp/labs/$name/exercise.cpp" <<'PY'
import sys
text = open(sys.argv[1]).read()
at, end = text.index("// EXERCISE 01.H1"), text.rindex("}  // namespace")
open(sys.argv[2], "w").write(text[:at] + text[end:])
PY
cp "$tmp/labs/$name/exercise.cpp" "$tmp/before.cpp"
# shellcheck source=tools/workbook/build.sh
source "$root/tools/workbook/build.sh"
out=$(cd "$tmp" && fill_from_stubs "$name")
fail() { echo "FAIL: $*"; exit 1; }
[ "$(grep -c . <<<"$out")" = 1 ] || fail "want one line, got: $out"
grep -q "labs/$name/exercise.cpp predates exercise 01.H1" <<<"$out" || fail "the line does not say what predates what: $out"
grep -q "tests/stubs/$name/exercise.cpp" <<<"$out" || fail "the line does not say where the stub is: $out"
grep -q "// EXERCISE 01.H1" "$tmp/labs/$name/exercise.cpp" || fail "01.H1's stub was not put into the file"
# Nothing of the student's was lost or changed: the difference only adds lines.
! diff "$tmp/before.cpp" "$tmp/labs/$name/exercise.cpp" | grep -q '^<' || fail "the student's own lines changed"
again=$(cd "$tmp" && fill_from_stubs "$name")
[ -z "$again" ] || fail "a second check added more: $again"
# The build's step, on the file as it was: the same line, the same file.
filled="$tmp/labs/$name/exercise.cpp" && cp "$filled" "$tmp/filled.cpp" && cp "$tmp/before.cpp" "$filled"
step=$(cmake -DWB_CHECK="$build/wb_check" -DSTUBS="$tmp/tests/stubs/$name" -DLAB_DIR="$tmp/labs/$name" -DLAB="$name" \
  -P "$root/cmake/FillFromStubs.cmake")
[ "$step" = "$out" ] || fail "the build's step says '$step', check says '$out'"
cmp -s "$filled" "$tmp/filled.cpp" || fail "the build's step fills the file otherwise than check"
echo "ok: $out"
