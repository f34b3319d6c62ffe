#!/usr/bin/env bash
# Red-team tests of the tape a runner hands the judge (common/judge/tape.hpp), on lab 10:
# 1. a recorded app run whose list of calls for the graded exercise is empty must not let the
#    judge's trusted app fall back to its own (the solution's) code: the scene test fails;
# 2. a tape line nested a million deep must not crash the judge (it is ignored as malformed);
# 3. with WB_REPLAY_USES naming no exercise, the judge replays only the graded exercise's calls
#    (the used exercises passed their own tests, so they get the solution's code).
# Usage: tape_forgery_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$build/test-output/tape-forgery
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
runner=$build/lab10_solution_tests judge=$build/lab10_solution_tests
test=Lab10.Ex10_3_SceneFieldCropped
export WB_VARY_SEED=5
"$runner" --gtest_filter=$test --runner "$work/tape" >"$work/runner.log" 2>&1 || true
# shellcheck disable=SC2012  # (the runner names its tape files: ls gives the first match)
calls=$(ls "$work"/tape/file-*exercises | head -1)
[ -f "$calls" ] || fail "the runner recorded no exercise calls"
cp -r "$work/tape" "$work/honest"
"$judge" --gtest_filter=$test --judge "$work/honest" >"$work/honest.log" 2>&1 || fail "the honest tape fails ($work/honest.log)"

# 1. An empty list of calls for 10.3.
/usr/bin/python3 - "$calls" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); j["calls"]["10.3"] = []; json.dump(j, open(sys.argv[1], "w"))
PY
if "$judge" --gtest_filter=$test --judge "$work/tape" >"$work/empty.log" 2>&1; then
  fail "an empty list of 10.3 calls passed the scene test ($work/empty.log)"
fi
grep -q "never ran exercise 10.3" "$work/empty.log" || fail "the empty list is not named ($work/empty.log)"
echo "1: an empty list of calls fails the scene test"

# 2. A line nested a million deep.
cp -r "$work/honest" "$work/deep"
/usr/bin/python3 -c "print('{\"key\":\"x\",\"value\":' + '[' * 1000000 + ']' * 1000000 + '}')" >>"$work/deep/tape.jsonl"
"$judge" --gtest_filter=$test --judge "$work/deep" >"$work/deep.log" 2>&1 || fail "a deep line broke the judge ($work/deep.log)"
echo "2: a line nested a million deep is ignored"

# 3. WB_REPLAY_USES empty: only 10.3's calls are replayed, with no upstream file for the reference.
WB_REPLAY_USES='' "$judge" --gtest_filter=$test --judge "$work/honest" >"$work/uses.log" 2>&1 || fail "judging without the used exercises failed"
out=$(ls -d "$build"/test-output/lab10_solution/Ex10.3_field_crop)
[ ! -e "$out/upstream.json" ] || fail "WB_REPLAY_USES= still replayed the used exercises"
/usr/bin/python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['calls']; sys.exit(0 if list(c)==['10.3'] else 1)" \
  "$out/exercises.json" || fail "the judge's replay file holds more than 10.3"
echo "3: WB_REPLAY_USES= replays the graded exercise alone"
