#!/usr/bin/env bash
# The Windows smoke test, run on Debian 12: cross-builds the framework and lab 01 with MinGW-w64,
# runs lab01 headless under Wine (whose OpenGL is the host's Mesa, through WGL), at Mesa's own
# version and capped at OpenGL 4.1 core, and compares both PNGs with a native Linux render.
#   tools/platforms/windows/cross_build.sh [WORK]      (WORK: default build-windows/; about 10 minutes the first
#                                             time on 2 cores, most of it Embree)
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

lab=lab01_solution; [ -d "$ROOT/solutions" ] || lab=lab01  # (the student edition has no solution)
step "the workbook's framework and $lab for Windows"
cmake -S "$ROOT" -B "$WORK/wb" "${TOOLCHAIN[@]}" -DWB_REGISTER_TESTS=OFF >"$WORK/wb-configure.log"
nice cmake --build "$WORK/wb" --target "$lab" -j"$JOBS" >"$WORK/wb-build.log"
step "$lab for Linux (the picture to compare with)"
cmake -S "$ROOT" -B "$WORK/linux" -DCMAKE_BUILD_TYPE=Release -DWB_REGISTER_TESTS=OFF >"$WORK/linux-configure.log"
nice cmake --build "$WORK/linux" --target "$lab" -j"$JOBS" >"$WORK/linux-build.log"

step "$lab.exe under Wine, headless (a hidden GLFW window), 480x270"
export WINEPREFIX=$WORK/wineprefix WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
args=(--headless --size 480x270 --frames 3)
"$WORK/linux/$lab" "${args[@]}" --screenshot "$WORK/linux.png" >/dev/null
status=0
for cap in "" 4.1; do
  png=$WORK/wine${cap:+-gl$cap}.png
  rm -f "$png"
  env ${cap:+MESA_GL_VERSION_OVERRIDE=$cap MESA_GLSL_VERSION_OVERRIDE=410} timeout 300 \
    xvfb-run -a -s "-screen 0 1280x800x24" /usr/lib/wine/wine64 "$WORK/wb/$lab.exe" "${args[@]}" \
    --screenshot "Z:$png" --record "Z:$png.json" >"$png.log" 2>&1 || true
  /usr/lib/wine/wineserver64 -k 2>/dev/null || true
  if [ ! -f "$png" ]; then
    echo "cross_build: the Wine run${cap:+ capped at $cap} wrote no picture; its output:"; cat "$png.log"; status=1
    continue
  fi
  echo "Wine${cap:+ capped at OpenGL $cap}: $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["gl_version"])' "$png.json")"
  python3 "$HERE/compare_png.py" "$png" "$WORK/linux.png" | tee "$png.compare"
  grep -q "pixels differing by > 2/255 in any channel: 0 of" "$png.compare" || status=1
done
[ "$status" = 0 ] && echo "cross_build: $lab.exe runs under Wine and draws the Linux picture, pixel for pixel"
exit "$status"
