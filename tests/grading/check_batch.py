#!/usr/bin/python3
"""Holds a graded batch of synthetic submissions (tests/grading/make_submissions.py) against what each should
get: usage check_batch.py SUBMISSIONS_DIR GRADES_DIR. Exit 0 when every check passes."""
import csv
import json
import os
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
           "endless_loop_glsl": ("timed out", "WRONG"),  # the loop guard ends an exercise's loops after 50000 steps
           "one_wrong": "WRONG", "stubs": "NOT IMPLEMENTED", "archive": "not in the submission",
           "endless_build": "the build timed out after", "forged_report": "NOT IMPLEMENTED",
           "symlink": "is a link", "empty_glsl": "ERROR", "memory_bomb": "used more than 2 GiB of memory",
           "glsl_include_relative": "is not allowed", "glsl_include_deeper": "is not allowed",
           "glsl_include_absolute": "is not allowed", "link_error": "undefined reference to",
           "glsl_endless_same": ("longer than the reference", "timed out"),
           "flood": "the grader kept the first and last 512 KB",
           "supervisor_kill": "its supervisor (wb_check) was stopped"}
root = Path(__file__).resolve().parent.parent.parent

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

# Nothing leaked: no line of a solution file in any student's results, and no result file swollen
# by a submission's output.
def lines_of(folder):
    return {l.strip() for f in folder.rglob("*") if f.is_file() for l in f.read_text(errors="replace").splitlines()
            if len(l.strip()) > 30 and not l.strip().startswith("//")}


# (a line the stubs have too is public: a signature, an include)
solution_lines = lines_of(root / "solutions") - lines_of(root / "labs")
for name in expected:
    results_file = grades / name / "results.json"
    if not results_file.exists():
        continue
    text = results_file.read_text(errors="replace")
    check(len(text) < 1 << 20, f"{name}: results.json is {len(text)} bytes")
    leaked = [l for l in solution_lines if l in text]
    check(not leaked, f"{name}: results.json shows solution code: {leaked[:2]}")
    # The held-out tests and their scenes likewise (leak_secrets throws whatever it could read).
    for mark in ("LEAKED", "HELDOUT ", "REQUEST ", "SMUGGLED", "SNOOPED", '"forged"'):
        check(mark not in text, f"{name}: results.json shows a file its code read: {text[text.find(mark):][:200]}")

# Nothing a runner wrote landed outside its own folders (write_other tries every folder it can reach).
own = ("/tapes/", "/test-output/")  # the runner's own folders (emptied for the next submission)
def named(top, name):
    """Every file called `name` under `top`, not crossing into another mount (a simulator's root in
    build/ may have /proc mounted) and passing over what cannot be read."""
    found = []
    for folder, dirs, files in os.walk(top):
        dirs[:] = [d for d in dirs if not os.path.ismount(os.path.join(folder, d))]
        found += [os.path.join(folder, name)] if name in files else []
    return found


intruded = [p for base in (grades, subs, root) for p in named(base, "WB_INTRUDER")
            if not ("build-grade/w" in p and any(o in p for o in own))]
check(not intruded, f"a runner wrote into folders not its own: {intruded[:5]}")
# No program built from a submission is left to run outside the sandbox by mistake.
programs = [str(p) for p in (root / "build-grade").glob("w*/build/lab[0-9][0-9]*") if p.is_file()]
check(not programs, f"programs built from a submission are left after the batch: {programs[:4]}")
# Nor is anything of theirs left in the shared temporary folders (a .drirc for the judge, a note for
# the next student): the grader sweeps them after each submission.
def sandbox_files(top):
    """Files of uids 61000-61599 in `top` and in the world-writable folders under it."""
    found = []
    for folder, dirs, files in os.walk(top):
        for name in files + dirs:
            try:
                if 61000 <= os.lstat(os.path.join(folder, name)).st_uid < 61600:
                    found.append(os.path.join(folder, name))
            except OSError:
                pass
        dirs[:] = [d for d in dirs if world_writable(os.path.join(folder, d))]
    return found


def world_writable(path):
    try:
        return not os.path.islink(path) and bool(os.lstat(path).st_mode & 0o002)
    except OSError:
        return False


left = [p for top in ("/tmp", "/var/tmp", "/dev/shm") for p in sandbox_files(top)] if os.geteuid() == 0 else []
check(not left, f"files of the sandbox users outlived grading in a shared folder: {left[:5]}")

# Every process a grading run started has ended (the sandbox's users are 61000 and up).
if os.geteuid() == 0:
    left = []
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            lines = status.read_text().splitlines()
            uid = int(next(l for l in lines if l.startswith("Uid:")).split()[1])
            zombie = any(l.startswith("State:") and "Z" in l.split()[1] for l in lines)
        except (OSError, StopIteration, ValueError, IndexError):
            continue
        # (a zombie has ended: an orphan of the sandbox waits there until init reaps it)
        if 61000 <= uid < 61600 and not zombie:  # runners (61000 + k) and builders (61500 + k)
            left.append(f"pid {status.parent.name} (uid {uid})")
    check(not left, f"processes of the sandbox's users outlived grading: {left}")
# No System V IPC object of theirs is left either (ipc_smuggle makes one in every held-out run).
if os.geteuid() == 0:
    for kind in ("shm", "sem", "msg"):
        try:
            lines = Path(f"/proc/sysvipc/{kind}").read_text().splitlines()
        except OSError:
            continue
        head = lines[0].split() if lines else []
        owned = [l for l in lines[1:] if "uid" in head and 61000 <= int(l.split()[head.index("uid")]) < 61600]
        check(not owned, f"System V {kind} objects of the sandbox's users outlived grading: {owned[:3]}")
# Grading is deterministic: the complete reference, graded twice at the class's fixed seed
# (WB_GRADE_SEED), gets full marks and the same results both times (the elapsed times aside). The
# complete reference once lost 08.5 at random (issue 25); reference_every_seed.sh tries more seeds.
def without_times(name):
    doc = json.loads((grades / name / "results.json").read_text())
    doc.pop("execution_time", None)
    doc.get("extra_data", {}).pop("student", None)  # (their names differ)
    return json.dumps(doc, sort_keys=True)
if (grades / "full_again" / "results.json").exists():
    check(without_times("full") == without_times("full_again"),
          "the complete reference graded twice at one seed got two different results.json")
# The instructor is told which protections were in force.
environment = json.loads((grades / "full" / "results.json").read_text())["tests"][-1]["output"] \
    if (grades / "full" / "results.json").exists() else ""
check("limits:" in environment, f"the grading environment does not state the sandbox's limits: {environment[:300]}")
for p in problems:
    print("FAIL:", p)
print(f"{len(expected)} submissions checked: " + ("all as expected" if not problems else f"{len(problems)} problems"))
sys.exit(1 if problems else 0)
