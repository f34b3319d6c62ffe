"""How a run of student code ended, in the student's words, and the rules that read an exercise's
outcome (what to grade again, alone): the grader's (grader.py) helpers that hold no state."""
import json
import re
import shutil
import signal
from pathlib import Path

from .chunks import chunk
from .sandbox import describe_limit


def runner_stopped(code, out, timed_out, timeout, cpu_seconds=0):
    """[(test, message)] saying why a runner ended early (a time-out, a limit of the sandbox, a crash),
    or []."""
    running = re.findall(r"\[ RUN      \] (\S+)", out)
    test = running[-1] if running else ""
    if timed_out:
        return [(test, f"ERROR: timed out after {timeout} s (an endless loop in C++?); the process was killed")]
    limit = describe_limit(code, out, cpu_seconds) if code < 0 or code > 128 else ""
    if limit:
        return [(test, f"ERROR: your code {limit}; the process was stopped in {test or 'start-up'}")]
    if code < 0 or code > 128:
        sig = -code if code < 0 else code - 128
        name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else f"exit {code}"
        tail = "\n".join(out.strip().splitlines()[-8:])
        return [(test, f"ERROR: the tests crashed ({name}) in {test or 'start-up'}:\n{tail}")]
    return []


# Where a run was cut short by the whole job's time limit (--time-limit), not by its own.
CUT_SHORT = "the job's time ran out here: an endless loop, or very slow code, somewhere in this submission?"


def named_limit(message):
    """A judge's failure message with the sandbox's limit named where the student's code ran into one
    (an exception std::bad_alloc recorded by the runner: the memory limit)."""
    limit = describe_limit(0, message, 0)
    return f"{message}\n(your code {limit})" if limit and "(your code" not in message else message


def grader_failed(exc):
    return f"the grader failed on this submission: {type(exc).__name__}: {exc}".rstrip(": ")


def runs_app(outcome):
    """Whether a failure came from a test that runs the lab app (by convention their names have Scene
    or Measured in them), where the student's other C++ exercises run too."""
    _, failures, _, hidden_result, _ = outcome
    every = failures + (hidden_result[1] if hidden_result else [])
    return any(test_runs_app(test) for test, _ in every)


def test_runs_app(test):
    """By the convention of the labs' tests: a test whose name has Scene or Measured in it."""
    return "Scene" in test or "Measured" in test


def hung_by_itself(outcome):
    """Whether the exercise's own tests ran out of time in a test that calls only its function (not
    the app, where the student's other exercises run too): graded alone, the same call would hang the
    same way, and cost another time limit."""
    _, failures, _, _, _ = outcome
    return any("timed out after" in msg and test and not test_runs_app(test) for test, msg in failures[:1])


def left_as_stub(outcome, mine, stub, ex_id):
    """Whether exercise `ex_id` failed only as not implemented with its chunk of exercise.cpp byte for
    byte the stub's: graded alone it would be the stub again, and say the same."""
    _, failures, _, hidden_result, _ = outcome
    every = failures + (hidden_result[1] if hidden_result else [])
    if not every or not all("NOT IMPLEMENTED" in msg for _, msg in every):
        return False
    at, at_stub = chunk(mine, ex_id), chunk(stub, ex_id)
    return at is not None and at_stub is not None and mine[at[0]:at[1]] == stub[at_stub[0]:at_stub[1]]


def copy_images(failures, images, tag):
    kept = []
    for test, msg in failures:
        for label, path in re.findall(r"(picture|diff|reference|result): (\S+\.png)", msg):
            src = Path(path)
            if src.exists():
                images.mkdir(parents=True, exist_ok=True)
                name = src.stem if label == "picture" else label  # (a sweep's plot is named by its test)
                dest = images / f"{tag}_{src.parent.name}_{name}.png"
                shutil.copyfile(src, dest)
                kept.append((test, label, dest.name))
    return kept


def explanation(verdicts, ex_id):
    """Exercise `ex_id`'s row of check's table, as the judge wrote it (WB_CHECK_JSON): its status and
    the lines printed under it; None when the judge wrote none (it could not finish)."""
    try:
        row = json.loads(verdicts.read_text()).get(ex_id)
    except (OSError, ValueError):
        return None
    if not isinstance(row, dict) or not isinstance(row.get("lines"), list):
        return None
    return {"status": str(row.get("status", "")), "lines": [str(line) for line in row["lines"]]}


def gtest_failures(report):
    """(how many tests ran, [(test, failure message)]) from a judge's --gtest_output=json report."""
    data = json.loads(report.read_text())
    failures, count = [], 0
    for suite in data.get("testsuites", []):
        for t in suite.get("testsuite", []):
            count += 1
            for f in t.get("failures", []):
                failures.append((f"{suite['name']}.{t['name']}", f["failure"]))
    return count, failures
