#!/usr/bin/env bash
# Writes the student edition of the workbook: ./workbook export-student DIR
# It is the repository minus what would give answers away: solutions/, the mutants (they quote
# solution lines) and instructor-only tests (tests/hidden/). Golden data and handouts stay.
# --verify DIR proves that an exported folder holds no solution content (see the rule below), and
# exits 1 naming each leak.
set -euo pipefail
verify=0
if [ "${1:-}" = "--verify" ]; then verify=1; shift; fi
[ $# -eq 1 ] || { echo "usage: $0 [--verify] DIR" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "$1" && cd "$1" && pwd)
[ -d "$root/solutions" ] || { echo "export-student: this copy has no solutions/; it is a student edition already" >&2; exit 2; }
if [ "$verify" = 0 ]; then
  [ -n "$(ls -A "$out" 2>/dev/null)" ] && { echo "export-student: $out is not empty" >&2; exit 2; }
  cd "$root"
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files)
  else  # an exported copy has no git history; take every file outside the build folders
    files=$(find . -type f ! -path './build*' ! -path './.git/*' | sed 's|^\./||')
  fi
  echo "$files" | grep -Ev '^(solutions/|tests/mutants/|tests/hidden/)' | while read -r f; do
    [ -f "$f" ] || continue
    mkdir -p "$out/$(dirname "$f")"
    cp -p "$f" "$out/$f"
  done
  echo "export-student: wrote $(cd "$out" && find . -type f | wc -l) files to $out"
fi

# A leak is three consecutive code lines of a solution file (blank lines and comments skipped) that
# appear, in the same order, in an exported file, unless the lab's own stub folder has them too (the
# signatures and includes the stubs share). /usr/bin/python3 is there: the build needs python3-glad.
/usr/bin/python3 - "$root" "$out" <<'PY'
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
        if f.is_file() and f.suffix in (".cpp", ".hpp", ".glsl", ".vert", ".frag", ".md"):
            public.update(code(f))
    c = code(sol)
    for i in range(len(c) - 2):
        w = tuple(c[i:i + 3])
        if not all(line in public for line in w):
            windows[w] = sol.relative_to(root)
leaks = 0
if (out / "solutions").exists():
    print("export-student: LEAK: the export has a solutions/ folder", file=sys.stderr); leaks += 1
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
