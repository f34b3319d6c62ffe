#!/usr/bin/env bash
# The grader on a synthetic class (ctest -L grading): submissions made from the solutions (full,
# stubs, one mutant, a compile error, a segfault, endless loops in C++ and GLSL, a build that runs
# past the build time limit, a zipped upload) are graded as a batch, which must complete, and held
# against their expected scores (the Gradescope bundle has its own test, gradescope_bundle_test.sh).
# Labs 01 and 02 keep it to a few minutes: the faults and cheats touch lab 01 only (lab 02 stays the
# stubs, which the grader neither builds nor runs), the judge is this build (--judge-build: no second
# compile of the solutions or the framework), and the time limits are low (8 s: a build of lab 01 takes
# about 1.5 s here, an exercise's tests under 1 s, with room for the other tests that ctest runs beside
# it; the endless build and loop run into them twice and three times).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: run_synthetic_class.sh OUTPUT_DIR BUILD_DIR}
build=$(cd "${2:?usage: run_synthetic_class.sh OUTPUT_DIR BUILD_DIR}" && pwd)
rm -rf "$out" && mkdir -p "$out"
# A second copy of the solutions elsewhere on the machine, readable by everyone (an instructor's
# other clone): the sandbox must keep it out of reach (cpp_include_copy).
base=/opt
[ -w "$base" ] || base=${TMPDIR:-/tmp}  # (not root: a folder of this user's, outside the checkout)
copy=$base/wb-second-copy-$$
trap 'rm -rf "$copy"' EXIT
mkdir -p "$copy" && cp -r "$root/solutions" "$copy/" && chmod -R a+rX "$copy"
/usr/bin/python3 "$root/tests/grading/make_submissions.py" "$out/submissions" --labs 01,02 --second-copy "$copy"
# One seed for the class (14: one that once cost the reference 08.5), so full and full_again must match.
WB_GRADE_SEED=14 /usr/bin/python3 "$root/tools/grading/grade.py" --batch "$out/submissions" --out "$out/grades" --labs 01,02 --jobs 1 \
  --timeout 8 --build-timeout 8 --judge-build "$build"
cat "$out/grades/summary.md"
/usr/bin/python3 "$root/tests/grading/check_batch.py" "$out/submissions" "$out/grades"
