#!/usr/bin/python3
"""OpenGL 4.1 core is macOS's ceiling, and the workbook's target (issue 28). This lists what the
tracked sources still use beyond it, per file:
  - entry points that 4.5 core has and 4.1 core lacks (glCreateTextures, glDispatchCompute, ...),
    found by generating both loaders with glad 2 (python3-glad) and comparing their functions;
  - shaders, and GLSL in C++ strings, that say #version 420 to 460.
A line that says "gl41-optional" is not counted: it runs only where a check found the feature.
It fails when a file uses more than tools/gl41_baseline.json allows, so the migration only goes
down; a file not in the baseline allows none. When a change removes uses, --write-baseline records
the new counts (and refuses to record a rise; without a baseline it records the first one).

Usage: tools/gl41_check.py [--write-baseline] [--list]
  --list  every use, file:line: name
"""
import json
import re
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = ROOT / "tools/gl41_baseline.json"
SOURCES = ("common", "labs", "solutions", "tests", "tools", "shaders")
SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".glsl", ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"}
VERSION = re.compile(r"#\s*version\s+4[2-6]0\b")


def core_functions(version, out):
    """The functions of glad's loader for `version` core with no extension."""
    subprocess.run(["/usr/bin/python3", "-m", "glad", "--quiet", "--api", f"gl:core={version}", "--extensions", "",
                    "--out-path", str(out), "--reproducible", "c"], check=True, capture_output=True)
    text = (out / "include/glad/gl.h").read_text()
    return set(re.findall(r"^#define (gl[A-Z]\w*) glad_gl", text, re.M))


def beyond_41():
    with tempfile.TemporaryDirectory() as tmp:
        return core_functions("4.5", Path(tmp) / "45") - core_functions("4.1", Path(tmp) / "41")


def uses(names):
    """(file, line, what) for every use in the tracked sources."""
    listed = subprocess.run(["git", "ls-files", "--", *SOURCES], cwd=ROOT, capture_output=True, text=True)
    files = listed.stdout.split() if listed.returncode == 0 else [  # (the student edition is no git checkout)
        str(p.relative_to(ROOT)) for d in SOURCES for p in sorted((ROOT / d).rglob("*"))]
    call = re.compile(r"\b(" + "|".join(sorted(names, key=len, reverse=True)) + r")\s*\(")
    found = []
    for name in files:
        path = ROOT / name
        if path.suffix not in SUFFIXES or not path.is_file():
            continue
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if "gl41-optional" in line:  # used only where the context has it, behind a check
                continue
            found += [(name, n, m.group(1)) for m in call.finditer(line)]
            found += [(name, n, "#version " + m.group(0).split()[-1]) for m in VERSION.finditer(line)]
    return found


def main():
    argv = sys.argv[1:]
    if any(a not in ("--write-baseline", "--list") for a in argv):
        sys.exit(__doc__)
    found = uses(beyond_41())
    counts = Counter(f for f, _, _ in found)
    if "--list" in argv:
        for f, n, what in found:
            print(f"{f}:{n}: {what}")
    allowed = json.loads(BASELINE.read_text()) if BASELINE.exists() else {}
    over = {f: (c, allowed.get(f, 0)) for f, c in counts.items() if c > allowed.get(f, 0)}
    kinds = Counter(w if w.startswith("#") else "entry point" for _, _, w in found)
    print(f"gl41_check: {len(found)} uses beyond OpenGL 4.1 core in {len(counts)} files "
          f"({kinds['entry point']} entry points, {len(found) - kinds['entry point']} #version 420+ lines); "
          f"the baseline allows {sum(allowed.values())}")
    for f, (c, a) in sorted(over.items()):
        lines = ", ".join(f"{n}: {w}" for g, n, w in found if g == f)
        print(f"  MORE THAN ALLOWED: {f} has {c}, allowed {a} ({lines})")
    if "--write-baseline" in argv:
        if over and BASELINE.exists():
            sys.exit("gl41_check: not recording a rise; remove the new uses (OpenGL 4.1 core is the target)")
        BASELINE.write_text(json.dumps(dict(sorted(counts.items())), indent=1) + "\n")
        print(f"gl41_check: wrote {BASELINE.relative_to(ROOT)}")
        return 0
    if over:
        print("gl41_check: new code must stay within OpenGL 4.1 core (macOS's ceiling): bind to edit instead "
              "of direct state access, no compute, no #version above 410")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
