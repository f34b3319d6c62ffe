#!/usr/bin/python3
"""What the grader does when grading one submission goes wrong (ctest -L grading; no build needed):
an exception inside Grader.grade costs only the exercises not graded yet, with the exception as
their reason; an exception that escapes a submission's grading altogether (a time-out, a bug)
becomes a result of 0 with the reason, the batch goes on, every workspace goes back to the pool,
and gradebook.csv and summary.md list every student. The real time-out of a build is held by the
synthetic class (endless_build in tests/grading/make_submissions.py)."""
import csv
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from grader_test_support import check, finish, grade


def exercise_tests(res):
    """results.json's tests less the hidden "Grading environment" one (no points)."""
    return [t for t in res["tests"] if "grading-environment" not in t.get("tags", [])]


class FakeSandbox:
    notes, user, mode = [], "the test's user", "bwrap"

    def protections(self):
        return "a fake sandbox (limits: none)"


class FakeWorkspace:
    """Takes the exercise files and builds nothing."""

    def __init__(self, tmp):
        self.dir = tmp / "w0"
        self.build = self.dir / "build"
        self.submission = self.dir / "submission"

    def reset_to_stubs(self):
        pass

    def fresh_outputs(self):
        pass

    def place(self, lab, rel, content):
        pass

    def after_killed_build(self, labs):
        pass

    def uids(self):
        return set()


class BrokenBuild(grade.Grader):
    """The grader with a fault in its build step: nothing can be graded."""

    def build(self, labs):
        raise RuntimeError("boom in build")

    def untouched(self, lab, files):  # (a lab left as the stubs is not built: this one is built)
        return False


class BrokenSecondLab(grade.Grader):
    """Every build works and every exercise passes, but listing the second lab's tests raises."""

    def build(self, labs):
        return True, ""

    def list_tests(self, lab):
        if lab is self.labs[1]:
            raise KeyError("no tests for you")
        return []

    def grade_exercise(self, lab, e, tests, broken, replay_uses=()):
        return True, [], [], None, False

    def untouched(self, lab, files):  # (the empty submission is not the stubs here: every test passes)
        return False


labs = grade.load_labs(["01", "02"])
points = {e["id"]: e["points"] for lab in labs for e in lab["exercises"]}
lab1 = {e["id"] for e in labs[0]["exercises"]}
with tempfile.TemporaryDirectory(prefix="grader-failures-") as tmp:
    tmp = Path(tmp)
    submission = tmp / "submission"
    (submission / "labs").mkdir(parents=True)
    ws = FakeWorkspace(tmp)

    # 1. A fault before anything is graded: every exercise scores 0 and says why.
    r = BrokenBuild(ws, labs, FakeSandbox(), 20, 1).grade(submission, tmp / "out1", "broken_build")
    res = json.loads((tmp / "out1/results.json").read_text())
    check(r["score"] == 0 and res["score"] == 0, f"1: score {r['score']}/{res['score']}, expected 0")
    check(len(exercise_tests(res)) == len(points),
          f"1: {len(exercise_tests(res))} exercise tests in results.json, expected {len(points)}")
    check(all("the grader failed on this submission: RuntimeError: boom in build" in t["output"]
              for t in exercise_tests(res)), "1: not every exercise gives the grader's failure as its reason")
    check("execution_time" in res, "1: results.json is still the partial one")
    check("the grader failed on this submission" in (tmp / "out1/report.md").read_text(), "1: report.md is silent")
    check(any("RuntimeError" in p for p in r["problems"]), f"1: problems {r['problems']}")

    # 2. A fault half-way: the first lab keeps its points, the second lab's exercises score 0.
    r = BrokenSecondLab(ws, labs, FakeSandbox(), 20, 1).grade(submission, tmp / "out2", "broken_second_lab")
    res = json.loads((tmp / "out2/results.json").read_text())
    want = sum(v for k, v in points.items() if k in lab1 and not any(
        e.get("extension") for l in labs for e in l["exercises"] if e["id"] == k))
    check(res["score"] == want, f"2: score {res['score']}, expected the first lab's {want}")
    lost = sorted({t["number"] for t in exercise_tests(res) if t["status"] == "failed"})
    check(lost == sorted(set(points) - lab1), f"2: lost {lost}, expected the second lab's exercises")
    check(all("KeyError" in t["output"] for t in exercise_tests(res) if t["status"] == "failed"),
          "2: the reason is missing")

    # 3. A batch where grading raises for two of three submissions (one workspace, so a workspace
    # that is not given back stops the third): every student is in the gradebook.
    subs = [tmp / "a_fine", tmp / "b_timeout", tmp / "c_bug"]
    used = []

    def grade_one(w, sub):
        used.append(w)
        if sub.name == "b_timeout":
            raise subprocess.TimeoutExpired(["cmake", "--build"], 20)
        if sub.name == "c_bug":
            raise ValueError("a bug outside Grader.grade")
        return BrokenSecondLab(w, labs, FakeSandbox(), 20, 1).grade(submission, tmp / "batch" / sub.name, sub.name)

    def fail_one(sub, problem, elapsed):
        return grade.salvage(tmp / "batch" / sub.name, sub.name, labs, FakeSandbox(), problem, elapsed)

    results = grade.grade_all(subs, [ws], grade_one, fail_one)
    grade.write_batch_outputs(tmp / "batch", results, labs)
    check([r["name"] for r in results] == ["a_fine", "b_timeout", "c_bug"], f"3: results {[r['name'] for r in results]}")
    check(used == [ws, ws, ws], "3: the workspace did not go back to the pool")
    rows = {row["student"]: row for row in csv.DictReader(open(tmp / "batch/gradebook.csv"))}
    check(sorted(rows) == ["a_fine", "b_timeout", "c_bug"], f"3: gradebook rows {sorted(rows)}")
    check(rows.get("a_fine", {}).get("total") == str(want), "3: a_fine lost its points")
    for name, reason in (("b_timeout", "TimeoutExpired"), ("c_bug", "ValueError: a bug outside Grader.grade")):
        check(rows.get(name, {}).get("total") == "0", f"3: {name} total {rows.get(name, {}).get('total')}")
        res = json.loads((tmp / "batch" / name / "results.json").read_text())
        check(res["score"] == 0 and all(reason in t["output"] for t in exercise_tests(res)),
              f"3: {name}'s results.json does not say {reason}")
    summary = (tmp / "batch/summary.md").read_text()
    check("c_bug: the grader failed on this submission: ValueError" in summary, "3: summary.md does not name c_bug")

finish("grader failures", "all recorded as expected")
