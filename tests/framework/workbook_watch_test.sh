#!/usr/bin/env bash
# ./workbook check NN --watch (watch_lab) survives saves: ten in a row, some while a check runs
# (which must start over) and some after one has finished (which once ended the watcher, exit 1, at
# the first such save: `[ -f running.pid ] && pkill` under set -e, with the file of the finished
# check still there and nothing left to kill). This script stands in for the check the watcher
# starts ("$0 check NN"): it leaves its running.pid as a real check's runner does, says so, and sleeps.
# Usage: workbook_watch_test.sh SCRATCH_DIR
[[ "$0" = /* ]] || exec "$PWD/$0" "$@"  # (the watcher starts "$0 check NN" from elsewhere)
if [ "${1:-}" = check ]; then
  mkdir -p "build/check/lab$2" && echo $$ >"build/check/lab$2/running.pid"
  echo "fake check $2 started"; sleep 3; echo "fake check $2 done"; exit 0
fi
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: workbook_watch_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp/labs/77_fake"
# shellcheck source=/dev/null
source "$root/workbook"  # (the functions only; it sets -e, as the workbook runs)
set +e
cd "$tmp" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
save() { echo "// save $1" >>labs/77_fake/exercise.cpp; }
save 0
(set -e; watch_lab 77) >watch.log 2>&1 &
watcher=$!
sleep 1.5
for k in 1 2 3 4 5 6 7 8 9 10; do
  save "$k"
  if ((k % 2)); then sleep 1.6; else sleep 5.5; fi  # odd: saved again while that check runs; even: after it ends
  kill -0 "$watcher" 2>/dev/null || { fail "the watcher ended after save $k: $(tail -3 watch.log)"; break; }
done
started=$(grep -c "fake check 77 started" watch.log)
over=$(grep -c "saved again: the check starts over" watch.log)
waiting=$(grep -c "waiting for the next save" watch.log)
[ "$started" -ge 11 ] || fail "$started checks started for the first state and ten saves (want 11)"
# (about five of each; a loaded machine may move a save from one kind to the other)
[ "$over" -ge 2 ] || fail "$over saves during a check started it over (want about 5)"
[ "$waiting" -ge 2 ] || fail "the watcher waited for the next save $waiting times (want about 5)"
kill -TERM "$watcher" 2>/dev/null
wait "$watcher" 2>/dev/null
sleep 0.5
pgrep -f "workbook_watch_test.sh check 77" >/dev/null && fail "a check the watcher started outlived it"
[ "$failures" = 0 ] && echo "check --watch: ten saves, $over during a check and $waiting between checks; $started checks"
exit $((failures > 0))
