"""The held-out tests' planning pass: the judge says which lab runs and C++ calls on held-out inputs
the runner must record, and the instructor's input files it needs are copied into its tape folder
(docs/grading-trust.md). The runner never reads tests/hidden/ itself."""
import json
import shutil
from pathlib import Path

from .common import ROOT
from .sandbox import run_killable
from .workspace import own


def plan_requests(lab, judge, gfilter, judged, env, tape, uid, seconds):
    """The judge's planning pass over held-out tests: the lab runs (JSON lines {key, args}) and the
    calls of C++ exercises on held-out inputs ({key, call, inputs}) the runner must record, written
    into its tape folder as requests.jsonl, with each input file of the instructor's (a held-out scene)
    copied beside it, since the runner cannot read them. Returns the requests file."""
    plan = judged / "plan.jsonl"
    (judged / "empty").mkdir()
    code, _, timed_out = run_killable([str(judge), f"--gtest_filter={gfilter}", "--judge", str(judged / "empty")],
                                      seconds, env=dict(env, WB_PLAN=str(plan)), cwd=judged)
    if timed_out or code < 0:  # a partial plan would read as results the student's build never recorded
        raise RuntimeError(f"planning the held-out tests {gfilter} {'timed out' if timed_out else 'crashed'} (a "
                           "fault of the grader: tell the instructor)")
    inputs, lines = tape / "inputs", []
    for line in plan.read_text().splitlines() if plan.exists() else []:
        request = json.loads(line)
        for k, arg in enumerate(request.get("args", [])):  # (a call request has inputs, no files)
            path = Path(arg)
            hidden = ROOT / "tests/hidden" / lab["name"]  # (the lab's held-out inputs, nothing else)
            if path.is_absolute() and path.is_file() and hidden in path.resolve().parents:
                inputs.mkdir(exist_ok=True)
                copy = inputs / f"{len(list(inputs.iterdir()))}-{path.name}"
                shutil.copyfile(path, copy)
                request["args"][k] = str(copy)
        lines.append(json.dumps(request))
    requests = tape / "requests.jsonl"
    requests.write_text("".join(l + "\n" for l in lines))
    own(tape, uid)
    return requests
