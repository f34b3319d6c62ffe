#!/usr/bin/env bash
# ./workbook export-student (tools/grading/export_student.sh), in a scratch copy of the repository with work
# in progress lying around: the export is the committed tree (an uncommitted edit and an untracked
# file stay out), it holds no instructor file (the grader, its tests, the instructor docs), its README
# is the students' one and offers no --solution, grade, golden or bundle command, and its ./workbook
# hides and refuses the instructor's commands. Usage: export_student_test.sh SCRATCH_DIR
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
tmp=${1:?usage: export_student_test.sh SCRATCH_DIR}
rm -rf "$tmp" && mkdir -p "$tmp"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# shellcheck source=scratch_repo.sh
source "$root/tests/framework/scratch_repo.sh"
scratch_repo "$root" "$tmp/repo"  # this checkout's tracked files as they are on disk, committed
# Work in progress: an edit of a tracked file and a new file, neither committed.
echo "WORK IN PROGRESS" >>"$tmp/repo/labs/01_depth_map/README.md"
echo "draft" >"$tmp/repo/labs/01_depth_map/draft-notes.md"

student="$tmp/student"
if ! "$tmp/repo/tools/grading/export_student.sh" "$student" >"$tmp/export.out" 2>&1; then
  fail "the export failed: $(cat "$tmp/export.out")"
fi
grep -q "not exported" "$tmp/export.out" || fail "the export does not say that uncommitted work is left out"
! grep -q "WORK IN PROGRESS" "$student/labs/01_depth_map/README.md" || fail "an uncommitted edit was exported"
[ ! -e "$student/labs/01_depth_map/draft-notes.md" ] || fail "an untracked file was exported"
for path in solutions tests/mutants tests/hidden tests/grading docs/instructors.md docs/gradescope.md \
            tools/grading/grade.py tools/grading/gradescope tests/grading/make_submissions.py tools/grading/export_student.sh tools/grading/student_README.md; do
  [ ! -e "$student/$path" ] || fail "the student edition has $path"
done
for path in workbook labs/01_depth_map/exercise.cpp tests/framework docs/adding-a-lab.md; do
  [ -e "$student/$path" ] || fail "the student edition lacks $path"
done
# The handed-out C++ exercise files, for check's filling in of an earlier edition's file.
for lab in "$student"/labs/[0-9][0-9]_*/; do
  [ ! -f "${lab}exercise.cpp" ] || cmp -s "${lab}exercise.cpp" "$student/tests/stubs/$(basename "$lab")/exercise.cpp" ||
    fail "the student edition lacks the stub tests/stubs/$(basename "$lab")/exercise.cpp, or it differs"
done
# The handed-out exercise shaders, for check's C++ runs: every lab's, as committed.
for lab in "$student"/labs/[0-9][0-9]_*/; do
  for f in "$lab"shaders/exercise*; do
    [ -f "$f" ] || continue
    copy="$student/tests/stubs/$(basename "$lab")/shaders/$(basename "$f")"
    cmp -s "$f" "$copy" || fail "the student edition lacks the stub $copy, or it differs from $f"
  done
done

# The students' README: the quick start and the lab table, and no instructor command.
readme="$student/README.md"
grep -q "student edition" "$readme" || fail "README.md is not the students' README"
grep -q '^./workbook demo' "$readme" && grep -q '^./workbook test' "$readme" || fail "README.md lacks the quick start"
grep -q '^| \[01\](labs/01_depth_map/README.md)' "$readme" || fail "README.md lacks the lab table"
! grep -q '^@' "$readme" || fail "README.md has a template line left: $(grep '^@' "$readme")"
for word in --solution "workbook grade" "workbook golden" "workbook figures" gradescope prairielearn make-submissions \
            export-student instructors.md; do
  ! grep -qi -- "$word" "$readme" || fail "README.md mentions '$word': $(grep -i -- "$word" "$readme" | head -1)"
done

# Its workbook: no instructor command in help, and each one refused with a clear message.
help=$("$student/workbook" help)
! grep -q -- --solution <<<"$help" || fail "./workbook help offers --solution"
for cmd in golden figures grade make-submissions gradescope-bundle prairielearn-export export-student; do
  ! grep -qE "^ +$cmd( |$)" <<<"$help" || fail "./workbook help offers '$cmd'"
done
for cmd in "grade x" "golden 01" "gradescope-bundle" "prairielearn-export x" "make-submissions x" "export-student x" "figures 01"; do
  # shellcheck disable=SC2086
  if out=$("$student/workbook" $cmd 2>&1); then
    fail "./workbook $cmd ran in the student edition"
  else
    grep -q "is for instructors: this is the student edition" <<<"$out" || fail "./workbook $cmd says: $out"
  fi
done

[ "$failures" = 0 ] && echo "student edition: every check passed" || exit 1
