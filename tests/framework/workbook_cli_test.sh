#!/usr/bin/env bash
# The workbook's command line, without building anything: in a scratch copy of the checkout, a fake
# cmake builds nothing and a fake build/lab03 prints the arguments it was given. Holds:
#   - `run 3` is lab 03, and without a display it renders headlessly to build/renders/lab03.png;
#   - `run 03 --help` passes --help alone, and says nothing about rendering headlessly;
#   - a malformed or unknown lab number gets one line and exit code 2, and so does an unknown option of check;
#   - `docs` works in a tree without build/, Doxygen warns about nothing, and its main page is the
#     README with links to the handouts (skipped without doxygen).
# Usage: workbook_cli_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: workbook_cli_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp/bin"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The scratch tree: the tracked files, a configured-looking build/ and a lab that echoes its arguments.
# It lies outside any build folder: the Doxyfile leaves out every path with a "/build" in it.
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then  # the tracked files
  (cd "$root" && git ls-files -z | tar --null -T - -cf -) | tar -xf - -C "$tree" --exclude='tests/golden/*' \
    --exclude='*/images/*'
else  # the student edition, exported without git: the tree less its build folders
  (cd "$root" && tar --exclude='./build*' --exclude='./tests/golden/*' --exclude='*/images/*' -cf - .) | tar -xf - -C "$tree"
fi
mkdir -p "$tree/build"
touch "$tree/build/CMakeCache.txt"
printf '#!/usr/bin/env bash\necho "lab03 got: $*"\n' >"$tree/build/lab03"
printf '#!/usr/bin/env bash\nexit 0\n' >"$tmp/bin/cmake"
chmod +x "$tree/build/lab03" "$tmp/bin/cmake"

wb() {  # ARGS: the workbook's output (stdout and stderr) in $out, its exit code in $code
  code=0
  out=$(cd "$tree" && env -u DISPLAY -u WAYLAND_DISPLAY PATH="$tmp/bin:$PATH" WB_NO_APT=1 ./workbook "$@" 2>&1) ||
    code=$?
}

wb run 3
[ "$code" = 0 ] || fail "run 3 exited $code: $out"
grep -qx "lab03 got: --headless --screenshot build/renders/lab03.png" <<<"$out" ||
  fail "run 3 without a display did not render lab 03 headlessly to build/renders/lab03.png: $out"

wb run 03 --help
[ "$code" = 0 ] || fail "run 03 --help exited $code: $out"
grep -qx "lab03 got: --help" <<<"$out" || fail "run 03 --help did not pass --help alone: $out"
if grep -qi "headless" <<<"$out"; then fail "run 03 --help talks about rendering headlessly: $out"; fi

wb run 3 --list-settings
grep -qx "lab03 got: --list-settings" <<<"$out" || fail "run 3 --list-settings was changed: $out"

for bad in 3x 123 abc; do
  wb run "$bad"
  [ "$code" = 2 ] || fail "run $bad exited $code, expected 2: $out"
  grep -q "expected a two-digit lab number" <<<"$out" || fail "run $bad did not say what a lab number is: $out"
done
wb run 42
[ "$code" = 2 ] && grep -q "there is no lab 42; the labs are: 01_depth_map" <<<"$out" ||
  fail "run 42 did not name the labs there are (exit $code): $out"
wb run
[ "$code" = 2 ] && grep -q "usage: ./workbook run NN" <<<"$out" || fail "run without a number (exit $code): $out"
wb check 03 --htm
[ "$code" = 2 ] && grep -q "check: unknown option '--htm' (usage: ./workbook check NN \[--watch\] \[--html\])" <<<"$out" ||
  fail "check with an unknown option (exit $code): $out"

if command -v doxygen >/dev/null; then
  rm -rf "$tree/build"
  wb docs
  [ "$code" = 0 ] || fail "docs failed in a tree without build/ (exit $code): $out"
  [ -f "$tree/build/docs/html/index.html" ] || fail "docs wrote no build/docs/html/index.html: $out"
  if grep -qi "warning" <<<"$out"; then fail "Doxygen warns: $(grep -i warning <<<"$out")"; fi
  # Students land on the main page: the README, with each lab's handout one click away. (Doxygen
  # names a Markdown page after its path, escaped its own way: md_labs_01_depth_map_README.html in
  # 1.9.4, md_labs_201__depth__map_2README.html in 1.9.8.)
  index=$tree/build/docs/html/index.html
  grep -q "Shadow Lab Workbook" "$index" && grep -qE 'href="md_labs_?[0-9_]*01_+depth_+map_[^"]*\.html"' "$index" ||
    fail "the docs' main page is not the README with links to the handouts"
  compgen -G "$tree/build/docs/html/md_labs*10_*cascades*.html" >/dev/null || fail "the docs have no page for lab 10's handout"
else
  echo "(doxygen is not installed: ./workbook docs is not tried)"
fi

[ "$failures" = 0 ] && echo "workbook command line: all good" || exit 1
