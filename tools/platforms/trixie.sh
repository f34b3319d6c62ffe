#!/usr/bin/env bash
# The newest dependencies Debian has, built and run: the whole suite in a Debian 13 (trixie) root
#   tools/platforms/trixie.sh [ROOT]     (as root; ROOT: default build/trixie/root, made once)
# Trixie's packages are near what Ubuntu 24.04 and Homebrew give students (GCC 14, CMake 3.31,
# GLFW 3.4, Embree 4, GoogleTest 1.16, ImGui 1.90): the root is made with debootstrap from the mirror
# apt uses, the committed tree is cloned in (with git, as CI's clone), `./workbook setup` installs the
# packages there and `./workbook test` runs the suite, the ray-traced truth on Embree 4 included. It
# prints the versions it built with, each step's time and the suite's result; the logs stay in
# ROOT/../ (setup.log, test.log). A command of its own: CI does not run it (about an hour on 2 cores).
set -euo pipefail
die() { echo "trixie: $*" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
root=$(realpath -m "${1:-$here/build/trixie/root}")
[ "$(id -u)" = 0 ] || die "run it as root: it makes a chroot"
# shellcheck source=../grading/sim_lib.sh
# shellcheck disable=SC1091  # (not found in the student edition, which has no tools/grading and cannot run this)
source "$here/tools/grading/sim_lib.sh"
logs=$(dirname "$root")
t0=$(date +%s)
sim_make_root trixie
echo "trixie: the root is ready ($(($(date +%s) - t0)) s)"

rm -rf "$root/work/workbook" && mkdir -p "$root/work"
git clone -q --no-hardlinks "$here" "$root/work/workbook"  # (a clone, as CI's: the export tests need git)
[ ! -d "$here/../shared" ] || { rm -rf "$root/work/shared" && cp -r "$here/../shared" "$root/work/shared"; }

t0=$(date +%s)
chroot "$root" /bin/bash -c 'cd /work/workbook && apt-get update -qq && apt-get install -y -qq git >/dev/null &&
  bash ./workbook setup' >"$logs/setup.log" 2>&1 ||
  { tail -20 "$logs/setup.log"; die "./workbook setup failed in trixie ($logs/setup.log)"; }
echo "trixie: ./workbook setup took $(($(date +%s) - t0)) s"
# shellcheck disable=SC2016  # (dpkg-query's own format, not the shell's)
chroot "$root" dpkg-query -W -f='  ${Package} ${Version}\n' g++ cmake libglfw3-dev libembree-dev libgtest-dev \
  libimgui-dev libglm-dev nlohmann-json3-dev libgl1-mesa-dri 2>/dev/null || true

t0=$(date +%s)
code=0
chroot "$root" /bin/bash -c 'cd /work/workbook && ./workbook test' >"$logs/test.log" 2>&1 || code=$?
echo "trixie: ./workbook test took $(($(date +%s) - t0)) s and exited $code"
grep -E "tests passed|tests failed|The following tests FAILED" -A30 "$logs/test.log" | head -40
grep -qi "embree" "$root/work/workbook/build-ci/CMakeCache.txt" 2>/dev/null &&
  grep -m1 -E "^embree_DIR" "$root/work/workbook/build-ci/CMakeCache.txt" | sed 's/^/trixie: /'
exit "$code"
