#!/usr/bin/env bash
# The Dockerfile of ./workbook prairielearn-export runs this once, when the grading image is built (as
# root, with network): image_setup.sh [LABS]. It installs the packages the workbook needs and prebuilds
# the public workbook in /opt/shadow-workbook: the framework the judge links and the runner's build of
# the stubs, for LABS (01,03; empty: every lab). The solutions are not in the image; each job brings
# them (run_job) and compiles only them and the lab's tests.
set -euo pipefail
trap 'echo "image_setup.sh: FAILED at line $LINENO: \"$BASH_COMMAND\" exited with $?" >&2' ERR
cd "${WB_PL_TREE:-/opt/shadow-workbook}"  # (the stand-in sets it)
[ ! -d solutions ] || { echo "image_setup.sh: FAILED: solutions/ is here; the image must not hold them" >&2; exit 1; }
labs=${1:-}
bash ./workbook setup
chmod -R a+rX .
/usr/bin/python3 tools/grading/grade.py --prepare-only ${labs:+--labs "$labs"}
chmod -R a+rX .
rm -rf /var/lib/apt/lists/*
echo "image_setup.sh: the image is ready (labs: ${labs:-all})"
