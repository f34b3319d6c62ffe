#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder image (as root, with network).
# It installs the Debian/Ubuntu packages the workbook needs and prebuilds the grading framework, so
# grading a submission later costs only its exercise files.
set -euo pipefail
cd /autograder/source
apt-get update -qq
./workbook setup
# glad2 (python3-glad on Debian 12). An older distribution may ship glad 1, without --api.
if ! /usr/bin/python3 -m glad --help 2>/dev/null | grep -q -- "--api"; then
  apt-get install -y -qq python3-pip >/dev/null
  /usr/bin/python3 -m pip install --break-system-packages glad2 2>/dev/null || /usr/bin/python3 -m pip install glad2
fi
# The tests run as the unprivileged user nobody: it must read the tree and the build.
chmod -R a+rX /autograder/source
/usr/bin/python3 tools/grade.py --prepare-only
chmod -R a+rX /autograder/source
