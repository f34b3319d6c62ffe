#!/usr/bin/env bash
# The committed glad 2 loader (third_party/glad): OpenGL 4.1 core, macOS's ceiling, so that a 4.2+
# entry point does not even compile; EGL 1.5 for headless Linux. It is committed because Ubuntu
# 22.04 (Gradescope's default image) and vcpkg ship glad 0.1, which cannot generate it.
#   tools/platforms/glad.sh           regenerate third_party/glad with Debian's python3-glad (glad 2)
#   tools/platforms/glad.sh --check   regenerate into a scratch folder and fail if it differs from the
#                           committed one (exit 77 where glad 2 is not installed: ctest skips)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
# GL: the debug callback and anisotropic filtering are used only where the context lists them.
# EGL: surfaceless Mesa (the platform, eglGetPlatformDisplayEXT, a context without a config).
EXTENSIONS=GL_KHR_debug,GL_EXT_texture_filter_anisotropic,GL_ARB_texture_filter_anisotropic
EXTENSIONS+=,EGL_EXT_platform_base,EGL_MESA_platform_surfaceless,EGL_KHR_no_config_context
PYTHON=/usr/bin/python3
[ -x "$PYTHON" ] || PYTHON=python3
generate() {  # OUT
  "$PYTHON" -m glad --quiet --api gl:core=4.1,egl=1.5 --extensions "$EXTENSIONS" --out-path "$1" \
    --reproducible c --loader
}
if ! "$PYTHON" -c 'import glad.generator.c' 2>/dev/null; then
  echo "tools/platforms/glad.sh: glad 2 is not installed for $PYTHON (Debian 12: sudo apt-get install python3-glad)" >&2
  exit 77
fi
if [ "${1:-}" = --check ]; then
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
  generate "$scratch"
  if ! diff -r "$scratch" "$ROOT/third_party/glad" >/dev/null; then
    diff -r "$scratch" "$ROOT/third_party/glad" | head -20 >&2
    echo "tools/platforms/glad.sh: third_party/glad differs from what glad generates; run tools/platforms/glad.sh and commit" >&2
    exit 1
  fi
  echo "third_party/glad matches the generator"
  exit 0
fi
rm -rf "$ROOT/third_party/glad"
generate "$ROOT/third_party/glad"
echo "wrote third_party/glad"
