#!/usr/bin/python3
"""The mutant matrix: every mutant (tests/mutants/NN_name/*.mutant, a solution with one mistake) run
as its ctest test runs it (label mutants: --expect-mistake and --expect-hint), tallied per lab: caught
as WRONG, attributed (no other exercise marked wrong), the hint right (its own, or none where none is
recorded), wrong hints, and how many mutants each exercise has.

Usage: tools/authoring/mutant_matrix.py BUILD_DIR [--jobs N] [--whole-lab] [--labs 01,09] [--only NAME,NAME]
  --whole-lab  runs every test of the mutant's lab, not only its exercise's, so that attribution means
               something: a mistake in 09.1 may block 09.3 (an ERROR that says so) but never make it
               WRONG. Several minutes per lab on 2 cores; ctest -L mutants runs the exercise's tests only.
  --only       the mutants of these names (file names without .mutant) alone.
"""
import json
import re
import subprocess
import sys
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools" / "authoring"))
from make_hints import fields_of, mutant_command  # (one way to run a mutant)


def recorded_hint(mutant):
    """The hint ctest expects (cmake/Lab.cmake): the first comment line, if make_hints.py recorded it."""
    hints = ROOT / "tests/hints" / f"{mutant.parent.name}.json"
    recorded = hints.exists() and any(h["mutant"] == mutant.stem for h in json.loads(hints.read_text())["hints"])
    return fields_of(mutant)[1] if recorded else ""


def run(build, mutant, whole_lab):
    fields, _ = fields_of(mutant)
    exe, env = mutant_command(build, mutant)
    args = [str(exe), "--expect-mistake", fields["exercise"], "--expect-hint", recorded_hint(mutant)]
    if not whole_lab:
        args.append(f"--gtest_filter=*Ex{fields['exercise'].replace('.', '_')}_*")
    if not exe.exists():
        return f"NOT BUILT ({exe.name})"
    try:
        out = subprocess.run(args, capture_output=True, text=True, env=env, timeout=900).stdout
    except subprocess.TimeoutExpired:
        return "NOT CAUGHT (timed out)"
    line = re.search(r"^mutant of .*$", out, re.M)
    return line.group(0) if line else "NOT CAUGHT (no verdict printed)"


def main():
    argv = sys.argv[1:]
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    build = Path(argv[0]).resolve()
    jobs = int(argv[argv.index("--jobs") + 1]) if "--jobs" in argv else 2
    labs = argv[argv.index("--labs") + 1].split(",") if "--labs" in argv else []
    whole_lab = "--whole-lab" in argv
    only = argv[argv.index("--only") + 1].split(",") if "--only" in argv else []
    mutants = [m for m in sorted((ROOT / "tests/mutants").glob("*/*.mutant"))
               if (not labs or m.parent.name[:2] in labs) and (not only or m.stem in only)]
    if only and len(mutants) != len(only):
        sys.exit(f"--only: {len(only)} names, {len(mutants)} mutants found in tests/mutants")
    with ThreadPoolExecutor(jobs) as pool:
        lines = list(pool.map(lambda m: run(build, m, whole_lab), mutants))
    per_lab = defaultdict(lambda: defaultdict(int))
    for mutant, line in zip(mutants, lines):
        row = per_lab[mutant.parent.name]
        row["mutants"] += 1
        row["caught"] += "caught as WRONG" in line
        row["attributed"] += "no other exercise marked wrong" in line
        row["hint_right"] += "hint right" in line
        row["hint_none"] += "hint none" in line
        row["wrong_hints"] += "hint WRONG" in line
        row["missing"] += "hint MISSING" in line
        ok = "caught as WRONG" in line and "no other exercise" in line and ("hint right" in line or "hint none" in line)
        row["bad"] += not ok
        if not ok:
            print(f"  {mutant.parent.name}/{mutant.stem}: {line}")
    print(f"\n{'Whole lab' if whole_lab else 'Each mutant against its own exercise tests'}:\n")
    print("| lab | mutants | caught as WRONG | attributed | own hint | no hint (none recorded) | wrong hints |")
    print("|---|---|---|---|---|---|---|")
    for lab, r in sorted(per_lab.items()):
        n = max(r["mutants"], 1)
        print(f"| {lab} | {r['mutants']} | {r['caught']} ({100 * r['caught'] // n}%) | "
              f"{r['attributed']} ({100 * r['attributed'] // n}%) | {r['hint_right']} | {r['hint_none']} | "
              f"{r['wrong_hints']} |")
    print("\nMutants per exercise (the aim is three or more):")
    for lab_dir in sorted((ROOT / "labs").glob("[0-9][0-9]_*")):
        if labs and lab_dir.name[:2] not in labs:
            continue
        count = defaultdict(int)
        for m in (ROOT / "tests/mutants" / lab_dir.name).glob("*.mutant"):
            count[fields_of(m)[0].get("exercise", "?")] += 1
        ids = [e["id"] for e in json.loads((lab_dir / "exercises.json").read_text())["exercises"]]
        print(f"  {lab_dir.name}: " + ", ".join(f"{i} {count.get(i, 0)}" for i in ids))
    total = sum(r["mutants"] for r in per_lab.values())
    bad = sum(r["bad"] for r in per_lab.values())
    print(f"\n{total} mutants run; " + ("all caught and attributed, each with its own hint or none, no wrong hint"
                                        if not bad else f"{bad} not caught, misattributed or wrongly hinted"))
    return 1 if bad or not total else 0


if __name__ == "__main__":
    sys.exit(main())
