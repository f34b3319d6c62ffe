#!/usr/bin/python3
"""A results.json on every exit path of run_autograder (docs/gradescope.md): Gradescope shows
"autograder failed" and gives the student nothing where the file is missing or broken.

  finish_results.py --provisional DIR   before grading: a valid file that says grading did not finish
                                        (what Gradescope shows if the container is killed: its time
                                        limit, its memory)
  finish_results.py --final DIR CODE    after grading, whatever happened: the grader's file where it
                                        finished; where it stopped part-way (exit CODE, a kill, out of
                                        memory), the exercises it graded keep their scores and the
                                        output says that the rest was not graded, and why

Only the keys of Gradescope's specification are written; the grader's own log stays in stdout,
which students do not see.
"""
import json
import os
import signal
import sys
from pathlib import Path

PROVISIONAL = "provisional"  # (extra_data key: the file was written before grading began)
ASK = "Resubmit once; if it happens again, tell your instructor (the autograder's log says more)."


def write(out, doc):
    tmp = out / "results.json.tmp"
    tmp.write_text(json.dumps(doc, indent=2))
    os.replace(tmp, out / "results.json")  # always a whole, valid file


def stopped_because(code):
    if code < 0 or code > 128:
        sig = -code if code < 0 else code - 128
        if sig == signal.SIGKILL:
            return "the grader was killed (SIGKILL: most often the container ran out of memory)"
        name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else f"signal {sig}"
        return f"the grader was stopped by {name}"
    return f"the grader stopped with exit code {code}"


def provisional(out):
    write(out, {"score": 0.0, "output": "Grading did not finish: the autograder was stopped before it wrote any "
                "result (its time or memory limit?). " + ASK, "output_format": "md", "visibility": "visible",
                "stdout_visibility": "hidden", "extra_data": {PROVISIONAL: True}, "tests": []})


def final(out, code):
    try:
        doc = json.loads((out / "results.json").read_text())
        if not isinstance(doc, dict) or not isinstance(doc.get("tests", []), list):
            raise ValueError("not a results object")
    except (OSError, ValueError):
        doc = None
    finished = doc is not None and "execution_time" in doc and not doc.get("extra_data", {}).get(PROVISIONAL)
    if finished:  # (whatever the exit code: the grader wrote its final results)
        return
    why = stopped_because(code) if code != 0 else "the grader ended without its final results"
    if doc is None or doc.get("extra_data", {}).get(PROVISIONAL):
        doc = {"score": 0.0, "output": f"Grading did not finish: {why}, before any exercise was graded. {ASK}",
               "output_format": "md", "visibility": "visible", "stdout_visibility": "hidden", "tests": []}
    elif not finished:  # part-way: what was graded keeps its score
        graded = [t for t in doc.get("tests", []) if t.get("number")]
        doc["output"] = (f"Grading did not finish: {why}. The {len(graded)} exercises graded before that keep "
                         f"their scores; the others were not graded and score 0. {ASK}" if graded else
                         f"Grading did not finish: {why}, before any exercise was graded. {ASK}")
        doc["score"] = sum(float(t.get("score", 0)) for t in doc.get("tests", []))
    doc.get("extra_data", {}).pop(PROVISIONAL, None)
    write(out, doc)


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--provisional":
        provisional(Path(sys.argv[2]))
    elif len(sys.argv) == 4 and sys.argv[1] == "--final":
        final(Path(sys.argv[2]), int(sys.argv[3]))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
