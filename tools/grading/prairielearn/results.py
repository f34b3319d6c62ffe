#!/usr/bin/python3
"""PrairieLearn's results.json from the grader's (docs/prairielearn.md). The grader writes Gradescope's
format; run_job turns it into PrairieLearn's external-grader result, on every exit path:

  results.py --provisional RESULTS       before grading: a file that says grading did not finish
  results.py --final GRADER RESULTS [total|exercises]
                                         after grading (finish_results.py has completed GRADER's file);
                                         the held-out tests' detail: their points alone, or which
                                         exercises passed them too
  results.py --overlay SRC DEST          the course's copy of the workbook over the image's: writes only
                                         the files whose content differs (make rebuilds only those)
  results.py --arrange STUDENT NN DEST   (in the workbook) the flat upload as a submission of lab NN

PrairieLearn's result: `score` in [0, 1]; `gradable` false only where no exercise was graded (the
grader or the job failed: the student keeps the attempt); `tests` with points, max_points,
output (plain text) and images (data URIs); the whole file under 1 MB. PrairieLearn shows every test
and the score at once, so the held-out tests, which Gradescope hides until the due date, are one test
here: their points and which exercises passed them, never their cases.
"""
import json
import os
import re
import shutil
import sys
from pathlib import Path

MAX_BYTES = 1_000_000  # PrairieLearn's limit on results.json
_PICTURE = re.compile(r"\n*!\[([^\]]*)\]\((data:image/[a-z]+;base64,[A-Za-z0-9+/=]+)\)")
STATUSES = ("done", "wrong", "not implemented", "error")  # (report.status_of)
GRADER_FAULT = "a fault of the grader"
ASK = "Submit again; if it happens again, tell your instructor."


def write(results_dir, doc):
    results_dir.mkdir(parents=True, exist_ok=True)
    tmp = results_dir / "results.json.tmp"
    tmp.write_text(json.dumps(doc, indent=1))
    os.replace(tmp, results_dir / "results.json")  # always a whole, valid file


def plain(markdown):
    """The grader's Markdown as the plain text PrairieLearn shows in a test's output."""
    text = re.sub(r"^```.*$\n?", "", markdown, flags=re.M)
    return re.sub(r"\*\*([^*]+)\*\*|`([^`]+)`", lambda m: m.group(1) or m.group(2), text).strip()


def test_of(t):
    """One visible test of the grader: its text, and its pictures as PrairieLearn's images."""
    out = t.get("output", "")
    images = [{"label": label or "Figure", "url": url} for label, url in _PICTURE.findall(out)]
    status, _, text = plain(_PICTURE.sub("", out)).partition("\n")  # (the grader's first line: its status)
    if status not in STATUSES:
        status, text = t.get("status", ""), plain(_PICTURE.sub("", out))
    if t.get("max_score", 0) == 0 and t.get("score", 0) > 0:
        status += " (an extension: bonus points)"
    return {"name": t["name"], "points": t.get("score", 0), "max_points": t.get("max_score", 0),
            "message": status, "output": text.strip(), "images": images}


def held_out(tests, detail):
    """The held-out tests as one: their points, and (detail "exercises") which exercises passed them.
    The default ("total") names none: PrairieLearn shows it at every attempt, and a list would let a
    student tune code against scenes they were never given."""
    lines = [f"{t['number']}: {'passed' if t.get('status') == 'passed' else 'failed'}" for t in tests]
    return {"name": "Held-out tests", "points": sum(t.get("score", 0) for t in tests),
            "max_points": sum(t.get("max_score", 0) for t in tests),
            "message": "scenes you were not given; their cases are not shown",
            "output": "\n".join(lines) if detail == "exercises" else "", "images": []}


def convert(doc, detail="total"):
    """PrairieLearn's result from the grader's finished (or completed) Gradescope results.json."""
    tests = [t for t in doc.get("tests", []) if "grading-environment" not in t.get("tags", [])]
    shown = [test_of(t) for t in tests if t.get("visibility", "visible") == "visible"]
    later = [t for t in tests if t.get("visibility", "visible") != "visible"]
    if later:
        shown.append(held_out(later, detail))
    maximum = doc.get("extra_data", {}).get("max_score") or sum(t["max_points"] for t in shown)
    earned = sum(t["points"] for t in shown)
    bonus = sum(t["points"] for t in shown if t["max_points"] == 0)
    finished = "execution_time" in doc
    # Graded: an exercise that has a result of the submission's own, not a fault of the grader's
    # (grader.py and batch.salvage say "a fault of the grader" in those).
    graded = [t for t in tests if t.get("number") and GRADER_FAULT not in t.get("output", "")]
    points = f"{earned - bonus:g} of {maximum:g} points" + (f" and {bonus:g} bonus points from extensions" if bonus else "")
    if finished:
        message = points + "." + "".join(f" {plain(n)}" for n in re.findall(r"\*\*Note:\*\*[^\n]*", doc.get("output", "")))
    else:
        why = re.search(r"Grading did not finish: (.*?)(?:\. The \d+ exercises|, before any exercise|\.\s|$)",
                        doc.get("output", ""))
        why = why.group(1) if why else "the grader stopped"
        message = (f"Grading stopped before the end ({why}): {points} from the {len(graded)} exercise"
                   f"{'s' * (len(graded) != 1)} graded before that; the others score 0. {ASK}" if graded else
                   f"Grading did not finish ({why}), before any exercise was graded: this attempt does not count. {ASK}")
    result = {"gradable": bool(graded), "score": min(1.0, earned / maximum) if maximum else 0.0,
              "message": message, "output": "", "tests": shown}
    if not result["gradable"]:  # (nothing graded, through no fault of the code: the attempt is kept)
        result["format_errors"] = [message]
    return fit(result)


def fit(result):
    """Drops pictures, the last first, until the file is under PrairieLearn's 1 MB."""
    pictures = [t["images"] for t in result["tests"] if t["images"]]
    while len(json.dumps(result, indent=1)) > MAX_BYTES and pictures:
        pictures[-1].pop()
        if not pictures[-1]:
            pictures.pop()
    return result


def provisional(results_dir):
    write(results_dir, {"gradable": False, "score": 0.0, "message": f"Grading did not finish. {ASK}",
                        "format_errors": [f"Grading did not finish. {ASK}"], "output": "", "tests": []})


def final(grader_dir, results_dir, detail):
    try:
        doc = json.loads((grader_dir / "results.json").read_text())
    except (OSError, ValueError):
        doc = {"output": "Grading did not finish: the grader wrote no results.", "tests": []}
    write(results_dir, convert(doc, detail))


def arrange(student, lab, dest):
    """The flat upload (pl-file-upload's files) laid out as a submission of `lab` (NN) in `dest`: each
    of the lab's exercise files at labs/NN_name/<its path>, as the grader looks for it."""
    manifest = next(Path("labs").glob(f"{lab}_*/exercises.json"))
    for rel in sorted({e["file"] for e in json.loads(manifest.read_text())["exercises"]}):
        src = student / Path(rel).name
        if src.is_file() and not src.is_symlink():
            target = dest / "labs" / manifest.parent.name / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(src, target)


def overlay(src, dest):
    """Copies src over dest, writing only the files whose content differs; returns how many it wrote
    of the instructor material (tools/grading/instructor_paths.txt), and how many others."""
    secret = [l.strip() for l in (src / "tools/grading/instructor_paths.txt").read_text().splitlines()
              if l.strip() and not l.startswith("#")]
    written = [0, 0]
    for folder, _, names in os.walk(src):
        target = dest / Path(folder).relative_to(src)
        target.mkdir(parents=True, exist_ok=True)
        for n in names:
            s, d = Path(folder) / n, target / n
            if s.is_symlink() or not s.is_file():
                continue
            if not d.is_file() or d.stat().st_size != s.stat().st_size or d.read_bytes() != s.read_bytes():
                shutil.copyfile(s, d)
                rel = d.relative_to(dest).as_posix()
                written[not any(rel == p or rel.startswith(p + "/") for p in secret)] += 1
            os.chmod(d, 0o644 | (s.stat().st_mode & 0o111))
    return written


def main():
    args = sys.argv[1:]
    if len(args) == 2 and args[0] == "--provisional":
        provisional(Path(args[1]))
    elif len(args) in (3, 4) and args[0] == "--final":
        final(Path(args[1]), Path(args[2]), args[3] if len(args) == 4 else "total")
    elif len(args) == 3 and args[0] == "--overlay":
        print(*overlay(Path(args[1]), Path(args[2])))
    elif len(args) == 4 and args[0] == "--arrange":
        arrange(Path(args[1]), args[2], Path(args[3]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
