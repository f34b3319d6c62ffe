# Sourced by ./workbook: the Debian packages the workbook needs, and installing them (apt-get, as
# root or through sudo) or, without apt, checking for them and naming what is missing.
# shellcheck shell=bash
# Debian 12 packages the build and the tests need (doxygen only for `docs`).
# shellcheck disable=SC2034  # (PACKAGES and TEST_PACKAGES are used by the scripts that source this file)
PACKAGES=(cmake g++ make pkg-config python3 libglfw3-dev libglm-dev libimgui-dev libstb-dev libembree-dev
  libgtest-dev nlohmann-json3-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri fonts-dejavu-core)
# And what ./workbook test (so CI, .ci/run) adds: doxygen builds the reference once, for warnings; xvfb,
# xauth and xdotool drive a real window for the presenter-keys test; bubblewrap is the grader's
# sandbox; python3-glad checks the committed loader; ffmpeg makes the lecture clips; the linters of
# CONTRIBUTING.md (tools/authoring/lint.py) are clang-format, shellcheck and python3-pyflakes.
# Every test that needs one of these skips without it.
# shellcheck disable=SC2034
TEST_PACKAGES=(doxygen xvfb xauth xdotool bubblewrap python3-glad ffmpeg clang-format shellcheck python3-pyflakes)

missing_packages() {
  local missing=()
  for p in "$@"; do
    [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" == *"install ok installed"* ]] || missing+=("$p")
  done
  echo "${missing[@]:-}"
}

has_pc() { command -v pkg-config >/dev/null 2>&1 && pkg-config --exists "$1"; }

has_headers() {  # HEADER...: the C++ compiler finds them (CMake's find_package has the last word)
  local cxx=${CXX:-c++} h
  command -v "$cxx" >/dev/null 2>&1 || cxx=g++
  for h in "$@"; do
    printf '#include <%s>\n' "$h"
  done | "$cxx" -x c++ -std=c++17 -E -o /dev/null - >/dev/null 2>&1
}

# What is missing of the Debian packages $@, checked without dpkg (for machines without apt): one
# "package (what was not found)" per line. Mesa's EGL and llvmpipe drivers are not checked: a lab
# that finds no OpenGL 4.1 context says so when it starts (exit code 3).
missing_without_apt() {
  local p why
  for p in "$@"; do
    why=""
    case "$p" in
      cmake|make|pkg-config|doxygen) command -v "$p" >/dev/null 2>&1 || why="no $p command" ;;
      gnuplot-nox) command -v gnuplot >/dev/null 2>&1 || why="no gnuplot command" ;;
      g++)
        command -v "${CXX:-c++}" >/dev/null 2>&1 || command -v g++ >/dev/null 2>&1 || why="no C++ compiler (c++ or g++)"
        command -v "${CC:-cc}" >/dev/null 2>&1 || command -v gcc >/dev/null 2>&1 || why="${why:+$why, }no C compiler (cc or gcc)" ;;
      python3) [ -x /usr/bin/python3 ] || command -v python3 >/dev/null 2>&1 || why="no /usr/bin/python3 and no python3 command" ;;
      libglfw3-dev) has_pc glfw3 || why="pkg-config finds no glfw3" ;;
      libimgui-dev) has_pc imgui || why="pkg-config finds no imgui" ;;
      libstb-dev) has_pc stb || why="pkg-config finds no stb" ;;
      libegl-dev) has_pc egl || why="pkg-config finds no egl" ;;
      libgl-dev) has_pc gl || why="pkg-config finds no gl" ;;
      libglm-dev) has_headers glm/glm.hpp || why="no <glm/glm.hpp>" ;;
      nlohmann-json3-dev) has_headers nlohmann/json.hpp || why="no <nlohmann/json.hpp>" ;;
      libgtest-dev) has_headers gtest/gtest.h || why="no <gtest/gtest.h>" ;;
      libembree-dev) has_headers embree3/rtcore.h || has_headers embree4/rtcore.h || why="no <embree3/rtcore.h> or <embree4/rtcore.h>" ;;
      libegl-mesa0|libgl1-mesa-dri) ;;
      xvfb|xauth|xdotool|fonts-lmodern|fonts-dejavu-core|bubblewrap|python3-glad|ffmpeg) ;;  # optional: the window test skips without them, math falls back, the grader isolates less, the loader check skips
      clang-format|shellcheck|python3-pyflakes) ;;  # optional: the lint tests skip without them
      pandoc|chromium|npm) command -v "$p" >/dev/null 2>&1 || why="no $p command" ;;
      nodejs) command -v node >/dev/null 2>&1 || why="no node command" ;;
      *) why="no check is known for it" ;;
    esac
    [ -z "$why" ] || echo "$p ($why)"
  done
}

install_packages() {
  local no_apt=""
  if [ "${WB_NO_APT:-0}" = 1 ]; then
    no_apt="WB_NO_APT=1, so apt-get is not used"
  elif ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
    no_apt="apt-get is not available on this machine"
  fi
  if [ -n "$no_apt" ]; then  # check for the dependencies themselves
    local absent
    absent=$(missing_without_apt "$@")
    if [ -n "$absent" ]; then
      echo "workbook: $no_apt, and these dependencies are missing (Debian 12 package names: install" >&2
      echo "them or your system's equivalents, then run this again):" >&2
      while IFS= read -r line; do echo "  $line" >&2; done <<<"$absent"
      exit 1
    fi
    echo "workbook: $no_apt, but the dependencies were found (CMake checks them again when it configures)"
    return 0
  fi
  local missing
  missing=$(missing_packages "$@")
  [ -z "$missing" ] && return 0
  echo "workbook: installing $missing"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "workbook: not root and no sudo; as root run: apt-get install -y $missing" >&2; exit 1; }
    sudo="sudo"
  fi
  $sudo apt-get update -qq || { echo "workbook: apt-get update failed (no network, or no access to the archive?)" >&2; exit 1; }
  # shellcheck disable=SC2086
  if ! DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing >/dev/null; then
    local p unknown=()
    for p in $missing; do apt-cache show "$p" >/dev/null 2>&1 || unknown+=("$p"); done
    if [ ${#unknown[@]} -gt 0 ]; then
      echo "workbook: apt-get failed: this system has no package named ${unknown[*]} (the names are Debian 12's;" >&2
      echo "docs/gradescope.md gives Ubuntu 22.04's and 24.04's)" >&2
    else
      echo "workbook: apt-get could not install: $missing (its message is above)" >&2
    fi
    exit 1
  fi
  missing=$(missing_packages "$@")
  [ -z "$missing" ] || { echo "workbook: still missing after apt-get: $missing" >&2; exit 1; }
}

# The Debian mirror apt is configured to use (deb822 .sources files or one-line .list files), less
# the security archive and snapshots; empty where apt names none. For tools that fetch from Debian
# themselves (debootstrap, a deb-src line), so they work wherever apt does.
apt_mirror() {
  {
    grep -h '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{ for (i = 2; i <= NF; i++) print $i }'
    grep -h '^deb ' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null |
      awk '{ for (i = 2; i <= NF; i++) if ($i ~ /^[a-z+]+:\/\//) { print $i; break } }'
  } | grep -v -e security -e snapshot | head -1
}
