#!/usr/bin/python3
"""The real grader killed at random points (SIGKILL, as the kernel's OOM killer or a container's limit
does it), each time followed by what run_autograder does next (finish_results.py --final with the exit
code): every results.json is valid and says what happened; what was graded keeps its score and nothing
scores more than its maximum; the modes the grader took from the checkout come back at the next start;
and an uninterrupted grading of the same submission in the same tree then gets full marks (a kill
mid-build must not leave an object that make takes as up to date; a first whole grading times
the kills, so they fall anywhere in it). Then, where this machine lets a
cgroup be made, the grader starved: a memory limit of 300 MB with a student's exercise that touches
600 MB: the kernel stops the student's run, not the grader, and only that exercise is lost. Last,
a time limit on the whole job (--time-limit, as PrairieLearn's run_job sets it) holds against an
endless loop, and the student is told.
Usage: grader_killed_test.py BUILD_DIR OUT_DIR [SEED] (WB_KILL_SEED too; the seed is printed)."""
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from grader_test_support import ROOT, check, finish

build, out = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
seed = int(sys.argv[3]) if len(sys.argv) > 3 else int(os.environ.get("WB_KILL_SEED", time.time_ns() % 100000))
rng = random.Random(seed)
print(f"seed {seed} (rerun with WB_KILL_SEED={seed})")
shutil.rmtree(out, ignore_errors=True)
out.mkdir(parents=True)
subprocess.run([sys.executable, "-B", str(ROOT / "tests/grading/make_submissions.py"), str(out / "subs"), "--labs", "01",
                "--only", "full"], check=True, capture_output=True)
GRADE = [sys.executable, "-B", str(ROOT / "tools/grading/grade.py"), str(out / "subs/full"), "--labs", "01",
         "--jobs", "1", "--timeout", "8", "--build-timeout", "60", "--judge-build", str(build), "--name", "full"]
modes_before = {p.name: p.stat().st_mode for p in ROOT.iterdir() if not p.is_symlink()}


def descendants(pid):
    """pid and every process below it (by /proc's parent links)."""
    children = {}
    for d in Path("/proc").iterdir():
        try:
            ppid = int((d / "stat").read_text().rsplit(")", 1)[1].split()[1])
            children.setdefault(ppid, []).append(int(d.name))
        except (ValueError, OSError, IndexError):
            continue
    found, todo = [], [pid]
    while todo:
        p = todo.pop()
        found.append(p)
        todo += children.get(p, [])
    return found


def kill_tree(pid):
    """Stops the grader and all its processes at once (stopped first, so none forks away), then kills them."""
    seen = set()
    for _ in range(5):
        new = [p for p in descendants(pid) if p not in seen]
        for p in new:
            try:
                os.kill(p, signal.SIGSTOP)
            except ProcessLookupError:
                pass
        seen.update(new)
        if not new:
            break
    for p in seen:
        try:
            os.kill(p, signal.SIGKILL)
        except ProcessLookupError:
            pass


def results_of(folder, code):
    """What run_autograder leaves after a grader that ended with `code`."""
    subprocess.run([sys.executable, "-B", str(ROOT / "tools/grading/gradescope/finish_results.py"), "--final",
                    str(folder), str(code)], check=True, capture_output=True)
    try:
        return json.loads((folder / "results.json").read_text())
    except (OSError, ValueError) as e:
        return {"broken": str(e)}


def whole(name):
    """The submission graded without a kill: (its results, the seconds it took)."""
    t0 = time.time()
    r = subprocess.run(GRADE + ["--out", str(out / name)], capture_output=True, text=True)
    doc = results_of(out / name, r.returncode)
    full = sum(e["points"] for e in json.loads((ROOT / "labs/01_depth_map/exercises.json").read_text())["exercises"])
    check(doc.get("score") == full, f"{name}: the full submission scores {doc.get('score')} of {full}: {doc.get('output')}\n"
          f"{r.stderr[-3000:]}")
    return doc, time.time() - t0


# How long a whole grading takes, so the kills fall anywhere in it: the preparation, the build, the runs.
_, seconds = whole("whole-before")
print(f"uninterrupted: {seconds:.1f} s")
for k in range(3):
    folder = out / f"killed-{k}"
    folder.mkdir()
    at = rng.uniform(0.05, 1.0) * seconds
    proc = subprocess.Popen(GRADE + ["--out", str(folder)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(at)
    finished = proc.poll() is not None
    kill_tree(proc.pid)
    code = proc.wait()
    doc = results_of(folder, code)
    tests = [t for t in doc.get("tests", []) if t.get("number")]
    check("broken" not in doc and isinstance(doc.get("score"), (int, float)), f"kill {k} at {at:.1f} s: {doc}")
    check(all(0 <= t["score"] <= t["max_score"] or t["max_score"] == 0 for t in tests),
          f"kill {k}: a test scores above its maximum: {tests}")
    check(abs(doc.get("score", -1) - sum(t["score"] for t in doc.get("tests", []))) < 1e-6,
          f"kill {k}: the score is not the sum of its tests: {doc.get('score')}")
    if not finished:
        check("Grading did not finish" in doc.get("output", "") and "SIGKILL" in doc.get("output", "")
              and ("keep their scores" in doc["output"]) == bool(tests),
              f"kill {k} at {at:.1f} s: the student is not told that grading was killed: {doc.get('output')}")
    print(f"kill {k} at {at:.1f} s: {'finished first' if finished else 'killed'}, {len(tests)} exercises graded, "
          f"score {doc.get('score')}")

# The same submission, uninterrupted, in the tree the kills left.
doc, _ = whole("whole-after")
modes_after = {p.name: p.stat().st_mode for p in ROOT.iterdir() if not p.is_symlink()}
changed = {n: (oct(modes_before[n]), oct(m)) for n, m in modes_after.items() if n in modes_before and m != modes_before[n]}
check(not changed, f"the checkout's modes were not put back after the kills: {changed}")
print(f"uninterrupted after the kills: score {doc.get('score')}")


# Starved: 300 MB for the whole grading, and 01.1 of a full submission touching 600 MB.
sys.path.insert(0, str(ROOT / "tests/grading"))
sys.path.insert(0, str(ROOT / "tools"))
import submission_tree
from grading.cgroups import Cgroups

groups = Cgroups(pids=4096, memory=300 << 20)  # (the grader's own groups: v1 or v2, made and removed)
groups.limits.update({"memory.swap.max": "0", "memory.memsw.limit_in_bytes": str(300 << 20)})  # (no swap)
if "memory" not in groups.available():
    print("starved: skipped (no memory cgroup can be made here; the stand-in,"
          " tools/grading/gradescope/simulate.sh --memory 300M, is the way to try it)")
else:
    submission_tree.prepend(out / "subs/full", "01_depth_map", "exercise.cpp", "#include <cstring>\n")
    submission_tree.edit(out / "subs/full", "01_depth_map", "exercise.cpp", "01.1",
                         "  { static char* bomb = new char[600u << 20]; std::memset(bomb, 1, 600u << 20); }\n")
    folder = out / "starved"
    name = f"starved-{os.getpid()}"
    try:
        r = subprocess.run(groups.prefix(name) + GRADE + ["--out", str(folder)], capture_output=True, text=True)
    finally:
        groups.remove(name)
    doc = results_of(folder, r.returncode)
    lost = sorted(t["number"] for t in doc.get("tests", []) if t.get("number") and t["score"] < t["max_score"])
    out01 = next((t["output"] for t in doc.get("tests", []) if t.get("number") == "01.1"), "")
    check(r.returncode == 0 and "execution_time" in doc, f"starved: the grader did not finish (exit {r.returncode}): "
          f"{doc.get('output')}\n{r.stderr[-2000:]}")
    check(lost == ["01.1", "01.1"] or lost == ["01.1"], f"starved: the exercises lost are {lost}, expected 01.1 alone")
    check("memory" in out01, f"starved: 01.1's output does not say that it ran out of memory: {out01[:500]}")
    print(f"starved at 300 MB: score {doc.get('score')}, lost {lost}")

# A job's time limit (--time-limit, PrairieLearn's run_job): an endless loop cannot keep the grader
# past it; the runs after it are cut short, and the student is told.
subprocess.run([sys.executable, "-B", str(ROOT / "tests/grading/make_submissions.py"), str(out / "loop"), "--labs", "01",
                "--only", "endless_loop_cpp"], check=True, capture_output=True)
t0 = time.time()
r = subprocess.run(GRADE[:3] + [str(out / "loop/endless_loop_cpp")] + GRADE[4:] + ["--out", str(out / "limited"),
                   "--time-limit", "12"], capture_output=True, text=True)
took = time.time() - t0
doc = results_of(out / "limited", r.returncode)
check(r.returncode == 0 and took < 12 + 30, f"time limit: the grader took {took:.0f} s for a limit of 12 s "
      f"(exit {r.returncode})\n{r.stderr[-2000:]}")
check("time limit of the whole job" in doc.get("output", ""), f"time limit: not said: {doc.get('output')}")
print(f"a 12 s time limit with an endless loop: {took:.0f} s, score {doc.get('score')}")

finish("the grader killed at random points", f"3 kills (seed {seed}), valid results each time, full marks after, "
       "and starved of memory")
