# Sourced by ./workbook and the tools it calls: the checkout's root (ROOT, also the working folder),
# JOBS, die, and the package and build helpers.
# shellcheck shell=bash
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$ROOT" || exit 2
JOBS=$(nproc 2>/dev/null || echo 2)
die() { echo "workbook: $*" >&2; exit 2; }
# shellcheck source=tools/workbook/packages.sh
source "$ROOT/tools/workbook/packages.sh"
# shellcheck source=tools/workbook/build.sh
source "$ROOT/tools/workbook/build.sh"
