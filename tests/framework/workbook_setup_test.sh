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

# 3. The glad check: glad 2 passes; glad 1 (it has --api, but --generator instead of the c command)
# and a Python without glad do not. Fake interpreters answer `-m glad ...` as those would.
fake_python() {  # NAME TOP_USAGE C_USAGE: answers `-m glad --help` and `-m glad c --help` ("fail": exit 1)
  cat >"$tmp/$1" <<EOF
#!$bash
[ "\$1 \$2" = "-m glad" ] || exit 1
if [ "\${3:-}" = c ]; then usage='$3'; else usage='$2'; fi
[ "\$usage" != fail ] || { echo "No module named glad" >&2; exit 1; }
echo "\$usage"
EOF
  chmod +x "$tmp/$1"
}
fake_python glad2 "usage: __main__.py [-h] --api API [--extensions EXTENSIONS] [--merge] --out-path OUT_PATH {c,rust} ..." \
  "usage: __main__.py c [-h] [--alias] [--debug] [--header-only] [--loader] [--mx] [--on-demand]"
glad1_usage="usage: __main__.py [-h] [--profile {core,compatibility}] --out-path OUT [--api API] --generator {c,c-debug,d,nim,pascal,volt} [--extensions EXTENSIONS] [--spec {gl,egl,glx,wgl}] [--no-loader] [--omit-khrplatform] [--local-files]"
fake_python glad1 "$glad1_usage" "$glad1_usage"
fake_python noglad fail fail
(
  # shellcheck source=../../workbook
  source "$root/workbook"
  set +e
  is_glad2 "$tmp/glad2" || echo "FAIL: glad 2 was not recognised"
  ! is_glad2 "$tmp/glad1" || echo "FAIL: glad 1 was taken for glad 2"
  ! is_glad2 "$tmp/noglad" || echo "FAIL: a Python without glad was taken for glad 2"
  is_glad2 "$(glad_python)" || echo "FAIL: $(glad_python), which the build uses, has no glad 2"
) >"$tmp/glad.out" 2>&1 || fail "sourcing the workbook failed: $(cat "$tmp/glad.out")"
while IFS= read -r line; do fail "${line#FAIL: }"; done < <(grep '^FAIL' "$tmp/glad.out" || true)

# 4. With apt, a package this system's apt does not know (names differ between Debian and Ubuntu):
# exit 1, naming it (fake dpkg-query, apt-get, apt-cache and sudo stand in for the real ones).
tools "$tmp/apt" "${base[@]}" id
fake() {  # NAME BODY
  printf '#!%s\n%s\n' "$bash" "$2" >"$tmp/apt/$1"
  chmod +x "$tmp/apt/$1"
}
fake dpkg-query 'exit 1'  # nothing is installed
fake apt-get '[ "$1" = update ] && exit 0; echo "E: Unable to locate package libimgui-dev" >&2; exit 100'
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
