#!/usr/bin/env python3
"""The synthetic class can be made for every lab alone (`./workbook make-submissions DIR --labs NN`):
labs without a C++ exercise (03, 07) used to crash it, and a C++ exercise whose solution is one line
(04.4) had no body it could break. Each class has the whole submission and the stubs; where the lab
has an exercise of a kind, the faults of that kind are planted inside that exercise's function."""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAKE = ROOT / "tests/grading/make_submissions.py"
failures = []

for manifest in sorted((ROOT / "labs").glob("[0-9][0-9]_*/exercises.json")):
    lab, nn = manifest.parent.name, manifest.parent.name[:2]
    exercises = json.loads(manifest.read_text())["exercises"]
    cpp = next((e for e in exercises if e["file"].endswith(".cpp")), None)
    glsl = next((e for e in exercises if e["file"].endswith(".glsl")), None)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "class"
        proc = subprocess.run([sys.executable, "-B", str(MAKE), str(out), "--labs", nn], capture_output=True, text=True)
        if proc.returncode != 0:
            failures.append(f"lab {nn}: make_submissions failed:\n{proc.stderr[-800:]}")
            continue
        expected = json.loads((out / "expected.json").read_text())
        want = {"full", "stubs", "archive"} | ({"compile_error", "segfault"} if cpp else set()) \
            | ({"endless_loop_glsl"} if glsl else set())
        if want - set(expected):
            failures.append(f"lab {nn}: the class lacks {sorted(want - set(expected))}")
        if cpp and "compile_error" in expected:
            text = (out / "compile_error" / "labs" / lab / cpp["file"]).read_text()
            chunk = text[text.index(f"// EXERCISE {cpp['id']}"):]
            body = chunk[chunk.index("{", chunk.index(")")):]
            if not body.startswith("{\n  this is not C++;"):
                failures.append(f"lab {nn}: compile_error's fault is not in {cpp['id']}'s body:\n{chunk[:300]}")
            if cpp["id"] not in expected["compile_error"]["lost"]:
                failures.append(f"lab {nn}: compile_error does not expect {cpp['id']} lost: {expected['compile_error']}")
        print(f"lab {nn}: {len(expected)} submissions")

for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
