#!/usr/bin/env bash
# Windows, as far as Debian 12 can show it: cross-builds every lab (its app, its solution, both test
# binaries) and wb_check with MinGW-w64; runs every lab's solution headless under Wine (whose OpenGL
# is the host's Mesa, through WGL), capped at OpenGL 4.1 core, and compares each picture with the
# Linux render; then runs check (wb_check.exe) under Wine on the check cases of a C++ lab and a
# GLSL-only lab (tests/check_cases/: a mutant, an endless loop, a crash or compile error) and compares
# every exercise's verdict with Linux's wb_check on the same case.
#   tools/platforms/windows/cross_build.sh [WORK]      (WORK: default build-windows/; the first time,
#                                             about 10 minutes of dependencies, most of it Embree)
#   WB_CROSS_CHECK_ONLY=1 ...: after a full run, rebuild wb_check alone and run the check cases again
#   WB_CROSS_LABS="11" ...: that lab's builds and pictures, with labs 01 and 03 (the check cases need them)
# The dependencies come from Debian's source packages (apt-get source: a deb-src line is added):
# GLFW 3.3.8, Dear ImGui 1.86, GoogleTest 1.12.1 and Embree 3.13.5 (SSE2, triangles, internal
# tasking; three CMake-only fixes for MinGW in embree-3.13.5-mingw.patch), built static.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
HERE=$ROOT/tools/platforms/windows
WORK=$(mkdir -p "${1:-$ROOT/build-windows}" && cd "${1:-$ROOT/build-windows}" && pwd)
export WB_WIN_PREFIX=$WORK/prefix
TOOLCHAIN=(-DCMAKE_TOOLCHAIN_FILE="$HERE/mingw-toolchain.cmake" -DCMAKE_BUILD_TYPE=Release
  -DCMAKE_INSTALL_PREFIX="$WB_WIN_PREFIX")
JOBS=$(nproc 2>/dev/null || echo 2)
SUDO=""; [ "$(id -u)" = 0 ] || SUDO=sudo
step() { echo "== cross_build: $*"; }

step "packages"
# shellcheck source=../../workbook/packages.sh
source "$ROOT/tools/workbook/packages.sh"  # (apt_mirror)
if ! grep -rqs "^Types: deb-src" /etc/apt/sources.list.d/ && ! grep -qs "^deb-src" /etc/apt/sources.list; then
  mirror=$(apt_mirror) || true
  [ -n "$mirror" ] || { echo "cross_build: apt names no Debian mirror to take the sources from" >&2; exit 1; }
  suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$mirror" "$suite" | $SUDO tee /etc/apt/sources.list.d/wb-debsrc.sources >/dev/null
  $SUDO apt-get update -qq
fi
need=(g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64 mingw-w64-x86-64-dev
  wine64 xvfb xauth dpkg-dev cmake pkg-config libglm-dev libstb-dev nlohmann-json3-dev)
missing=(); for p in "${need[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
[ ${#missing[@]} = 0 ] || $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"

step "sources (apt-get source)"
mkdir -p "$WORK/src" && cd "$WORK/src"
[ -d glfw3-3.3.8 ] || apt-get source -qq glfw3
[ -d imgui-1.86+ds ] || apt-get source -qq imgui
[ -d googletest-1.12.1 ] || apt-get source -qq googletest
if [ ! -d embree-3.13.5 ]; then  # (the mirror lacks its debian.tar.xz: the orig tarball, checked, is enough)
  [ -f embree_3.13.5+dfsg.orig.tar.xz ] || apt-get source -qq --download-only embree || true
  echo "a80c545520e1e3916c581195f2b21579  embree_3.13.5+dfsg.orig.tar.xz" | md5sum -c --quiet -
  mkdir embree-3.13.5 && tar -xf embree_3.13.5+dfsg.orig.tar.xz -C embree-3.13.5 --strip-components=1
  patch -s -d embree-3.13.5 -p1 <"$HERE/embree-3.13.5-mingw.patch"
fi

build() {  # NAME SOURCE [CMAKE ARGS...]: configure, build and install one dependency, once
  local name=$1 src=$2; shift 2
  [ -f "$WORK/deps/$name.done" ] && return 0
  step "$name"
  cmake -S "$src" -B "$WORK/deps/$name" "${TOOLCHAIN[@]}" "$@" >"$WORK/deps-$name.log"
  nice cmake --build "$WORK/deps/$name" -j"$JOBS" >>"$WORK/deps-$name.log"
  cmake --install "$WORK/deps/$name" >>"$WORK/deps-$name.log"
  touch "$WORK/deps/$name.done"
}
build glfw "$WORK/src/glfw3-3.3.8" -DBUILD_SHARED_LIBS=OFF -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF \
  -DGLFW_BUILD_DOCS=OFF
build imgui "$HERE/imgui" -DIMGUI_SRC="$WORK/src/imgui-1.86+ds" -DIMGUI_VERSION=1.86
build gtest "$WORK/src/googletest-1.12.1" -DBUILD_SHARED_LIBS=OFF
build embree "$WORK/src/embree-3.13.5" -DEMBREE_TASKING_SYSTEM=INTERNAL -DEMBREE_ISPC_SUPPORT=OFF \
  -DEMBREE_TUTORIALS=OFF -DEMBREE_STATIC_LIB=ON -DEMBREE_MAX_ISA=SSE2 -DEMBREE_GEOMETRY_TRIANGLE=ON \
  -DEMBREE_GEOMETRY_QUAD=OFF -DEMBREE_GEOMETRY_CURVE=OFF -DEMBREE_GEOMETRY_SUBDIVISION=OFF \
  -DEMBREE_GEOMETRY_USER=OFF -DEMBREE_GEOMETRY_INSTANCE=OFF -DEMBREE_GEOMETRY_GRID=OFF \
  -DEMBREE_GEOMETRY_POINT=OFF -DEMBREE_FILTER_FUNCTION=ON -DEMBREE_RAY_MASK=OFF -DEMBREE_RAY_PACKETS=OFF \
  -DBUILD_TESTING=OFF -DEMBREE_ZIP_MODE=OFF
step "header-only libraries (GLM, stb, nlohmann-json, from Debian)"
mkdir -p "$WB_WIN_PREFIX/include" "$WB_WIN_PREFIX/share/cmake"
cp -r /usr/include/glm /usr/include/stb /usr/include/nlohmann "$WB_WIN_PREFIX/include/"
cp -r /usr/share/cmake/glm /usr/share/cmake/nlohmann_json "$WB_WIN_PREFIX/share/cmake/"

[ -d "$ROOT/solutions" ] || { echo "cross_build: the instructor edition is needed (solutions and check cases)" >&2; exit 1; }
case_labs=(01 03)  # (a lab with C++ exercises, and one whose exercises are all GLSL)
# (WB_CROSS_LABS="11": that lab's builds and pictures, and the check cases' labs, whose runs need theirs)
labs=(); for d in "$ROOT"/labs/[0-9][0-9]_*/; do
  nn=$(basename "$d" | cut -c1-2)
  [ -z "${WB_CROSS_LABS:-}" ] || [[ " $WB_CROSS_LABS ${case_labs[*]} " == *" $nn "* ]] && labs+=("$(basename "$d")")
done
cases=(); for nn in "${case_labs[@]}"; do
  for f in "$ROOT"/tests/check_cases/"$nn"_*/*.case; do cases+=("$nn:$(basename "$f" .case)"); done
done
targets=(wb_check); linux_targets=(wb_check)
for lab in "${labs[@]}"; do
  nn=${lab:0:2}
  targets+=("lab$nn" "lab${nn}_solution" "lab${nn}_tests" "lab${nn}_solution_tests")
  linux_targets+=("lab${nn}_solution")
done
for nn in "${case_labs[@]}"; do linux_targets+=("lab${nn}_solution_tests"); done
for c in "${cases[@]}"; do  # (a C++ case has a build of its own; a GLSL case only its folder)
  for f in "$ROOT/tests/check_cases/${c%%:*}"_*/"${c#*:}.case"; do  # (one lab folder: NN_name)
    [ -f "$f" ] && grep -q "^file: exercise.cpp" "$f" &&
      targets+=("lab${c%%:*}_mutant_${c#*:}_tests") linux_targets+=("lab${c%%:*}_mutant_${c#*:}_tests")
  done
done
if [ "${WB_CROSS_CHECK_ONLY:-0}" = 1 ]; then  # (the builds as they are, and wb_check anew: the check cases only)
  targets=(wb_check) linux_targets=(wb_check)
fi
step "the workbook for Windows: ${#targets[@]} targets (every lab, its solution and both test binaries)"
cmake -S "$ROOT" -B "$WORK/wb" "${TOOLCHAIN[@]}" -DWB_REGISTER_TESTS=OFF >"$WORK/wb-configure.log"
nice cmake --build "$WORK/wb" --target "${targets[@]}" -j"$JOBS" -- -k >"$WORK/wb-build.log" 2>&1 ||
  { tail -30 "$WORK/wb-build.log"; exit 1; }
echo "warnings in the Windows build: $(grep -c "warning:" "$WORK/wb-build.log")"
step "the same for Linux (the pictures and verdicts to compare with)"
cmake -S "$ROOT" -B "$WORK/linux" -DCMAKE_BUILD_TYPE=Release -DWB_REGISTER_TESTS=OFF >"$WORK/linux-configure.log"
nice cmake --build "$WORK/linux" --target "${linux_targets[@]}" -j"$JOBS" >"$WORK/linux-build.log" 2>&1 ||
  { tail -30 "$WORK/linux-build.log"; exit 1; }

export WINEPREFIX=$WORK/wineprefix WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
# (both sides at 4.1 core; not 4.1FC, which Linux's suite runs: under Wine, Mesa's forward-compatible
# override hangs at the first context, before the workbook's code draws anything)
export MESA_GL_VERSION_OVERRIDE=4.1 MESA_GLSL_VERSION_OVERRIDE=410
status=0
step "every solution under Wine, headless (a hidden GLFW window), 480x270, against the Linux render"
[ "${WB_CROSS_CHECK_ONLY:-0}" = 1 ] && labs_drawn=() || labs_drawn=("${labs[@]}")
for lab in "${labs_drawn[@]}"; do
  nn=${lab:0:2} png=$WORK/pictures/lab$nn
  mkdir -p "$WORK/pictures" && rm -f "$png"-*.png
  args=(--headless --size 480x270 --frames 3)
  "$WORK/linux/lab${nn}_solution" "${args[@]}" --screenshot "$png-linux.png" >"$png-linux.log" 2>&1
  timeout 300 xvfb-run -a -s "-screen 0 1280x800x24" /usr/lib/wine/wine64 "$WORK/wb/lab${nn}_solution.exe" \
    "${args[@]}" --screenshot "Z:$png-wine.png" >"$png-wine.log" 2>&1 || true
  /usr/lib/wine/wineserver64 -k 2>/dev/null || true
  if [ ! -f "$png-wine.png" ]; then
    echo "lab $nn: the Wine run wrote no picture: $(tail -3 "$png-wine.log")"; status=1; continue
  fi
  python3 "$HERE/compare_png.py" "$png-wine.png" "$png-linux.png" >"$png.compare"
  echo "lab $nn: $(grep "pixels differing" "$png.compare")"
  # (an edge pixel may flip: MinGW's maths library rounds a light's matrix apart from glibc's in the
  # last bit; at most 0.01% of the pixels, 12 of 129600)
  differing=$(sed -n 's/^pixels differing by > 2\/255 in any channel: \([0-9]*\) of.*/\1/p' "$png.compare")
  [ -n "$differing" ] && [ "$differing" -le 12 ] || status=1
done

step "check under Wine (wb_check.exe) and on Linux, on every check case of labs ${case_labs[*]}"
# (the same limits on both sides, wider than a laptop's 8 s: under Wine each lab run starts a Wine
# process and a GL context, seconds that Windows itself does not spend)
export WB_CHECK_TIMEOUT=30
verdicts() { sed -n 's/^  \([0-9][0-9]\.[0-9xH]*\)  \(passes its tests\|passes own tests\|not implemented\|wrong\|error\) .*/\1 \2/p' "$1"; }
for c in "${cases[@]}"; do
  nn=${c%%:*} name=${c#*:} lab=""
  for l in "${labs[@]}"; do [ "${l:0:2}" = "$nn" ] && lab=$l; done
  tests=lab${nn}_solution_tests; [ -x "$WORK/linux/lab${nn}_mutant_${name}_tests" ] && tests=lab${nn}_mutant_${name}_tests
  out=$WORK/check/$nn-$name && rm -rf "$out" && mkdir -p "$out"
  "$WORK/linux/wb_check" "$nn" --root "$ROOT" --tests "$WORK/linux/$tests" --judge "$WORK/linux/lab${nn}_solution_tests" \
    --submission "$WORK/linux/mutants/$lab/$name" --tape "$out/linux-tape" >"$out/linux.txt" 2>&1 || true  # (1: a case fails)
  start=$(date +%s)
  timeout 600 xvfb-run -a -s "-screen 0 1280x800x24" /usr/lib/wine/wine64 "$WORK/wb/wb_check.exe" "$nn" --root "Z:$ROOT" \
    --tests "Z:$WORK/wb/$tests.exe" --judge "Z:$WORK/wb/lab${nn}_solution_tests.exe" \
    --submission "Z:$WORK/wb/mutants/$lab/$name" --tape "Z:$out/wine-tape" >"$out/wine.txt" 2>&1 || true
  /usr/lib/wine/wineserver64 -k 2>/dev/null || true
  if [ -n "$(verdicts "$out/linux.txt")" ] && [ "$(verdicts "$out/linux.txt")" = "$(verdicts "$out/wine.txt")" ]; then
    echo "lab $nn $name: the same verdicts ($(( $(date +%s) - start )) s under Wine): $(verdicts "$out/wine.txt" | tr '\n' ';')"
  else
    echo "lab $nn $name: the verdicts differ: Linux: $(verdicts "$out/linux.txt" | tr '\n' ';') Wine: $(verdicts "$out/wine.txt" | tr '\n' ';')"
    status=1
  fi
done
[ "$status" = 0 ] && echo "cross_build: every lab draws the Linux picture under Wine, and check gives Linux's verdicts"
exit "$status"
