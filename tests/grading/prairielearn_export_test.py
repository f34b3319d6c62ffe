#!/usr/bin/python3
"""./workbook prairielearn-export (tools/grading/prairielearn/export.py), as PrairieLearn reads it: one
question per lab whose info.json asks for external grading within PrairieLearn's 600 s, with run_job
and the lab as its entrypoint and the upload's file names the lab's exercise files; the job's files
(serverFilesCourse, which students never see) the instructor edition; the image's Docker context the
public workbook only: no solution, mutant or held-out test, and no three lines of a solution in any
file (export_student.sh --verify's rule); bad options refused with a reason. Seconds, no build."""
import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from grader_test_support import ROOT, check, finish

EXPORT = ROOT / "tools/grading/prairielearn/export.py"
SECRET = ("solutions", "tests/mutants", "tests/hidden", "tests/reference")


def export(dest, *options):
    return subprocess.run([sys.executable, "-B", str(EXPORT), str(dest), *options], capture_output=True, text=True)


with tempfile.TemporaryDirectory(prefix="wb-prairielearn-") as tmp:
    tmp = Path(tmp)
    r = export(tmp / "x", "--labs", "1,03", "--image", "course/grader:1")
    check(r.returncode == 0, f"the export failed: {r.stdout}{r.stderr}")
    course, image = tmp / "x/course", tmp / "x/image"
    questions = sorted((course / "questions/shadow-workbook").glob("*/info.json"))
    check([q.parent.name for q in questions] == ["01_depth_map", "03_pcf"], f"the questions are {questions}")
    uuids = set()
    for q in questions:
        info = json.loads(q.read_text())
        lab = json.loads((ROOT / "labs" / q.parent.name / "exercises.json").read_text())
        opts = info.get("externalGradingOptions", {})
        uuids.add(info.get("uuid"))
        check(info.get("gradingMethod") == "External" and opts.get("enabled") and opts.get("image") == "course/grader:1",
              f"{q.parent.name}: not an external-grading question of the image asked for: {info}")
        check(0 < opts.get("timeout", 0) <= 600, f"{q.parent.name}: timeout {opts.get('timeout')} (PrairieLearn: <= 600)")
        check(opts.get("entrypoint") == ["/bin/bash", "/grade/serverFilesCourse/shadow-workbook/run_job", q.parent.name[:2],
                                         str(opts.get("timeout")), "total"]
              and opts.get("serverFilesCourse") == ["shadow-workbook/"], f"{q.parent.name}: entrypoint {opts}")
        names = re.search(r'file-names="([^"]*)"', (q.parent / "question.html").read_text())
        want = sorted({Path(e["file"]).name for e in lab["exercises"]})
        check(names and [n.strip() for n in names.group(1).split(",")] == want,
              f"{q.parent.name}: the upload asks for {names and names.group(1)}, the lab's files are {want}")
    check(len(uuids) == len(questions), "two questions share a uuid")
    server = course / "serverFilesCourse/shadow-workbook"
    check((server / "run_job").is_file() and (server / "workbook/solutions").is_dir()
          and (server / "workbook/tools/grading/prairielearn/results.py").is_file(),
          "the job's files lack run_job, the solutions or the grader")
    for secret in SECRET:
        check(not (image / "workbook" / secret).exists(), f"the image's context holds {secret}")
    check((image / "workbook/tools/grading/grade.py").is_file(), "the image's context lacks the grader")
    docker = (image / "Dockerfile").read_text()
    check("FROM ubuntu:22.04" in docker and "image_setup.sh 01,03" in docker, f"the Dockerfile: {docker}")
    # No solution content anywhere in the image (the student edition's leak rule; the grader, which
    # the student edition leaves out, set aside first).
    shutil.rmtree(image / "workbook/tools/grading")
    v = subprocess.run([str(ROOT / "tools/grading/export_student.sh"), "--verify", str(image / "workbook")],
                       capture_output=True, text=True)
    check(v.returncode == 0, f"the image's context leaks: {v.stdout[-2000:]}{v.stderr[-2000:]}")
    for options, why in ((["--labs", "42"], "no lab 42"), (["--timeout", "900"], "at most 600"),
                         ([], "is not empty")):
        r = export(tmp / "x" if why == "is not empty" else tmp / "y", *options)
        check(r.returncode != 0 and why in r.stderr, f"{options}: not refused with '{why}': {r.stderr}")
finish("prairielearn export", "questions, job files and a public image, as PrairieLearn reads them")
