"""A class graded: the batch outputs (gradebook.csv, summary.md), one submission's failure kept to
itself, and the command line of ./workbook grade."""
import argparse
import atexit
import csv
import concurrent.futures
import json
import os
import re
import stat
import sys
import threading
import time
import traceback
from pathlib import Path

from .chunks import DEFAULT_BUILD_TIMEOUT
from .common import ROOT, available_cpus, log
from .grader import Grader, grader_failed
from .report import Results, first_line
from .sandbox import Sandbox
from .submission import archive_suffix, load_labs, submission_name, unique_names
from .workspace import Workspace


def write_batch_outputs(out, results, labs):
    columns = [e for l in labs for e in l["exercises"]]
    with open(out / "gradebook.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["student"] + [e["id"] for e in columns] + ["total", "max"])
        for r in sorted(results, key=lambda r: r["name"]):
            by_id = {}
            for x in r["entries"]:
                by_id[x["id"]] = by_id.get(x["id"], 0) + x["score"]
            w.writerow([r["name"]] + [by_id.get(e["id"], 0) for e in columns] + [r["score"], r["max_score"]])
    n = len(results)
    md = [f"# Class summary: {n} submissions", "",
          f"Mean score {sum(r['score'] for r in results) / max(n, 1):.1f} of {results[0]['max_score'] if results else 0}.",
          "", "| exercise | points | passed | most common failure |", "|---|---|---|---|"]
    for e in columns:
        rows = [x for r in results for x in r["entries"] if x["id"] == e["id"] and "held-out" not in x["title"]]
        passed = sum(x["ok"] for x in rows)
        reasons = {}
        for x in rows:
            if not x["ok"]:
                line = first_line(x["failures"][0][1]) if x["failures"] else x["status"]
                line = re.sub(r"/\S*/", "", line)  # paths differ per student and worker
                key = re.sub(r"\b\d+(\.\d+)?\b", "#", line)[:120]
                reasons[key] = reasons.get(key, 0) + 1
        common = max(reasons.items(), key=lambda kv: kv[1]) if reasons else ("", 0)
        cell = f"{common[1]}× {common[0]}".replace("|", "\\|") if common[1] else ""
        md.append(f"| {e['id']} {e['title']} | {e['points']} | {passed} of {len(rows)} "
                  f"({100 * passed / max(len(rows), 1):.0f}%) | {cell} |")
    md += ["", "Where the time went: the first build of the submission, then its tests; within them, every "
           "build (compile and link, the first included), the runners and the judge, summed over the "
           "exercises graded at once.", "",
           "| student | score | seconds | build + tests | compile | runner | judge |", "|---|---|---|---|---|---|---|"]
    md += [f"| {r['name']} | {r['score']} / {r['max_score']} | {r['seconds']:.1f} | {r['timing']['build']:.1f} + "
           f"{r['timing']['tests']:.1f} | {r['timing'].get('compile', 0):.1f} | {r['timing'].get('runner', 0):.1f} | "
           f"{r['timing'].get('judge', 0):.1f} |" for r in sorted(results, key=lambda r: r["name"])]
    total = {k: sum(r["timing"].get(k, 0) for r in results) for k in ("compile", "runner", "judge")}
    md += ["", f"In all: {sum(r['seconds'] for r in results):.0f} s; compile {total['compile']:.0f} s, runners "
           f"{total['runner']:.0f} s, judge {total['judge']:.0f} s."]
    troubled = [r for r in sorted(results, key=lambda r: r["name"]) if r.get("problems")]
    if troubled:
        md += ["", "Not everything could be graded (what was not graded scored 0; see each report):", ""]
        md += [f"- {r['name']}: {'; '.join(r['problems'])}" for r in troubled]
    isolation = sorted({n for r in results for n in r.get("environment", [])})
    if isolation:
        md += ["", "Isolation was weaker than intended (each results.json has it in the hidden test "
               "\"Grading environment\"):", ""] + [f"- {n}" for n in isolation]
    (out / "summary.md").write_text("\n".join(md) + "\n")


def grade_all(subs, spaces, grade_one, fail_one, progress=None):
    """Grades every submission, as many at once as there are workspaces: grade_one(workspace, sub)
    returns a result. An exception that escapes it (Grader.grade records its own, so this is the last
    line of defence) becomes the result fail_one(sub, message), and the others go on. A workspace
    always goes back to the pool. Returns the results in the order of subs."""
    free, lock = list(spaces), threading.Lock()

    def one(sub):
        with lock:
            ws = free.pop()
        t0 = time.time()
        try:
            r = grade_one(ws, sub)
        except (Exception, SystemExit) as exc:
            log(f"\ngrade: the grader failed on {sub}:\n{traceback.format_exc()}")
            r = fail_one(sub, grader_failed(exc), time.time() - t0)
        finally:
            with lock:
                free.append(ws)
        if progress:
            with lock:
                progress(r)
        return r

    with concurrent.futures.ThreadPoolExecutor(max(1, len(spaces))) as pool:
        return list(pool.map(one, subs))


def salvage(out_dir, name, labs, sandbox, problem, elapsed):
    """The result of a submission whose grading failed outside Grader.grade's own handling: every
    exercise scores 0 with the reason, written as results.json and reports when the disk allows."""
    results = None
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
        results = Results(out_dir, name, labs, sandbox)
        results.problems.append(problem)
        results.fail_all(f"ERROR: {problem}; nothing was graded (a fault of the grader, not of the "
                         "submission: tell the instructor)")
        return results.finish(elapsed)
    except Exception as exc:
        log(f"grade: could not write the results of {name} either: {exc}")
        return {"name": name, "score": 0, "max_score": results.max_score if results else 0,
                "entries": results.entries if results else [], "seconds": elapsed,
                "timing": {"build": 0.0, "tests": 0.0}, "problems": [problem]}


HIDDEN_MODES = ROOT / "build-grade" / "hidden-modes.json"  # (while a grader runs: the modes it will put back)


def hide_from_sandbox(paths):
    """Makes `paths` (the checkout's solutions, held-out tests, git history and other builds; the
    submissions and the results) unreadable to the sandbox users while grading runs, and puts their
    modes back when it ends. Only the student edition in build-grade/wK stays in their reach. The modes
    to put back are kept in HIDDEN_MODES too: a grader that was killed (out of memory, a kill -9) cannot
    put them back, so the next one does before it starts."""
    record = restore_hidden_modes()
    modes = {}
    for p in paths:
        try:
            st = os.lstat(p)
            if not stat.S_ISLNK(st.st_mode):
                modes[p] = record.get(str(p), stat.S_IMODE(st.st_mode))
        except OSError:
            pass
    HIDDEN_MODES.parent.mkdir(parents=True, exist_ok=True)
    HIDDEN_MODES.unlink(missing_ok=True)
    with os.fdopen(os.open(HIDDEN_MODES, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600), "w") as f:  # (root's alone)
        json.dump({"pid": os.getpid(), "modes": {str(p): m for p, m in modes.items()}}, f)
    for p, m in modes.items():
        os.chmod(p, m & ~0o077)

    def put_back():
        for p, m in modes.items():
            if p.exists():
                os.chmod(p, m)
        HIDDEN_MODES.unlink(missing_ok=True)
    atexit.register(put_back)


def restore_hidden_modes():
    """The modes a killed grader left in HIDDEN_MODES, put back; {} when there is none. Where that
    grader still runs, its record is left alone, and its modes are returned as the ones to put back."""
    try:
        record = json.loads(HIDDEN_MODES.read_text())
        pid, modes = int(record["pid"]), {str(p): int(m) for p, m in record["modes"].items()}
    except (OSError, ValueError, KeyError, TypeError):
        return {}
    if pid != os.getpid() and Path(f"/proc/{pid}").exists():
        return modes  # (a grader at work: nothing to repair)
    for p, m in modes.items():
        try:
            os.chmod(p, m)
        except OSError:
            pass
    log(f"grade: a grader was stopped before it could put back the modes of {len(modes)} folders; they are back")
    return {}


def main():
    ap = argparse.ArgumentParser(prog="workbook grade", description=__doc__.split("\n")[0])
    ap.add_argument("submission", nargs="?", help="a submission (folder or archive), or with --batch a folder of them")
    ap.add_argument("--prepare-only", action="store_true", help="only build the grading framework (Gradescope's setup)")
    ap.add_argument("--batch", action="store_true", help="grade every folder or archive inside SUBMISSION")
    ap.add_argument("--out", help="where the results go (default: grades/<name>)")
    ap.add_argument("--labs", help="only these labs, e.g. 01,02")
    ap.add_argument("--exercises", choices=["all", "builds", "hunts"], default="all",
                    help="grade every exercise (default), only those written into stubs, or only the bug hunts "
                         "(NN.Hk): hunts as an assignment of their own")
    # One at a time by default: one grading tree already builds and tests with every core. Measured on 2
    # cores (4 submissions of lab 01, docs/instructors.md): --jobs 2 took as long as --jobs 1 once its
    # second tree was built (34 s against 35 s), and 104 s the first time, when it builds that tree.
    ap.add_argument("--jobs", type=int, default=1,
                    help="submissions graded at once (batch; default 1: each one has a grading tree of its own "
                         "and uses every core already)")
    ap.add_argument("--timeout", type=int, default=60, help="seconds for one exercise's tests")
    ap.add_argument("--build-timeout", type=int, default=DEFAULT_BUILD_TIMEOUT,
                    help="seconds for one build of a submission's code; a build that runs longer is stopped and "
                         f"costs the exercises it was building (default {DEFAULT_BUILD_TIMEOUT})")
    ap.add_argument("--judge-build", metavar="DIR",
                    help="judge with this existing build of the checkout (./workbook build's build/) instead of "
                         "building one in build-grade/judge: saves the framework's compile")
    ap.add_argument("--name", help="the student's name in the reports (default: the submission's name)")
    ap.add_argument("--time-limit", type=int, metavar="S",
                    help="no run goes on past S seconds after the grader started: a grading service's limit on "
                         "the whole job, less a margin (PrairieLearn's run_job sets it)")
    args = ap.parse_args()
    deadline = time.time() + args.time_limit if args.time_limit else None
    only = [x.strip().zfill(2) for x in args.labs.split(",")] if args.labs else None
    labs = load_labs(only, args.exercises)
    sandbox = Sandbox()
    if args.prepare_only:
        secs = Workspace(0, labs, ROOT / "build-grade", args.judge_build).prepare(available_cpus(), sandbox)
        log(f"grade: the grading build is ready ({secs:.0f} s)")
        return 0
    if not args.submission:
        ap.error("a SUBMISSION (or --batch DIR, or --prepare-only) is needed")
    if args.batch and args.name:
        ap.error("--name names one submission; in a batch each is named after its file or folder")
    src = Path(args.submission)
    if not src.exists():
        log(f"grade: no such submission or folder: {src}")
        return 2
    subs = sorted(p for p in src.iterdir() if p.is_dir() or archive_suffix(p)) if args.batch else [src]
    if args.batch and not subs:
        log(f"grade: {src} holds no submissions (folders or .zip/.tar archives)")
        return 2
    out = Path(args.out) if args.out else ROOT / "grades" / (src.name if args.batch else submission_name(src))
    out.mkdir(parents=True, exist_ok=True)
    workers = max(1, min(args.jobs, len(subs)))
    if sandbox.mode == "session" and workers > 1:  # (see Grader.test_jobs: no judge beside a student's run)
        log("grade: one submission at a time: without namespaces a student's run could see another's judge")
        workers = 1
    base = ROOT / "build-grade"
    if sandbox.drop:  # what the student's code must not read: everything of the instructor's but its trees
        hide_from_sandbox([p for p in ROOT.iterdir() if p.name != "build-grade"] + [out] + ([src] if args.batch else [])
                          + ([Path(args.judge_build)] if args.judge_build else []))
    log(f"grade: student code runs in {sandbox.protections()}")
    for n in sandbox.notes:
        log(f"grade: note: {n}")
    spaces = [Workspace(k, labs, base, args.judge_build) for k in range(workers)]
    for ws in spaces:
        log(f"grade: preparing the grading build {ws.dir} (the first time builds the framework) ...")
        secs = ws.prepare(available_cpus(), sandbox)  # (the container's quota, not the host's cores)
        log(f"grade: ready in {secs:.0f} s")
    done = [0]

    names = unique_names(subs)  # erin.smith.zip and erin.jones are two students, erin/ and erin.zip too
    for sub, name in names.items():
        if name != submission_name(sub):
            log(f"grade: {sub.name} is graded as {name}: another submission is named {submission_name(sub)}")

    def where(sub):
        name = args.name or names[sub]
        return name, (out / name if args.batch else out)

    def grade_one(ws, sub):
        name, dest = where(sub)
        cores = max(1, available_cpus() // workers)
        return Grader(ws, labs, sandbox, args.timeout, cores, args.build_timeout, deadline).grade(sub, dest, name)

    def fail_one(sub, problem, elapsed):
        name, dest = where(sub)
        return salvage(dest, name, labs, sandbox, problem, elapsed)

    def progress(r):
        done[0] += 1
        print(f"\r[{done[0]}/{len(subs)}] {r['name']}: {r['score']} of {r['max_score']} "
              f"({r['seconds']:.0f} s)" + " " * 20, end="" if args.batch else "\n", file=sys.stderr, flush=True)

    t0 = time.time()
    try:
        results = grade_all(subs, spaces, grade_one, fail_one, progress)
    finally:
        for ws in spaces:
            ws.remove_student_programs()
    failed = [r["name"] for r in results if any(p.startswith("the grader failed") for p in r.get("problems", []))]
    if args.batch:
        log("")
        write_batch_outputs(out, results, labs)
        log(f"grade: {len(subs)} submissions in {time.time() - t0:.0f} s; wrote {out / 'gradebook.csv'} and "
            f"{out / 'summary.md'}")
        for r in results:
            for problem in r.get("problems", []):
                log(f"grade: {r['name']}: {problem}")
    else:
        r = results[0]
        for x in r["entries"]:
            log(f"  {x['id']:<5} {x['title'][:52]:<52} {x['status']:<16} {x['score']:>3} / {x['points']}  "
                f"{first_line(x['failures'][0][1])[:70] if x['failures'] else ''}")
        for problem in r.get("problems", []):
            log(f"grade: {problem}")
        log(f"grade: {r['score']} of {r['max_score']} points in {r['seconds']:.1f} s; wrote {out}/results.json, "
            f"junit.xml, report.md, report.html")
    if failed:  # every result is written, but the grader has a bug to look at
        log(f"grade: the grader itself failed on {', '.join(failed)} (the tracebacks are above)")
    # A batch says so in its exit code; one submission (Gradescope's run_autograder) keeps exit 0,
    # since its results.json is written and already says what was not graded.
    return 1 if failed and args.batch else 0

