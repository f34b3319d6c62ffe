"""How a run of student code ended, in the student's words, and the rules that read an exercise's
outcome (what to grade again, alone): the grader's (grader.py) helpers that hold no state."""
import json
import os
import re
import shutil
import signal
from pathlib import Path

from .chunks import chunk
from .common import open_regular
from .sandbox import KEEP, describe_limit


class SupervisedRun:
    """A runner's run under wb_check, as the grader reads it: why it stopped ([(test, message)], or []),
    its output as shown (head and tail), MB it printed where that was a lot, and whether it ran out
    of time."""

    def __init__(self, stopped, output, printed_mb, timed_out):
        self.stopped, self.output, self.printed_mb, self.timed_out = stopped, output, printed_mb, timed_out


def tag_id(tag):
    """The exercise of a run's tag: "01_H1_visible" -> "01.H1"."""
    nn, ex = tag.split("_")[:2]
    return f"{nn}.{ex}"


def read_untrusted(path, keep=KEEP):
    """(head and tail of the regular file at `path`, its size): a file the sandbox's user wrote, so no
    link is followed, nothing but a regular file is opened (a FIFO would stop the grader), and at most
    twice `keep` bytes are read. ("", 0) when there is none."""
    f = open_regular(path)
    if f is None:
        return "", 0
    with f:
        size = os.fstat(f.fileno()).st_size
        if size <= 2 * keep:
            return f.read(2 * keep).decode(errors="replace"), size
        head = f.read(keep)
        f.seek(size - keep)
        return (head.decode(errors="replace") + f"\n[grader: cut here: {size - 2 * keep} bytes of output left out "
                f"(the run printed {size >> 20} MB)]\n" + f.read(keep).decode(errors="replace")), size


def signal_of(reason):
    """-signal where a stop reason names one by its description ("crashed (CPU time limit exceeded)"), or 0."""
    for sig in signal.Signals:
        text = signal.strsignal(sig)
        if text and f"({text}" in reason:
            return -int(sig)
    return 0


def supervised_run(tape, ex_id, code, out, timed_out, timeout, cpu_seconds=0, held_out=False):
    """What wb_check --runner left in `tape` (common/judge/supervisor.cpp words why a run stopped, for
    check and the grader alike), with the sandbox's limits named where the run met one; `code`, `out`
    and `timed_out`: the sandbox's run of wb_check itself, which only fails when wb_check could not
    finish (its own limit is shorter). All of it is the student's code's to write: each line is
    bounded, and of a held-out run (`held_out`) nothing is quoted, not even a test's name, since it
    could carry the held-out inputs; only that it stopped, and whether at its time limit."""
    tag = "Ex" + ex_id.replace(".", "_")
    log, size = read_untrusted(tape / f"{tag}.log")
    reasons = []
    if not (tape / "all").is_symlink():
        reasons = [line.partition("\t")[2][:2000] for line in
                   read_untrusted(tape / "all" / "stopped.txt")[0].splitlines() if line.startswith(tag + "\t")]
    running = re.findall(r"\[ RUN      \] (\S{1,200})", log)
    test = running[-1] if running else ""
    if timed_out:
        reasons = [f"{ex_id} timed out after {timeout} s and was stopped (an endless loop?)"]
    elif not reasons and (code < 0 or code > 128):
        reasons = [f"{ex_id}'s run did not finish: its supervisor (wb_check) was stopped ({signal_name(code)}). Did "
                   "your code stop its parent process?"]
    elif not reasons and code != 0:
        raise RuntimeError(f"the runner's supervisor could not start or run (exit {code}): a fault of the grader, "
                           f"not of the submission: tell the instructor\n{out[-1000:]}")
    timed = timed_out or any("timed out after" in r for r in reasons)
    if held_out:
        stopped = [("", f"ERROR: the held-out run of {ex_id} " + ("ran past its time limit" if timed else "crashed or "
                   "was stopped") + " (held-out runs quote nothing of what they printed)")] if reasons else []
        return SupervisedRun(stopped, "", None, timed)
    stopped = []
    for reason in reasons[:1]:
        limit = describe_limit(signal_of(reason), log + out, cpu_seconds)
        stopped.append((test, f"ERROR: {reason}" + (f"\n(your code {limit})" if limit else "")))
    printed = size >> 20 if size > 2 * KEEP else None
    return SupervisedRun(stopped, log, printed, timed)


def signal_name(code):
    sig = -code if code < 0 else code - 128
    return signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else f"exit {code}"


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


def stopped_itself(outcome):
    """Whether the exercise's own tests stopped it (a crash or its time limit) in a test that calls only
    its function: its code stops whatever runs it, so an exercise graded alone with it would stop too."""
    _, failures, _, _, _ = outcome
    return any(("timed out after" in msg or "crashed (" in msg) and test and not test_runs_app(test)
               for test, msg in failures)


def left_as_stub(outcome, mine, stub, ex_id):
    """Whether exercise `ex_id` failed only as not implemented with its chunk of exercise.cpp byte for
    byte the stub's: graded alone it would be the stub again, and say the same."""
    _, failures, _, hidden_result, _ = outcome
    every = failures + (hidden_result[1] if hidden_result else [])
    if not every or not all("NOT IMPLEMENTED" in msg for _, msg in every):
        return False
    at, at_stub = chunk(mine, ex_id), chunk(stub, ex_id)
    return at is not None and at_stub is not None and mine[at[0]:at[1]] == stub[at_stub[0]:at_stub[1]]


def copy_images(failures, images, tag, judged):
    """The pictures the judge's failures name ("picture: PATH.png"), copied for the report. Only the
    judge's own pictures, regular files under `judged` (its test output), are taken: a message may
    quote what the student's code printed, and a path there could name any file, or a link to one."""
    kept, root = [], Path(judged).resolve()
    for test, msg in failures:
        for label, path in re.findall(r"(picture|diff|reference|result): (\S+\.png)", msg):
            src = Path(path)
            try:
                inside = root in src.resolve().parents and not src.is_symlink() and src.is_file()
            except OSError:
                inside = False
            if inside and src.stat().st_size <= (16 << 20):
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
