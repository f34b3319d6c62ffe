#!/usr/bin/env bash
# ./workbook check (wb_check, common/judge/supervisor.hpp, the same on every OS) runs each
# exercise's runner alone, in a session of its own, with a time limit: a runner that loops forever is stopped at the limit with every process it
# started, and one that crashes is named with its signal; both reasons reach the judge
# (stopped.txt), and the other exercises' records are kept; one that prints without end is stopped
# when its log reaches the cap, which says that it was cut. The judge is bounded too: one
# that never ends is stopped at its limit, naming the test it was in. A fake lab stands in for the
# build: 77.1 records, 77.2 loops (with a child that would outlive it), 77.3 crashes, 77.4 floods.
# Usage: workbook_check_limits_test.sh WB_CHECK SCRATCH_DIR
set -uo pipefail
check=${1:?usage: workbook_check_limits_test.sh WB_CHECK SCRATCH_DIR}
tmp=${2:?usage: workbook_check_limits_test.sh WB_CHECK SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp/build"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$tmp" || exit 1
cat >build/lab77_tests <<'FAKE'
#!/usr/bin/env bash
dir=$2 filter=$3
mkdir -p "$dir"
case $filter in
  *Ex77_1_*) echo '{"key":"Lab77.Ex77_1_A#0","value":1}' >"$dir/tape.jsonl"
    sleep 1000 & echo $! >"$dir/../left.pid" ;;  # (ends, leaving a process behind)
  *Ex77_2_*) sleep 1000 & echo $! >"$dir/../child.pid"; while :; do :; done ;;
  *Ex77_3_*) echo "crashed (SIGSEGV: test) in exercise 77.3, at labs/77_fake/exercise.cpp:9 (f)" >&2; kill -SEGV $$ ;;
  *Ex77_4_*) exec yes "a debug print in a loop" ;;
esac
FAKE
chmod +x build/lab77_tests
tape=$tmp/tape
mkdir -p "$tape/all"
start=$(date +%s)
export WB_CHECK_LOG_MB=1
for id in 77.1 77.2 77.3 77.4; do WB_CHECK_TIMEOUT=3 "$check" --runner build/lab77_tests "$id" "$tape"; done
took=$(($(date +%s) - start))
[ "$took" -le 12 ] || fail "four runners with a 3 s limit took $took s"
grep -q '"Lab77.Ex77_1_A#0"' "$tape/all/tape.jsonl" || fail "77.1's record was not kept: $(cat "$tape/all/tape.jsonl")"
grep -q "^Ex77_2	77.2 timed out after 3 s and was stopped: an endless loop?" "$tape/all/stopped.txt" ||
  fail "the endless runner is not named: $(cat "$tape/all/stopped.txt")"
grep -q "^Ex77_3	crashed (SIGSEGV: test) in exercise 77.3, at labs/77_fake/exercise.cpp:9" "$tape/all/stopped.txt" ||
  fail "the crash is not named with its place: $(cat "$tape/all/stopped.txt")"
grep -q "^Ex77_4	77.4 wrote more than 1 MB of output (a print in a loop?) and was stopped" "$tape/all/stopped.txt" ||
  fail "the flooding runner is not named: $(cat "$tape/all/stopped.txt")"
size=$(stat -c %s "$tape/Ex77_4.log")
[ "$size" -le $((1024 * 1024 + 200)) ] || fail "the flooding runner's log holds $size bytes, more than the 1 MB cap"
tail -1 "$tape/Ex77_4.log" | grep -q "^\[workbook: cut here: the run wrote more than 1 MB" ||
  fail "the cut log does not say it was cut: $(tail -c 200 "$tape/Ex77_4.log")"
# A judge whose test never ends (it calls an endless exercise) has that test stopped at the limit of
# one test, written down for its exercise, and runs again without it; tests that each take their
# time are not stopped.
cat >build/lab77_judge <<'FAKE'
#!/usr/bin/env bash
for t in A B C; do echo "Lab77.Ex77_1_$t" >"$WB_PROGRESS_FILE"; sleep 1; done
[[ " $* " == *" --gtest_filter=-Lab77.Ex77_2_Loops "* ]] && { echo "the table, without the endless test"; exit 1; }
echo "Lab77.Ex77_2_Loops" >"$WB_PROGRESS_FILE"
sleep 1000 & echo $! >"$WB_PROGRESS_FILE.child"
while :; do :; done
FAKE
chmod +x build/lab77_judge
start=$(date +%s)
code=0
out=$(WB_CHECK_JUDGE_TIMEOUT=2 WB_CHECK_TIMEOUT=3 "$check" --judge 77 build/lab77_judge "$tape" labs/77_fake 2>&1) || code=$?
took=$(($(date +%s) - start))
[ "$took" -le 20 ] || fail "an endless judge test with a 2 s limit per test took $took s"
[ "$code" = 1 ] || fail "the judge's second run (the table) should give its own exit code 1, got $code"
grep -q "judging lab 77: the test Lab77.Ex77_2_Loops (exercise 77.2) ran past 2 s and was stopped; judging the rest" \
  <<<"$out" || fail "the endless judge test is not named: $out"
grep -q "the table, without the endless test" <<<"$out" || fail "the judge did not run again without it: $out"
grep -q "^Ex77_2	the judge's test Lab77.Ex77_2_Loops ran past 2 s and was stopped" "$tape/all/stopped.txt" ||
  fail "the stopped judge test is not written down for 77.2: $(cat "$tape/all/stopped.txt")"
grep -q "Ex77_1_.*ran past" <<<"$out" && fail "a judge test that took its time (1 s) was stopped: $out"
child=$(cat "$tape/child.pid" 2>/dev/null)
alive() { ps -o stat= -p "$1" 2>/dev/null | grep -qv Z; }  # (a zombie waits for its reaper only)
for _ in 1 2 3 4 5 6 7 8 9 10; do alive "$child" || break; sleep 0.2; done
[ -n "$child" ] && ! alive "$child" || fail "a process the endless runner started is still running ($child)"
left=$(cat "$tape/left.pid" 2>/dev/null)
[ -n "$left" ] && ! alive "$left" || fail "a process a finished runner left behind is still running ($left)"
judged=$(cat "$tape/judging.txt.child" 2>/dev/null)
[ -n "$judged" ] && ! alive "$judged" || fail "a process the stopped judge started is still running ($judged)"
[ "$failures" = 0 ] && echo "check's limits: a loop stopped with its children, a crash named, a flood cut, an endless judge stopped, the rest kept"
exit $((failures > 0))
