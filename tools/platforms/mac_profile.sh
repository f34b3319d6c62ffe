#!/usr/bin/env bash
# A Mac's build and OpenGL, as near as Debian 12 comes (README, "Your own laptop"):
#   tools/platforms/mac_profile.sh [WORK]     (WORK: default build-mac-profile/)
# 1. clang with libc++, the Mac's compiler and standard library (libc++ is stricter about transitive
#    includes, as Apple's is), at -Wall -Wextra: the whole tree must build without one warning.
#    GoogleTest is built from Debian's sources with it (WB_GTEST_SOURCE_DIR): a libstdc++ build of
#    it cannot be linked.
# 2. Every lab's solution tests in a forward-compatible OpenGL 4.1 core context, what macOS gives
#    (MESA_GL_VERSION_OVERRIDE=4.1FC), and again without KHR_debug, which macOS lacks
#    (WB_GL_NO_KHR_DEBUG=1: Mesa cannot turn the extension off).
# It prints each step's time, and exits 1 naming what failed. What only a real Mac can show (Apple's
# clang and OpenGL-over-Metal, a Retina framebuffer, Homebrew's packages) it cannot.
set -uo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
WORK=$(mkdir -p "${1:-$ROOT/build-mac-profile}" && cd "${1:-$ROOT/build-mac-profile}" && pwd)
# shellcheck source=../workbook/packages.sh
source "$ROOT/tools/workbook/packages.sh"
failures=()
step() { echo "== mac_profile: $* ($(date +%T))"; }

step "packages"
install_packages "${PACKAGES[@]}" clang libc++-dev libc++abi-dev googletest || exit 1
[ -f /usr/src/googletest/CMakeLists.txt ] || { echo "mac_profile: no GoogleTest sources in /usr/src/googletest" >&2; exit 1; }

step "clang and libc++: configure and build everything"
t0=$(date +%s)
CC=clang CXX=clang++ cmake -S "$ROOT" -B "$WORK" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="-stdlib=libc++" -DCMAKE_EXE_LINKER_FLAGS="-stdlib=libc++" \
  -DWB_GTEST_SOURCE_DIR=/usr/src/googletest >"$WORK/configure.log" 2>&1 ||
  { tail -20 "$WORK/configure.log"; echo "mac_profile: configure failed ($WORK/configure.log)" >&2; exit 1; }
cmake --build "$WORK" -j "$(nproc)" >"$WORK/build.log" 2>&1 || failures+=("the build ($WORK/build.log)")
warnings=$(grep -c "warning:" "$WORK/build.log")
[ "$warnings" = 0 ] || failures+=("$warnings warnings ($WORK/build.log)")
grep -E "error:|warning:" "$WORK/build.log" | sort | uniq | head -20
echo "mac_profile: built in $(($(date +%s) - t0)) s, $warnings warnings"

run_solutions() {  # WHAT ENV...: every lab's solution tests, in that environment
  local what=$1 t0
  t0=$(date +%s)
  shift
  step "solution tests, $what"
  (cd "$WORK" && env "$@" ctest -L solution -j "$(nproc)" --output-on-failure >"$WORK/ctest-$what.log" 2>&1) ||
    failures+=("solution tests, $what ($WORK/ctest-$what.log)")
  grep -E "tests passed|tests failed" "$WORK/ctest-$what.log"
  echo "mac_profile: $(($(date +%s) - t0)) s"
}
run_solutions 4.1FC MESA_GL_VERSION_OVERRIDE=4.1FC MESA_GLSL_VERSION_OVERRIDE=410
run_solutions 4.1FC-no-KHR_debug MESA_GL_VERSION_OVERRIDE=4.1FC MESA_GLSL_VERSION_OVERRIDE=410 WB_GL_NO_KHR_DEBUG=1
grep -q "no KHR_debug here" "$WORK"/Testing/Temporary/LastTest.log ||
  failures+=("without KHR_debug, no test said that OpenGL errors are not reported")

for f in "${failures[@]}"; do echo "mac_profile: FAILED: $f"; done
[ ${#failures[@]} = 0 ] && echo "mac_profile: clang + libc++ warning-free; the solutions pass at 4.1FC, with and without KHR_debug"
[ ${#failures[@]} = 0 ]
