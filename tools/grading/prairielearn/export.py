#!/usr/bin/python3
"""Writes the workbook for PrairieLearn's external grader (docs/prairielearn.md):
./workbook prairielearn-export DIR [--labs 01,03] [--image NAME] [--timeout S] [--held-out total|exercises]

  DIR/course/questions/shadow-workbook/NN_name/      one question per lab (PrairieLearn gives a job at
                                                     most 600 s; a lab is graded in well under that)
          info.json, question.html                   the student uploads the lab's exercise files
  DIR/course/serverFilesCourse/shadow-workbook/      what each job brings: run_job (the entrypoint) and
          run_job, workbook/                         the instructor edition (solutions, held-out tests),
                                                     which students never see
  DIR/image/Dockerfile, workbook/                    the grading image: the public workbook (no
                                                     solutions, mutants or held-out tests), its packages
                                                     installed and its framework prebuilt

Copy course/ into the course's repository, build the image and push it where PrairieLearn pulls from
(docker build -t NAME DIR/image && docker push NAME). Only files that git tracks go in.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import uuid
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tools"))
from grading.workspace import instructor_paths
HERE = Path(__file__).resolve().parent
# What the public image leaves out: the instructor paths (tools/grading/instructor_paths.txt), but for
# the grader itself, which the image runs and which holds no answer.
KEEP_IN_IMAGE = {"tools/grading"}
MAX_TIMEOUT = 600  # PrairieLearn's limit for one grading job
PLACEHOLDER = "YOUR_DOCKERHUB_NAME/shadow-workbook-grader:latest"


def tracked_files():
    out = subprocess.run(["git", "-C", str(ROOT), "ls-files", "-z"], capture_output=True, check=True).stdout
    return [f for f in out.decode().split("\0") if f and (ROOT / f).is_file() and not (ROOT / f).is_symlink()]


def copy_files(files, dest):
    for f in files:
        target = dest / f
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / f, target)


def labs_of(wanted):
    manifests = {p.parent.name[:2]: p for p in sorted((ROOT / "labs").glob("*/exercises.json"))}
    unknown = [x for x in wanted if x not in manifests]
    if unknown:
        sys.exit(f"prairielearn-export: no lab {', '.join(unknown)}; the labs are {', '.join(manifests)}")
    return [(nn, json.loads(manifests[nn].read_text())) for nn in (wanted or list(manifests))]


def question(nn, lab, image, timeout, held_out):
    """info.json and question.html of one lab's question."""
    files = sorted({Path(e["file"]).name for e in lab["exercises"]})
    if len(files) != len({e["file"] for e in lab["exercises"]}):
        sys.exit(f"prairielearn-export: lab {nn} has two exercise files of the same name; a flat upload cannot tell them apart")
    points = sum(e["points"] for e in lab["exercises"] if not e.get("extension"))
    info = {"uuid": str(uuid.uuid5(uuid.NAMESPACE_URL, f"shadow-lab-workbook/prairielearn/{lab['lab']}")),
            "title": f"Lab {nn}: {lab['title']}", "topic": "Real-time shadows", "tags": ["shadow-workbook", f"lab{nn}"],
            "type": "v3", "singleVariant": True, "gradingMethod": "External",
            "externalGradingOptions": {"enabled": True, "image": image, "serverFilesCourse": ["shadow-workbook/"],
                                       "entrypoint": ["/bin/bash", "/grade/serverFilesCourse/shadow-workbook/run_job", nn,
                                                      str(timeout), held_out],
                                       "timeout": timeout}}
    rows = "\n".join(f"    <li>{e['id']} {e['title']} ({e['points']} points{', bonus' if e.get('extension') else ''})</li>"
                     for e in lab["exercises"])
    html = f"""<pl-question-panel>
  <p>Lab {nn} of the Shadow Lab Workbook: {lab['title']}. Upload your <code>{'</code> and <code>'.join(files)}</code>
  from <code>labs/{lab['lab']}/</code> ({points} points). Before you submit, <code>./workbook check {nn}</code> gives
  the verdict this grader will, with the failing cases.</p>
  <ul>
{rows}
  </ul>
</pl-question-panel>
<pl-file-upload file-names="{', '.join(files)}"></pl-file-upload>
<pl-submission-panel>
  <pl-external-grader-results></pl-external-grader-results>
  <pl-file-preview></pl-file-preview>
</pl-submission-panel>
"""
    return info, html


def main():
    ap = argparse.ArgumentParser(prog="workbook prairielearn-export", description=__doc__.split("\n")[0])
    ap.add_argument("dir", help="an empty or new folder")
    ap.add_argument("--labs", default="", help="only these labs, e.g. 01,03 (default: all)")
    ap.add_argument("--image", default=PLACEHOLDER,
                    help="the image name the questions use (where you push the image)")
    ap.add_argument("--timeout", type=int, default=MAX_TIMEOUT, help=f"seconds a job may take (at most {MAX_TIMEOUT})")
    ap.add_argument("--held-out", choices=("total", "exercises"), default="total",
                    help="what students see of the held-out tests at every attempt: their points (default), or "
                         "also which exercises passed them (lets a student tune code against unseen scenes)")
    args = ap.parse_args()
    if not 30 <= args.timeout <= MAX_TIMEOUT:
        ap.error(f"--timeout {args.timeout}: PrairieLearn allows at most {MAX_TIMEOUT} s (and a lab needs 30 s at least)")
    if not (ROOT / "solutions").is_dir():
        sys.exit("prairielearn-export: the grader needs the instructor edition (solutions/ is missing)")
    out = Path(args.dir).resolve()
    if out.exists() and any(out.iterdir()):
        sys.exit(f"prairielearn-export: {out} is not empty")
    wanted = [x.strip().zfill(2) for x in args.labs.split(",") if x.strip()]
    labs = labs_of(wanted)
    files = tracked_files()
    secret = [p for p in instructor_paths() if p not in KEEP_IN_IMAGE]
    public = [f for f in files if not any(f == p or f.startswith(p + "/") for p in secret)]

    server = out / "course/serverFilesCourse/shadow-workbook"
    copy_files(files, server / "workbook")
    shutil.copy2(HERE / "run_job", server / "run_job")
    for nn, lab in labs:
        info, html = question(nn, lab, args.image, args.timeout, args.held_out)
        q = out / "course/questions/shadow-workbook" / lab["lab"]
        q.mkdir(parents=True)
        (q / "info.json").write_text(json.dumps(info, indent=2) + "\n")
        (q / "question.html").write_text(html)
    copy_files(public, out / "image/workbook")
    lab_list = ",".join(nn for nn, _ in labs)
    (out / "image/Dockerfile").write_text(
        "# The Shadow Lab Workbook's grading image for PrairieLearn (docs/prairielearn.md): the public workbook,\n"
        "# its packages and its framework prebuilt for the labs of these questions. No solution is in it.\n"
        "FROM ubuntu:22.04\nENV DEBIAN_FRONTEND=noninteractive\nCOPY workbook/ /opt/shadow-workbook/\n"
        f"RUN bash /opt/shadow-workbook/tools/grading/prairielearn/image_setup.sh {lab_list}\n")
    os.chmod(server / "run_job", 0o755)
    print(f"prairielearn-export: wrote {out}: {len(labs)} question{'s' * (len(labs) > 1)} (labs {lab_list}), "
          f"{len(files)} files for the jobs, {len(public)} in the image (no solutions, mutants or held-out tests)")
    print(f"prairielearn-export: copy {out}/course into your course's repository; build and push the image: "
          f"docker build -t {args.image} {out}/image && docker push {args.image}; then sync it in PrairieLearn "
          "(docs/prairielearn.md lists every step)")
    if args.image == PLACEHOLDER:
        print(f"prairielearn-export: note: the questions name the image {PLACEHOLDER}: give yours with --image NAME "
              "(or edit each info.json), or PrairieLearn will find no image to grade with", file=sys.stderr)


if __name__ == "__main__":
    main()
