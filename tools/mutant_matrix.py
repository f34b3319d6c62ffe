#!/usr/bin/python3
"""The mutant matrix: every mutant (tests/mutants/NN_name/*.mutant, a solution with one mistake) run
as its ctest test does (label mutants: its exercise's tests with --expect-mistake and --expect-hint),
tallied per lab: caught as WRONG, the hint right (its own, or none where none is recorded), wrong
hints, and how many mutants each exercise has. Usage: tools/mutant_matrix.py BUILD_DIR [--jobs N]"""
import json
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    build = sys.argv[1]
    jobs = sys.argv[sys.argv.index("--jobs") + 1] if "--jobs" in sys.argv else "2"
    out = subprocess.run(["ctest", "--test-dir", build, "-L", "mutants", "-j", jobs, "-V"],
                         capture_output=True, text=True).stdout
    names = dict(re.findall(r"^(\d+): Test command: .*$\n(?:.*\n)*?.*Test #\1: (\S+)", out, re.M))
    names.update({n: t for n, t in re.findall(r"Test +#(\d+): (\S+)", out)})
    verdicts = {names.get(n, n): v for n, v in re.findall(r"^(\d+): (mutant of .*)$", out, re.M)}
    per_lab = defaultdict(lambda: {"mutants": 0, "caught": 0, "hint_right": 0, "hinted": 0, "wrong_hints": 0})
    for test, line in sorted(verdicts.items()):
        lab = test.split(".")[1]
        row = per_lab[lab]
        row["mutants"] += 1
        row["caught"] += "caught as WRONG" in line
        row["hint_right"] += "hint right" in line
        row["hinted"] += "hint none" not in line
        row["wrong_hints"] += "hint WRONG" in line
        if "caught as WRONG" not in line or "hint right" not in line and "hint none" not in line:
            print(f"  {test}: {line}")
    print("| lab | mutants | caught as WRONG | own hint | no hint (none recorded) | wrong hints |")
    print("|---|---|---|---|---|---|")
    for lab, r in sorted(per_lab.items()):
        n = r["mutants"]
        print(f"| {lab} | {n} | {r['caught']} ({100 * r['caught'] // max(n, 1)}%) | {r['hint_right']} | "
              f"{n - r['hinted']} | {r['wrong_hints']} |")
    print("\nMutants per exercise (the aim is three or more):")
    for lab_dir in sorted((ROOT / "labs").glob("[0-9][0-9]_*")):
        count = defaultdict(int)
        for m in (ROOT / "tests/mutants" / lab_dir.name).glob("*.mutant"):
            ex = re.search(r"^exercise: ?(\S+)", m.read_text(), re.M)
            count[ex.group(1) if ex else "?"] += 1
        ids = [e["id"] for e in json.loads((lab_dir / "exercises.json").read_text())["exercises"]]
        print(f"  {lab_dir.name}: " + ", ".join(f"{i} {count.get(i, 0)}" for i in ids))
    total = sum(r["mutants"] for r in per_lab.values())
    missing = sum(r["hinted"] - r["hint_right"] - r["wrong_hints"] for r in per_lab.values())
    bad = sum(r["mutants"] - r["caught"] + r["wrong_hints"] for r in per_lab.values()) + missing
    print(f"\n{total} mutants run; " + ("all caught, each with its own hint or none, no wrong hint" if not bad
                                        else f"{bad} not caught, wrongly hinted, or missing their recorded hint"))
    return 1 if bad or not total else 0


if __name__ == "__main__":
    sys.exit(main())
