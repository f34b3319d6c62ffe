#!/usr/bin/env bash
# The workbook's verdict suite on a GPU, in two steps (docs/gpu-check.md):
#   tools/platforms/gpu_check.sh pack [BUILD_DIR] [OUT_DIR] [--framework] [--keep-debug REGEX]
#       here, beside a build: one folder (gpu-pack/, about 30 MB) with the stripped executables, the
#       libraries a bare machine may lack, the files the tests read and ctest's list of the tests
#   gpu-pack/gpu_check.sh run [PACK_DIR] [-j N] [--only REGEX] [--label REGEX] [--nvidia] [--timings] ...
#       there, on the machine with the GPU (python3 only: no apt, CMake or ctest): every test with
#       ctest's rules; results.tsv, failures.txt, a table per label and "N passed, N failed"
#   gpu_check.sh self-test
#       the runner's rules on tiny fake tests (what tests/framework runs)
# The work is in Python (standard library only): gpu_pack.py packs; gpu_check.py runs, with
# ctest_rules.py (what ctest would do) and gpu_unpack.py (the tree where the binaries look for it).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

die() { echo "gpu_check: $*" >&2; exit 2; }

usage() {
  sed -n '2,12s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
}

# python3 3.7 or newer: the one thing the target must have besides the GPU driver.
find_python() {
  local p
  p=$(command -v python3 || true)
  [ -n "$p" ] || die "python3 is needed (3.7 or newer) and is not on PATH"
  "$p" -c 'import sys; sys.exit(sys.version_info < (3, 7))' || die "$p is older than Python 3.7"
  echo "$p"
}

main() {
  local cmd=${1:-help} python
  [ $# -gt 0 ] && shift
  case $cmd in
    pack)
      # (only in the repository: a pack holds the runner, not the packer)
      [ -f "$here/gpu_pack.py" ] || die "pack: run it from the repository (tools/platforms/gpu_check.sh pack)"
      python=$(find_python)
      exec "$python" -B "$here/gpu_pack.py" "$@" ;;
    run)
      python=$(find_python)
      exec "$python" -B "$here/gpu_check.py" run "$@" ;;
    self-test|--self-test)
      python=$(find_python)
      exec "$python" -B "$here/gpu_check.py" --self-test ;;
    help|-h|--help) usage ;;
    *) usage >&2; die "unknown command '$cmd'" ;;
  esac
}

main "$@"
