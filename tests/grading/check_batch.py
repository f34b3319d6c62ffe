#!/usr/bin/python3
"""Holds a graded batch of synthetic submissions (tools/make_submissions.py) against what each should
get: usage check_batch.py SUBMISSIONS_DIR GRADES_DIR. Exit 0 when every check passes."""
import csv
import json
import sys
from pathlib import Path

subs, grades = Path(sys.argv[1]), Path(sys.argv[2])
expected = json.loads((subs / "expected.json").read_text())
problems = []


def check(cond, what):
    if not cond:
        problems.append(what)


# The reason each broken submission must give for the exercise it loses.
reasons = {"compile_error": "does not compile", "segfault": "SIGSEGV", "endless_loop_cpp": "timed out",
           "endless_loop_glsl": ("timed out", "WRONG"),  # llvmpipe ends any shader loop after 65535 turns
           "one_wrong": "WRONG", "stubs": "NOT IMPLEMENTED", "archive": "not in the submission",
           "endless_build": "the build timed out after"}

rows = {r["student"]: r for r in csv.DictReader(open(grades / "gradebook.csv"))}
check(sorted(rows) == sorted(expected), f"the gradebook lists {sorted(rows)}, expected every submission: "
      f"{sorted(expected)}")
for name, want in expected.items():
    results_file = grades / name / "results.json"
    check(results_file.exists(), f"{name}: no results.json")
    if not results_file.exists():
        continue
    res = json.loads(results_file.read_text())
    # The hidden "Grading environment" test (no points) says how the tests ran; the exercises are the rest.
    exercises = [t for t in res.get("tests", []) if "grading-environment" not in t.get("tags", [])]
    # Gradescope's fields.
    check(isinstance(res.get("score"), (int, float)), f"{name}: results.json has no numeric score")
    check(isinstance(res.get("tests"), list) and res["tests"], f"{name}: results.json has no tests[]")
    for t in res.get("tests", []):
        for field in ("name", "score", "max_score", "status", "output", "visibility"):
            check(field in t, f"{name}: test {t.get('name')} lacks '{field}'")
        check(t.get("status") in ("passed", "failed"), f"{name}: test {t.get('name')} status {t.get('status')}")
        check(t.get("visibility") in ("visible", "hidden", "after_due_date", "after_published"),
              f"{name}: test {t.get('name')} visibility {t.get('visibility')}")
        check(t.get("score", 0) <= t.get("max_score", 0) or t["max_score"] == 0,
              f"{name}: test {t.get('name')} scores above its maximum")
    check(abs(sum(t["score"] for t in res["tests"]) - res["score"]) < 1e-9, f"{name}: tests do not add up to score")
    check(res["score"] == want["score"], f"{name}: score {res['score']}, expected {want['score']}")
    lost = sorted({t["number"] for t in exercises if t["status"] == "failed"})
    check(lost == want["lost"], f"{name}: lost {lost}, expected {want['lost']}")
    # The report says why.
    report = (grades / name / "report.md").read_text() if (grades / name / "report.md").exists() else ""
    if name in reasons:
        said = reasons[name] if isinstance(reasons[name], tuple) else (reasons[name],)
        check(any(r in report for r in said), f"{name}: the report does not say {' or '.join(said)}")
    check((grades / name / "junit.xml").exists(), f"{name}: no junit.xml")
    # The gradebook row adds up and matches.
    row = rows.get(name)
    check(row is not None, f"{name}: no gradebook row")
    if row:
        ids = [k for k in row if k not in ("student", "total", "max")]
        check(abs(sum(float(row[k]) for k in ids) - float(row["total"])) < 1e-9, f"{name}: gradebook row does not add up")
        check(float(row["total"]) == res["score"], f"{name}: gradebook total {row['total']} != {res['score']}")

check((grades / "summary.md").exists(), "no summary.md")
for p in problems:
    print("FAIL:", p)
print(f"{len(expected)} submissions checked: " + ("all as expected" if not problems else f"{len(problems)} problems"))
sys.exit(1 if problems else 0)
