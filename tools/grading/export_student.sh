#!/usr/bin/env bash
# Writes the student edition of the workbook: ./workbook export-student DIR
# It is the committed tree (git archive HEAD: never uncommitted work in progress) minus what would
# give answers away or is for instructors only: solutions/, the mutants (they quote solution lines),
# the held-out tests (tests/hidden/), the grader and its tests, and the instructor docs (INSTRUCTOR
# below). Golden data and handouts stay. Its README.md is tools/grading/student_README.md, filled in from
# this README (the lab table and the sections it names), so it offers no instructor command.
# --verify DIR proves that an exported folder holds no solution content and no instructor file (see
# the rule below), and exits 1 naming each leak.
set -euo pipefail
mapfile -t INSTRUCTOR < <(grep -v '^#' "$(dirname "$0")/instructor_paths.txt" | grep .)
verify=0
if [ "${1:-}" = "--verify" ]; then verify=1; shift; fi
[ $# -eq 1 ] || { echo "usage: $0 [--verify] DIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mkdir -p "$1" && cd "$1" && pwd)
[ -d "$root/solutions" ] || { echo "export-student: this copy has no solutions/; it is a student edition already" >&2; exit 2; }
if [ "$verify" = 0 ]; then
  [ -n "$(ls -A "$out" 2>/dev/null)" ] && { echo "export-student: $out is not empty" >&2; exit 2; }
  cd "$root"
  git rev-parse --verify -q HEAD >/dev/null 2>&1 || { echo "export-student: $root is not a git checkout with a commit:" \
    "the student edition is exported from the committed tree" >&2; exit 2; }
  dirty=$(git status --porcelain | wc -l)
  [ "$dirty" = 0 ] || echo "export-student: note: $dirty uncommitted changes or untracked files are not exported" \
    "(the student edition is the committed tree, $(git rev-parse --short HEAD))" >&2
  git archive --format=tar HEAD -- . "${INSTRUCTOR[@]/#/:(exclude)}" | tar -xf - -C "$out"
  # The exercise files as handed out (tests/stubs/NN_name/): ./workbook check records the C++
  # exercises with these shaders, as the grader does, so that a student's GLSL mistake cannot stop
  # those runs; and it fills in, from them, an exercise a file written before it was added lacks.
  for lab in "$out"/labs/[0-9][0-9]_*/; do
    name=$(basename "$lab")
    mkdir -p "$out/tests/stubs/$name/shaders"
    for f in "$lab"shaders/exercise*; do [ -f "$f" ] && cp "$f" "$out/tests/stubs/$name/shaders/"; done
    for f in "$lab"exercise*.cpp; do [ -f "$f" ] && cp "$f" "$out/tests/stubs/$name/"; done
  done
  # The students' README: the template, with the lab table and named sections of this README.
  git show HEAD:README.md >"$out/README.md.instructor"
  git show HEAD:tools/grading/student_README.md | /usr/bin/python3 -B -c '
import re, sys
readme = open(sys.argv[1]).read()
def section(title):
    m = re.search(r"^## " + re.escape(title) + r"\n.*?(?=^## |\Z)", readme, re.S | re.M)
    if not m:
        sys.exit(f"export-student: README.md has no section {title!r} for the student README")
    return m.group(0).rstrip() + "\n"
table = re.search(r"^\| Lab \|.*?\n(?:\|.*\n)+", readme, re.M)
if not table:
    sys.exit("export-student: README.md has no lab table (| Lab | ...) for the student README")
text = sys.stdin.read().replace("@LAB_TABLE@", table.group(0).rstrip())
text = re.sub(r"^@SECTION (.+)@$", lambda m: section(m.group(1)).rstrip(), text, flags=re.M)
sys.stdout.write(text)' "$out/README.md.instructor" >"$out/README.md"
  rm "$out/README.md.instructor"
  echo "export-student: wrote $(cd "$out" && find . -type f | wc -l) files to $out (the committed tree, $(git rev-parse --short HEAD))"
fi

# A leak is three consecutive code lines of a solution file (blank lines and comments skipped), one
# of them at least 24 characters long, that appear in the same order in an exported file, unless the
# lab's own stub folder has them too (the signatures and includes the stubs share). /usr/bin/python3 is there: the build needs python3-glad.
/usr/bin/python3 - "$root" "$out" "${INSTRUCTOR[@]}" <<'PY'
import pathlib, sys
root, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
def code(path):
    lines = []
    for raw in path.read_text(errors="replace").splitlines():
        t = raw.strip()
        if t and not t.startswith("//"):
            lines.append(t)
    return lines
windows = {}
for sol in (root / "solutions").rglob("*"):
    if not sol.is_file():
        continue
    lab = root / "labs" / sol.relative_to(root / "solutions").parts[0]
    public = set()
    for f in lab.rglob("*"):
        if f.is_file() and f.suffix in (".cpp", ".hpp", ".glsl", ".vert", ".frag", ".geom", ".comp", ".md"):
            public.update(code(f))
    c = code(sol)
    for i in range(len(c) - 2):
        w = tuple(c[i:i + 3])
        # Three lines of bare structure ("EmitVertex();", "}", "EndPrimitive();") tell nothing.
        if max(len(line) for line in w) >= 24 and not all(line in public for line in w):
            windows[w] = sol.relative_to(root)
leaks = 0
for path in sys.argv[3:]:  # INSTRUCTOR: answers, the grader and the instructor docs
    if (out / path).exists():
        print(f"export-student: LEAK: the export has {path}, which is for instructors only", file=sys.stderr)
        leaks += 1
for f in out.rglob("*"):
    if not f.is_file() or f.suffix in (".png", ".pfm", ".csv"):
        continue
    c = code(f)
    for i in range(len(c) - 2):
        src = windows.get(tuple(c[i:i + 3]))
        if src:
            print(f"export-student: LEAK: {f.relative_to(out)} line {i} repeats {src}: {c[i]}", file=sys.stderr)
            leaks += 1
            break
sys.exit(1 if leaks else 0)
PY
echo "export-student: no solution content in $out"
