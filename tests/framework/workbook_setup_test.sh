#!/usr/bin/env bash
# ./workbook on a machine without apt (no dpkg-query, no apt-get on PATH): it checks for the
# dependencies themselves, goes on when they are all there, and names exactly what is missing (exit 1)
# when they are not; glad 1 is not taken for glad 2; with apt, a package name apt does not know is
# named. Usage: workbook_setup_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: workbook_setup_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp"
bash=$(command -v bash)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

tools() {  # DIR TOOL...: DIR holds links to these tools of this machine, and nothing else
  local dir=$1 t p
  shift
  mkdir -p "$dir"
  for t in "$@"; do
    if p=$(command -v "$t"); then ln -s "$p" "$dir/$t"; fi
  done
}
base=(dirname nproc grep sed cat)  # what the script itself uses
[ -n "$(command -v g++ || command -v c++)" ] || { echo "FAIL: this machine has no C++ compiler"; exit 1; }

# 1. Every dependency is there, apt is not: one line says so, and setup succeeds.
tools "$tmp/all" "${base[@]}" cmake make pkg-config c++ g++ cc gcc
for t in dpkg-query apt-get; do [ ! -e "$tmp/all/$t" ] || fail "$t is on the test PATH"; done
if out=$(PATH="$tmp/all" "$bash" "$root/workbook" setup 2>&1); then
  grep -q "^workbook: apt-get is not available on this machine, but the dependencies were found" <<<"$out" ||
    fail "setup without apt did not say the dependencies were found: $out"
  grep -q "every dependency is installed" <<<"$out" || fail "setup without apt did not finish: $out"
else
  fail "setup without apt failed although every dependency is here: $out"
fi

# 2. cmake is missing and pkg-config cannot find imgui: exit 1, naming those two and nothing else.
tools "$tmp/some" "${base[@]}" make c++ g++ cc gcc
cat >"$tmp/some/pkg-config" <<EOF
#!$bash
for a in "\$@"; do [ "\$a" != imgui ] || exit 1; done
exec $(command -v pkg-config) "\$@"
EOF
chmod +x "$tmp/some/pkg-config"
if out=$(PATH="$tmp/some" "$bash" "$root/workbook" setup 2>&1); then
  fail "setup without apt succeeded with cmake and imgui missing: $out"
else
  code=$?
  [ "$code" = 1 ] || fail "setup without apt exited $code with dependencies missing, expected 1"
  listed=$(grep '^  ' <<<"$out" || true)
  want=$'  cmake (no cmake command)\n  libimgui-dev (pkg-config finds no imgui)'
  [ "$listed" = "$want" ] || fail "the missing dependencies are listed as:
$listed
expected:
$want"
  grep -q "apt-get is not available on this machine, and these dependencies are missing" <<<"$out" ||
    fail "the message does not say why: $out"
fi

# 3. With apt, a package this system's apt does not know (names differ between Debian and Ubuntu):
# exit 1, naming it (fake dpkg-query, apt-get, apt-cache and sudo stand in for the real ones).
tools "$tmp/apt" "${base[@]}" id
fake() {  # NAME BODY
  printf '#!%s\n%s\n' "$bash" "$2" >"$tmp/apt/$1"
  chmod +x "$tmp/apt/$1"
}
fake dpkg-query 'exit 1'  # nothing is installed
# shellcheck disable=SC2016  # (the fakes' bodies: they expand when the fakes run)
fake apt-get '[ "$1" = update ] && exit 0; echo "E: Unable to locate package libimgui-dev" >&2; exit 100'
# shellcheck disable=SC2016  # (likewise)
fake apt-cache '[ "$2" = libimgui-dev ] && exit 100; exit 0'
fake sudo 'exec "$@"'
if out=$(PATH="$tmp/apt" "$bash" "$root/workbook" setup 2>&1); then
  fail "setup succeeded although apt-get failed: $out"
else
  code=$?
  [ "$code" = 1 ] || fail "setup exited $code when apt-get failed, expected 1"
  grep -q "this system has no package named libimgui-dev" <<<"$out" ||
    fail "setup does not name the package apt does not know: $out"
fi

[ "$failures" = 0 ] && echo "workbook setup without apt: every check passed" || exit 1
