#!/usr/bin/python3
"""`check` names each known mistake: usage hints_test.py BUILD_DIR. For every value that
tests/hints/NN_name.json records for a mutant (tools/make_hints.py), the mutant's own check must
print that mutant's hint. Fails when the hints are stale (a test or mutant changed since they were
recorded: run tools/make_hints.py BUILD_DIR) or when the matching in tests/harness/diagnosis.cpp
breaks."""
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from make_hints import mutant_command  # noqa: E402  (how each mutant's tests are run)
build = Path(sys.argv[1])
problems, checked = [], 0
for hints_file in sorted((ROOT / "tests/hints").glob("*.json")):
    lab = hints_file.stem
    by_mutant = {}
    for h in json.loads(hints_file.read_text())["hints"]:
        by_mutant.setdefault(h["mutant"], h)
    for mutant in sorted((ROOT / "tests/mutants" / lab).glob("*.mutant")):
        h = by_mutant.get(mutant.stem)
        if h is None:
            print(f"note: {lab}/{mutant.stem} gives no value to recognise it by (no hint)")
            continue
        exe, env = mutant_command(build, mutant)
        out = subprocess.run([str(exe), f"--gtest_filter=*Ex{h['exercise'].replace('.', '_')}_*", "--check"],
                             capture_output=True, text=True, timeout=600, env=env).stdout
        checked += 1
        # (where several mistakes give the same value, check lists them all, one "- hint" line each)
        if f"looks like a known mistake: {h['hint']}" not in out and f"- {h['hint']}" not in out:
            problems.append(f"{lab}/{mutant.stem}: check does not name it (stale hints? run tools/make_hints.py "
                            f"{build}):\n{out[-1500:]}")
    readme = (ROOT / "labs" / lab / "README.md").read_text()
    for h in by_mutant.values():
        if h["hint"] not in readme:
            problems.append(f"labs/{lab}/README.md: its Common mistakes section lacks '{h['hint']}' (run "
                            f"tools/make_hints.py {build})")
for p in problems:
    print("FAIL:", p)
print(f"{checked} mutants: " + ("each named by check" if not problems else f"{len(problems)} not named"))
sys.exit(1 if problems or not checked else 0)
