#!/usr/bin/python3
"""run_autograder leaves a valid results.json on every exit path (issue 39: once in 11 runs Gradescope
got none, and showed "autograder failed"). A fake grade.py stands in for the grader and ends each
way it can: killed before writing anything (out of memory), a crash part-way with some exercises
graded, an exit with an error and nothing written, a normal end; and run_autograder itself killed at
once (the container's limit). PrairieLearn's run_job the same way, and with an image that has no
workbook: its results.json must keep PrairieLearn's contract (a score in [0, 1]; not gradable, so the
student keeps the attempt, only where nothing was graded). In seconds, no build."""
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

from grader_test_support import ROOT, check, finish

PARTIAL = {"score": 10.0, "output": "Graded 1 of 2 exercises so far", "extra_data": {"max_score": 20}, "tests": [
    {"name": "01.1 A", "number": "01.1", "score": 10.0, "max_score": 10, "status": "passed", "output": ""},
    {"name": "Environment", "score": 0, "max_score": 0, "output": "", "tags": ["grading-environment"],
     "visibility": "hidden"}]}
FINAL = dict(PARTIAL, output="10 of 20 points.", execution_time=3.0)
FAKES = {  # how the fake grader ends
    "killed": "import os, signal; os.kill(os.getpid(), signal.SIGKILL)",
    "partial": f"import json, sys; open(sys.argv[3] + '/results.json', 'w').write(json.dumps({PARTIAL!r})); "
               "raise RuntimeError('a crash part-way')",
    "nothing": "import sys; print('could not build the runner\\'s build'); sys.exit(1)",
    "final": f"import json, sys; open(sys.argv[3] + '/results.json', 'w').write(json.dumps({FINAL!r}))",
}


def autograder(tmp, fake, name=None):
    ag = tmp / (name or fake)
    (ag / "source/tools/grading/gradescope").mkdir(parents=True)
    (ag / "submission").mkdir()
    shutil.copy(ROOT / "tools/grading/gradescope/finish_results.py", ag / "source/tools/grading/gradescope/")
    (ag / "source/tools/grading/grade.py").write_text(FAKES[fake] + "\n")
    return ag


def results(ag):
    try:
        return json.loads((ag / "results/results.json").read_text())
    except (OSError, ValueError) as e:
        return {"broken": str(e)}


def prairielearn_job(tmp, fake):
    """run_job with the fake grader in a stand-in image tree; the job's /grade in tmp."""
    job, tree = tmp / f"pl-{fake}/grade", tmp / f"pl-{fake}/tree"
    course = job / "serverFilesCourse/shadow-workbook/workbook"
    for rel in ("tools/grading/prairielearn/results.py", "tools/grading/gradescope/finish_results.py",
                "tools/grading/instructor_paths.txt", "labs/01_depth_map/exercises.json"):
        (course / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / rel, course / rel)
    (job / "student").mkdir()
    (job / "shared/shadow-workbook/workbook/solutions").mkdir(parents=True)  # (PrairieLearn's older copy)
    if fake != "no image":
        (tree / "tools/grading").mkdir(parents=True)
        (tree / "tools/grading/grade.py").write_text(FAKES[fake] + "\n")
    r = subprocess.run(["/bin/bash", str(ROOT / "tools/grading/prairielearn/run_job"), "01"], capture_output=True,
                       text=True, env=dict(os.environ, WB_PL_GRADE=str(job), WB_PL_TREE=str(tree)), timeout=60)
    check(r.returncode == 0, f"PrairieLearn, {fake}: run_job exited {r.returncode}: PrairieLearn would read no "
          f"results.json\n{r.stdout}")
    try:
        return json.loads((job / "results/results.json").read_text()), r.stdout
    except (OSError, ValueError) as e:
        return {"broken": str(e)}, r.stdout


with tempfile.TemporaryDirectory(prefix="wb-results-") as tmp:
    tmp = Path(tmp)
    run = ROOT / "tools/grading/gradescope/run_autograder"
    for fake in FAKES:
        ag = autograder(tmp, fake)
        subprocess.run([str(run)], env=dict(os.environ, WB_AUTOGRADER=str(ag)), capture_output=True, timeout=60)
        doc = results(ag)
        ok_keys = set(doc) <= {"score", "output", "output_format", "visibility", "stdout_visibility", "extra_data",
                               "tests", "execution_time"}
        check(ok_keys and isinstance(doc.get("tests"), list), f"{fake}: results.json is not a valid result: {doc}")
        out = doc.get("output", "")
        if fake == "killed":
            check(doc.get("score") == 0 and "Grading did not finish" in out and "SIGKILL" in out,
                  f"killed: the student is not told that grading was killed: {out}")
        elif fake == "partial":
            check(doc.get("score") == 10 and len(doc["tests"]) == 2 and "keep their scores" in out,
                  f"partial: the graded exercise did not keep its score, or the output does not say why: {doc}")
        elif fake == "nothing":
            check(doc.get("score") == 0 and "exit code 1" in out, f"nothing: {out}")
        else:
            check(doc == FINAL, f"final: a finished result was changed: {doc}")
    # The container killed while grading: the provisional file is what Gradescope finds.
    ag = autograder(tmp, "nothing", "container-killed")
    (ag / "source/tools/grading/grade.py").write_text("import time; time.sleep(60)\n")
    proc = subprocess.Popen([str(run)], env=dict(os.environ, WB_AUTOGRADER=str(ag)), start_new_session=True,
                            stdout=subprocess.DEVNULL)
    for _ in range(100):
        if (ag / "results/results.json").exists():
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    doc = results(ag)
    check(doc.get("score") == 0 and "was stopped before it wrote any result" in doc.get("output", ""),
          f"killed at once: no provisional result: {doc}")
    for fake in ["no image"] + list(FAKES):
        doc, log = prairielearn_job(tmp, fake)
        score = doc.get("score")
        check(isinstance(score, float) and 0 <= score <= 1, f"PrairieLearn, {fake}: no score in [0, 1]: {doc} {log}")
        gradable, message = doc.get("gradable"), doc.get("message", "")
        check(not (tmp / f"pl-{fake}/grade/shared").exists() and (os.geteuid() != 0 or
              (tmp / f"pl-{fake}/grade").stat().st_mode & 0o077 == 0),
              f"PrairieLearn, {fake}: /grade (with the solutions) is left in the student's reach")
        if fake in ("no image", "killed", "nothing"):
            check(gradable is False and score == 0 and doc.get("format_errors"),
                  f"PrairieLearn, {fake}: nothing graded, yet the attempt counts: {doc}")
            check(fake != "killed" or "SIGKILL" in message, f"PrairieLearn, killed: not said: {message}")
            check(fake != "no image" or "no workbook" in log, f"PrairieLearn, no image: the log does not say so: {log}")
        elif fake == "partial":
            check(gradable and score == 0.5 and "10 of 20 points from the 1 exercise graded" in message,
                  f"PrairieLearn, partial: {doc}")
        else:
            check(gradable and score == 0.5 and message.startswith("10 of 20 points") and len(doc["tests"]) == 1,
                  f"PrairieLearn, final: {doc}")
finish("results.json on every exit path", "killed, crashed part-way, failed, finished, and the container killed; "
       "PrairieLearn's job the same ways, and without its image")
