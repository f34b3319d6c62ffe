#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder image (as root, with network), on its
# Ubuntu 22.04 or 24.04 base image, in /autograder/source where it unpacked the bundle. It installs the
# packages the workbook needs and prebuilds the grading framework for the
# assignment's labs (gradescope-labs), so grading a submission later costs only its exercise files.
# Anything missing stops it with a line that starts with "setup.sh: FAILED" and says what.
set -euo pipefail
fail() { echo "setup.sh: FAILED: $*" >&2; exit 1; }
trap 'echo "setup.sh: FAILED at line $LINENO: \"$BASH_COMMAND\" exited with $?" >&2' ERR
cd "${WB_AUTOGRADER:-/autograder}/source"  # WB_AUTOGRADER: only tests set it
[ -f ./workbook ] || fail "no ./workbook in $PWD: the bundle must be unpacked here (./workbook gradescope-bundle makes it)"
# shellcheck disable=SC1091
os=$( (. /etc/os-release && echo "$PRETTY_NAME") 2>/dev/null || echo "an unknown system")
echo "setup.sh: setting up the autograder on $os"
export DEBIAN_FRONTEND=noninteractive

# 1. The packages: ./workbook setup names a package this distribution does not have. (The glad loader
# is committed, third_party/glad: Ubuntu 22.04's python3-glad, glad 1, is not needed.)
# (through bash: an unzip that drops the executable bits does not stop it)
bash ./workbook setup || fail "./workbook setup could not install what the workbook needs (its message is above)"

# 2. The grading framework, for the labs of this assignment. The student's code is built and run by
# unprivileged users, which must read build-grade/ (the grader hides the rest of the tree from them
# while it grades).
labs=$(tr -d '[:space:]' <gradescope-labs 2>/dev/null || true)
chmod -R a+rX .
/usr/bin/python3 tools/grading/grade.py --prepare-only ${labs:+--labs "$labs"} ||
  fail "the grading build failed (the compiler's or CMake's message is above)"
chmod -R a+rX .
echo "setup.sh: the autograder is ready (labs: ${labs:-all})"
