#!/usr/bin/python3
"""The known mistakes that `check` names (tests/hints/NN_name.json, recorded from the mutants by
tools/authoring/make_hints.py) are in the handouts and belong to mutants that exist: usage hints_test.py
BUILD_DIR. Whether check names each mutant's own mistake, and never another's, is each mutant's
ctest test (mutant.labNN.NAME runs its exercise with --expect-mistake and --expect-hint, cmake/Lab.cmake):
a stale hint fails there (run tools/authoring/make_hints.py BUILD_DIR)."""
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
problems, checked = [], 0
for hints_file in sorted((ROOT / "tests/hints").glob("*.json")):
    lab = hints_file.stem
    hints = json.loads(hints_file.read_text())["hints"]
    readme = (ROOT / "labs" / lab / "README.md").read_text()
    for h in hints:
        checked += 1
        if not (ROOT / "tests/mutants" / lab / f"{h['mutant']}.mutant").is_file():
            problems.append(f"{hints_file.name}: a hint of mutant {h['mutant']}, which tests/mutants/{lab} no longer has "
                            f"(run tools/authoring/make_hints.py {sys.argv[1] if len(sys.argv) > 1 else 'BUILD_DIR'})")
        if h["hint"] not in readme:
            problems.append(f"labs/{lab}/README.md: its Common mistakes section lacks '{h['hint']}' (run "
                            "tools/authoring/make_hints.py BUILD_DIR)")
for p in problems:
    print("FAIL:", p)
print(f"{checked} recorded hints: " + ("each in its handout, each of a mutant" if not problems else f"{len(problems)} problems"))
sys.exit(1 if problems or not checked else 0)
