#!/usr/bin/env bash
# The grader in its weakest sandbox, as in Gradescope's container (no user namespaces: bubblewrap and
# unshare cannot start): WB_SANDBOX_MODE=session turns both off here. A small class of lab 01 holds the
# cheats that mode must still stop (tests/grading/redteam.py: /proc snooping, a daemon that forges
# results, a FIFO swapped into the tape, a runner that kills its supervisor; make_submissions.py: a flood, a daemon, an include of the
# solutions, C++ that reads them where they are) beside an honest submission, each against its expected score (check_batch.py).
# Usage: run_weak_class.sh OUTPUT_DIR BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: run_weak_class.sh OUTPUT_DIR BUILD_DIR}
build=$(cd "${2:?usage: run_weak_class.sh OUTPUT_DIR BUILD_DIR}" && pwd)
rm -rf "$out" && mkdir -p "$out"
/usr/bin/python3 "$root/tests/grading/make_submissions.py" "$out/submissions" --labs 01 \
  --only full,flood,daemon,include_solutions,leak_secrets,proc_snoop,results_daemon,fifo_tape,supervisor_kill
WB_SANDBOX_MODE=session WB_GRADE_SEED=14 /usr/bin/python3 "$root/tools/grading/grade.py" --batch "$out/submissions" \
  --out "$out/grades" --labs 01 --jobs 1 --timeout 8 --build-timeout 30 --judge-build "$build"
grep -q "WB_SANDBOX_MODE=session" "$out/grades/full/report.md" ||
  { echo "FAIL: the report does not say that the weakest mode was used"; exit 1; }
cat "$out/grades/summary.md"
/usr/bin/python3 "$root/tests/grading/check_batch.py" "$out/submissions" "$out/grades"
