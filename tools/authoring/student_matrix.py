#!/usr/bin/python3
"""The mutant matrix in the student edition: every mutant (tests/mutants/NN_name/*.mutant, a solution
with one mistake) handed in to `./workbook check NN` of an exported edition, as a student who got one
thing wrong would run it. There the judge is the student's own build and every scene is drawn with the
student's own shaders, so this is where a mistake could spill into other exercises.

Usage: tools/authoring/student_matrix.py EXPORT [--labs 02,07] [--only NAME,NAME] [--prepare] [--log FILE]
       tools/authoring/student_matrix.py --from-log FILE   (judges an earlier run's log again)
  EXPORT     a folder written by ./workbook export-student.
  --prepare  first copies the solutions into EXPORT/labs (a student with every exercise right) and
             builds it; without it, EXPORT must hold them already. Each lab is checked unmutated
             first: it must pass whole, or its mutants would prove nothing.
  --log FILE every mutant's check output, one after another.

Per mutant it reads check's table: caught (the mutant's exercise is "wrong"), attributed (no other
exercise "wrong" or "error", but for "blocked by" the mutant's exercise where the edition cannot
check another without the reference: a GLSL function that calls the wrong one), the hint (its recorded one from tests/hints, or none where none is
recorded), and the summary's count, which must be what the grader gives the same files: every exercise
but the mutant's (the grader draws each exercise's scenes with the reference for the others), less
those blocked, which the summary must name as not known yet. The
files are put back after each mutant, also when the run is stopped.
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools" / "authoring"))
from make_hints import fields_of, replacements  # (one reader of .mutant files)
from mutant_matrix import recorded_hint  # (the hint ctest expects, the same here)

STATUS = re.compile(r"^  (\d\d\.(?:[0-9x]|H\d))\s+(passes its tests|passes own tests|waiting|not implemented|error|wrong)\s")
SUMMARY = re.compile(r"^  (\d+) of (\d+) exercises pass their tests", re.M)


def check(export, nn, timeout=600):
    """./workbook check NN in EXPORT: (its output, seconds)."""
    start = time.monotonic()
    # (a session of its own: past the timeout the judge and the runners go too, not only the workbook)
    proc = subprocess.Popen(["./workbook", "check", nn], cwd=export, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out = proc.communicate()[0] + f"\n[student_matrix: check ran past {timeout} s]"
    return out, time.monotonic() - start


def table(out):
    """{id: (status, [lines below it])} and the summary (passing, total) from check's output."""
    rows, current = {}, None
    for line in out.splitlines():
        m = STATUS.match(line)
        if m:
            current = m.group(1)
            rows[current] = (m.group(2), [])
        elif current and line.startswith("        "):
            rows[current][1].append(line.strip())
        else:
            current = None
    s = SUMMARY.search(out)
    return rows, ((int(s.group(1)), int(s.group(2))) if s else None)


def judge(mutant, out):
    """One mutant's row: caught, attributed, hint (right / none / WRONG / MISSING), score right."""
    exercise = fields_of(mutant)[0]["exercise"]
    rows, summary = table(out)
    status, lines = rows.get(exercise, ("missing", []))
    # "blocked by" the mutant's exercise: where the edition cannot check another exercise without the
    # reference (a GLSL function that calls the wrong one); its points are then not known, and the
    # summary says so. Anything else marked wrong or error is a mistake put on the wrong exercise.
    blocked = {i for i, (s, ls) in rows.items()
               if i != exercise and s == "error" and ls and ls[0].startswith(f"ERROR: blocked by {exercise}")}
    others = {i: s for i, (s, _) in rows.items() if i != exercise and s in ("wrong", "error") and i not in blocked}
    shown = []  # each hint line: [X] for "looks like a known mistake: X", the options of "one of these:"
    for k, line in enumerate(lines):
        if line.startswith("looks like a known mistake: "):
            shown.append([line.split(":", 1)[1].strip()])
        elif line.startswith("looks like a known mistake, one of these:"):
            shown.append([o[2:].strip() for o in lines[k + 1:k + 9] if o.startswith("- ")])
    want = recorded_hint(mutant)
    if want:  # (right: every hint line names the mutant's own, alone or among options of the same value)
        hint = "right" if shown and all(want in options for options in shown) else ("WRONG" if shown else "MISSING")
    else:
        hint = "WRONG" if shown else "none"
    waiting = {i for i, (s, _) in rows.items() if i != exercise and s == "waiting"}  # (scenes alone, not known yet)
    score = summary is not None and summary[0] + len(blocked) + len(waiting) == summary[1] - 1 and \
        (not blocked or "cannot be checked before that one passes" in out)
    return {"caught": status == "wrong", "attributed": status == "wrong" and not others, "hint": hint,
            "score": score, "status": status, "others": others, "shown": shown, "summary": summary,
            "blocked": blocked}


def mutate(export, mutant):
    """Applies the mutant to EXPORT/labs/NN/FILE; returns (path, original text)."""
    fields, _ = fields_of(mutant)
    path = export / "labs" / mutant.parent.name / fields["file"]
    original = text = path.read_text()
    for find, replace in replacements(mutant):
        if text.count(find) != 1:
            raise SystemExit(f"{mutant}: '{find}' is not in {path} exactly once (is EXPORT filled with the solutions?)")
        text = text.replace(find, replace)
    path.write_text(text)
    return path, original


def prepare(export):
    for lab in sorted((ROOT / "solutions").glob("[0-9][0-9]_*")):
        shutil.copytree(lab, export / "labs" / lab.name, dirs_exist_ok=True)
    subprocess.run(["./workbook", "build"], cwd=export, check=True, stdout=subprocess.DEVNULL)


def print_table(per_lab, rows):
    for name, r in rows:
        if not (r["caught"] and r["attributed"] and r["hint"] in ("right", "none") and r["score"]):
            print(f"  {name}: {r['status']}; others {r['others'] or 'none'}; hint {r['hint']} {r['shown']};"
                  f" summary {r['summary']}")
    keys = ("mutants", "caught", "attributed", "blocked", "score", "right", "none", "WRONG", "MISSING")
    print("\n| lab | mutants | caught | attributed | of which another is blocked by it | score = grader's |"
          " own hint | no hint (none recorded) | wrong hints | hints missing | median check (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    total = defaultdict(int)
    for lab, t in sorted(per_lab.items()):
        times = sorted(t.pop("times"))
        print(f"| {lab} | " + " | ".join(str(t[k]) for k in keys) + f" | {times[len(times) // 2]:.0f} |")
        for k, v in t.items():
            total[k] += v
    print("| all | " + " | ".join(str(total[k]) for k in keys) + " | |")
    return total


def checked_mutants(export, mutants, log):
    """Hands each mutant in to check: yields (mutant, check's output, seconds)."""
    for nn in sorted({m.parent.name[:2] for m in mutants}):
        out, _ = check(export, nn)
        summary = table(out)[1]
        if not summary or summary[0] != summary[1]:
            print(out)
            sys.exit(f"lab {nn}: the unmutated solutions do not pass check in {export} ({summary})")
    for mutant in mutants:
        path, original = mutate(export, mutant)
        try:
            out, seconds = check(export, mutant.parent.name[:2])
        finally:
            path.write_text(original)
        if log:
            log.write(f"\n===== {mutant.parent.name}/{mutant.stem} ({seconds:.0f} s)\n{out}")
            log.flush()
        yield mutant, out, seconds


def logged_mutants(log_file):
    """The same from a --log file of an earlier run (--from-log: judged again, nothing run)."""
    blocks = re.split(r"^===== (\S+)/(\S+) \((\d+) s\)$", Path(log_file).read_text(), flags=re.M)
    for k in range(1, len(blocks) - 3, 4):
        yield ROOT / "tests/mutants" / blocks[k] / f"{blocks[k + 1]}.mutant", blocks[k + 3], float(blocks[k + 2])


def main():
    argv = sys.argv[1:]
    if argv[:1] == ["--from-log"] and len(argv) == 2:
        results = logged_mutants(argv[1])
    else:
        if not argv or argv[0].startswith("-"):
            sys.exit(__doc__)
        export = Path(argv[0]).resolve()
        if (export / "solutions").exists() or not (export / "workbook").exists():
            sys.exit(f"{export}: not a student edition (./workbook export-student DIR writes one)")
        labs = argv[argv.index("--labs") + 1].split(",") if "--labs" in argv else []
        only = argv[argv.index("--only") + 1].split(",") if "--only" in argv else []
        log = open(argv[argv.index("--log") + 1], "w") if "--log" in argv else None
        if "--prepare" in argv:
            prepare(export)
        mutants = [m for m in sorted((ROOT / "tests/mutants").glob("*/*.mutant"))
                   if (not labs or m.parent.name[:2] in labs) and (not only or m.stem in only)]
        results = checked_mutants(export, mutants, log)
    per_lab, rows = defaultdict(lambda: defaultdict(int, times=[])), []
    for mutant, out, seconds in results:
        r = judge(mutant, out)
        rows.append((f"{mutant.parent.name}/{mutant.stem}", r))
        t = per_lab[mutant.parent.name]
        t["mutants"] += 1
        t["times"].append(seconds)
        for key in ("caught", "attributed", "score"):
            t[key] += r[key]
        t["blocked"] += bool(r["blocked"])
        t[r["hint"]] += 1
        print(f"{mutant.parent.name}/{mutant.stem}: {r['status']}, hint {r['hint']}, {seconds:.0f} s", flush=True)
    total = print_table(per_lab, rows)
    ok = all(total[k] == total["mutants"] for k in ("caught", "attributed", "score")) and not total["WRONG"]
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
