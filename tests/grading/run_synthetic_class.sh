#!/usr/bin/env bash
# The grader on a synthetic class (ctest -L grading): submissions made from the solutions (full,
# stubs, one mutant, a compile error, a segfault, endless loops in C++ and GLSL, a build that runs
# past the build time limit, a zipped upload) are graded as a batch, which must complete, and held
# against their expected scores (the Gradescope bundle has its own test, gradescope_bundle_test.sh).
# Labs 01 and 02 keep it to a few minutes (the build time limit of 20 s costs endless_build about 1 min).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: run_synthetic_class.sh OUTPUT_DIR}
rm -rf "$out" && mkdir -p "$out"
# A second copy of the solutions elsewhere on the machine, readable by everyone (an instructor's
# other clone): the sandbox must keep it out of reach (cpp_include_copy).
base=/opt
[ -w "$base" ] || base=${TMPDIR:-/tmp}  # (not root: a folder of this user's, outside the checkout)
copy=$base/wb-second-copy-$$
trap 'rm -rf "$copy"' EXIT
mkdir -p "$copy" && cp -r "$root/solutions" "$copy/" && chmod -R a+rX "$copy"
/usr/bin/python3 "$root/tools/make_submissions.py" "$out/submissions" --labs 01,02 --second-copy "$copy"
/usr/bin/python3 "$root/tools/grade.py" --batch "$out/submissions" --out "$out/grades" --labs 01,02 --jobs 1 \
  --timeout 20 --build-timeout 20
cat "$out/grades/summary.md"
/usr/bin/python3 "$root/tests/grading/check_batch.py" "$out/submissions" "$out/grades"
