#!/usr/bin/env bash
# Held-out tests that call C++ exercises (WB_CALL_HELD_OUT) through the grader's three steps, for
# every lab that has them: the judge's planning pass lists the calls, a runner that does not hold the
# tests makes them from that plan, and the judge replays them. With the solution as the runner every
# held-out test passes; with the stubs each call is reported as not implemented, never as "recorded
# no result" (what every submission got before the calls could be planned).
# Usage: heldout_calls_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
work=$build/test-output/heldout-calls
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
labs=$(grep -l "WB_CALL_HELD_OUT" "$src"/tests/hidden/*/heldout_test.cpp | sed 's|.*/hidden/\([0-9][0-9]\)_.*|\1|')
[ -n "$labs" ] || fail "no held-out test calls an exercise"
for nn in $labs; do
  judge="$build/lab${nn}_solution_tests"
  filter="Hidden${nn}.*"
  for who in solution stubs; do
    runner="$build/lab${nn}_tests"
    [ $who = solution ] && runner="$judge"
    dir="$work/$nn-$who" && mkdir -p "$dir/empty"
    WB_PLAN="$dir/plan.jsonl" "$judge" --gtest_filter="$filter" --judge "$dir/empty" >"$dir/plan.log" 2>&1 || true
    calls=$(grep -c '"call"' "$dir/plan.jsonl" || true)
    [ "$calls" -gt 0 ] || fail "lab $nn: the planning pass asked for no call (plan: $dir/plan.jsonl)"
    "$runner" --requests "$dir/plan.jsonl" --runner "$dir/tape" >"$dir/runner.log" 2>&1 || true
    "$judge" --gtest_filter="$filter" --judge "$dir/tape" >"$dir/judge.log" 2>&1 && ok=1 || ok=0
    if grep -q "recorded no result" "$dir/judge.log"; then fail "lab $nn ($who): a planned call was not recorded ($dir/judge.log)"; fi
    if [ "$who" = solution ] && [ "$ok" = 0 ]; then fail "lab $nn: the solution as the runner fails held-out tests ($dir/judge.log)"; fi
    if [ $who = stubs ]; then
      grep -q "NOT IMPLEMENTED" "$dir/judge.log" || fail "lab $nn: the stubs' calls were not reported as not implemented"
    fi
    echo "lab $nn, $who as the runner: $calls planned calls, judged as expected"
  done
done
