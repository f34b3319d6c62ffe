#!/usr/bin/env bash
# ./workbook gradescope-bundle (tools/grading/gradescope/bundle.sh), in a scratch copy of the repository:
# the zip holds the tracked files only (run twice, with an earlier zip, an untracked zip, a
# __pycache__ and a build folder lying around, none of them goes in), laid out as Gradescope unpacks
# it (setup.sh and run_autograder beside the workbook, executable); --labs 03 (or 03,04) makes an
# assignment for those labs, and its run_autograder passes them to the grader; its setup.sh stops
# with "setup.sh: FAILED" and the reason; outside a git checkout it refuses. Usage: gradescope_bundle_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: gradescope_bundle_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# shellcheck source=../framework/scratch_repo.sh
source "$root/tests/framework/scratch_repo.sh"
scratch_repo "$root" "$tmp/repo"  # this checkout's tracked files as they are on disk, committed
mkdir -p "$tmp/repo/tools/__pycache__" "$tmp/repo/build-x"
echo junk >"$tmp/repo/tools/__pycache__/grade.cpython-311.pyc"
echo junk >"$tmp/repo/build-x/CMakeCache.txt"
echo junk >"$tmp/repo/old-autograder.zip"
bundle="$tmp/repo/tools/grading/gradescope/bundle.sh"

zip="$tmp/repo/autograder.zip"  # inside the repository, so a second run could pick the first up
"$bundle" "$zip" --labs 03 >"$tmp/first.out" 2>&1 || fail "the first bundle failed: $(cat "$tmp/first.out")"
"$bundle" "$zip" --labs 03 >"$tmp/second.out" 2>&1 || fail "the second bundle failed: $(cat "$tmp/second.out")"
grep -q "set its total to 120 points" "$tmp/second.out" || fail "the bundle does not give lab 03's total: $(cat "$tmp/second.out")"
/usr/bin/python3 -B - "$zip" "$tmp/repo" <<'PY' || failures=$((failures + 1))
import subprocess, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = set(z.namelist())
mode = {i.filename: i.external_attr >> 16 for i in z.infolist()}
tracked = set(subprocess.run(["git", "-C", sys.argv[2], "ls-files"], capture_output=True, text=True).stdout.split())
bad = []
need = ["setup.sh", "run_autograder", "gradescope-labs", "workbook", "tools/grading/grade.py", "CMakeLists.txt"]
bad += [f"lacks {n}" for n in need if n not in names]
bad += [f"{n} is not executable" for n in ("setup.sh", "run_autograder", "workbook") if n in mode and not mode[n] & 0o111]
bad += ["has no solutions/"] * (not any(n.startswith("solutions/") for n in names))
bad += [f"holds {n}" for n in names if n.endswith(".zip") or "__pycache__" in n or n.startswith("build")]
extra = names - tracked - {"setup.sh", "run_autograder", "gradescope-labs"}
bad += [f"holds the untracked {n}" for n in sorted(extra)]
labs = z.read("gradescope-labs").decode().strip() if "gradescope-labs" in names else None
bad += [f"gradescope-labs is {labs!r}, expected '03'"] * (labs != "03")
for b in bad:
    print("FAIL: the bundle", b)
sys.exit(1 if bad else 0)
PY

# Its run_autograder passes the assignment's labs to the grader (a stand-in grade.py records its arguments).
mkdir -p "$tmp/ag/source" "$tmp/ag/submission"
(cd "$tmp/ag/source" && /usr/bin/python3 -m zipfile -e "$zip" .)
chmod +x "$tmp/ag/source/run_autograder"
cat >"$tmp/ag/source/tools/grading/grade.py" <<'EOF'
import sys
open(sys.argv[0] + ".args", "w").write(" ".join(sys.argv[1:]))
EOF
WB_AUTOGRADER="$tmp/ag" "$tmp/ag/source/run_autograder" >"$tmp/run.out" 2>&1 || fail "run_autograder failed: $(cat "$tmp/run.out")"
args=$(cat "$tmp/ag/source/tools/grading/grade.py.args" 2>/dev/null || true)
[[ " $args " == *" --labs 03 "* ]] || fail "run_autograder runs the grader with '$args', without --labs 03"
[[ " $args " == *" --out $tmp/ag/results "* ]] || fail "run_autograder does not write to results/: '$args'"

# Its setup.sh stops loudly, before the grading build, when ./workbook setup fails (a stand-in
# workbook fails its setup). (No glad is needed: the loader is committed, third_party/glad.)
cat >"$tmp/ag/source/workbook" <<'EOF'
#!/usr/bin/env bash
if [[ "${BASH_SOURCE[0]}" != "$0" ]]; then return 0; fi
[ "$1" = setup ] && exit "${STUB_SETUP_EXIT:-0}"
EOF
# shellcheck disable=SC2043  # (a table of cases: one so far)
for case in "1 ./workbook setup could not install"; do
  if out=$(STUB_SETUP_EXIT=${case%% *} WB_AUTOGRADER="$tmp/ag" bash "$tmp/ag/source/setup.sh" 2>&1); then
    fail "setup.sh succeeded although ${case#* }"
  elif ! grep -q "^setup.sh: FAILED: ${case#* }" <<<"$out"; then
    fail "setup.sh does not say '${case#* }': $out"
  fi
done

# Two labs: their total, and both in gradescope-labs.
"$bundle" "$tmp/two.zip" --labs 3,04 >"$tmp/two.out" 2>&1 || fail "--labs 3,04 failed: $(cat "$tmp/two.out")"
grep -q "set its total to 230 points" "$tmp/two.out" || fail "the two-lab bundle's total: $(cat "$tmp/two.out")"
[ "$(/usr/bin/python3 -c 'import sys, zipfile; print(zipfile.ZipFile(sys.argv[1]).read("gradescope-labs").decode().strip())' "$tmp/two.zip")" = "03,04" ] ||
  fail "gradescope-labs of --labs 3,04 is not 03,04"
if "$bundle" "$tmp/none.zip" --labs 42 >"$tmp/none.out" 2>&1; then fail "--labs 42 (no such lab) made a bundle"; fi
grep -q "no lab 42" "$tmp/none.out" || fail "--labs 42 does not say there is no such lab: $(cat "$tmp/none.out")"

# Outside a git checkout the bundle refuses (it could not tell tracked files from the rest).
mkdir -p "$tmp/nogit"
(cd "$tmp/repo" && tar --exclude=.git -cf - .) | tar -xf - -C "$tmp/nogit"
if "$tmp/nogit/tools/grading/gradescope/bundle.sh" "$tmp/nogit.zip" >"$tmp/nogit.out" 2>&1; then
  fail "the bundle was made outside a git checkout"
fi
grep -q "not a git checkout" "$tmp/nogit.out" || fail "outside git, the message is: $(cat "$tmp/nogit.out")"

[ "$failures" = 0 ] && echo "gradescope bundle: every check passed" || exit 1
