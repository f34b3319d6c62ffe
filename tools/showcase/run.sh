#!/usr/bin/env bash
# ./workbook showcase [--table [--publish]] [OPTIONS]: every technique of the ten labs on one scene,
# in one window (headlessly to build/renders/showcase.png without a display), or --table: the whole
# workbook in one table (tools/showcase/table.py).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../workbook/lib.sh"
install_packages "${PACKAGES[@]}"
echo "workbook: building the showcase (every lab's solution in one program)"
QUIET=1 configure_and_build default --target showcase
if [ "${1:-}" = "--table" ]; then
  shift
  exec /usr/bin/python3 -B tools/showcase/table.py --exe build/showcase "$@"
elif ! has_display && [[ ! " $* " =~ " --headless "|" --help "|" --list-settings " ]]; then
  echo "workbook: no display found, so the showcase renders headlessly (Mesa llvmpipe) to a file"
  mkdir -p build/renders
  exec build/showcase --headless --screenshot build/renders/showcase.png "$@"
fi
exec build/showcase "$@"
