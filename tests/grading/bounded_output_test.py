#!/usr/bin/python3
"""What a run of student code prints cannot make the grader run out of memory (issue 39: a lab that
wrote 3 GiB to stdout had the grader itself OOM-killed, as it buffered the whole output):
run_killable (tools/grading/sandbox.py) reads the output as it comes, keeps its head and tail, and
says what it left out; the run itself goes on, so a correct submission that floods stdout is graded
(and one that prints for ever meets its time limit). In seconds, no build."""
import os
import resource
import sys
import time

from grader_test_support import ROOT, check, finish

sys.path.insert(0, str(ROOT / "tools"))
import tempfile
from pathlib import Path

import shutil

from grading.outcomes import copy_images, supervised_run
from grading.workspace import copy_tape
from grading.sandbox import KEEP, run_killable

# A print in an endless loop: its time limit stops it, and the grader keeps a bounded part.
t0 = time.monotonic()
code, out, timed_out = run_killable(["yes", "a debug print in a loop"], 4)
took = time.monotonic() - t0
check(timed_out and took < 15, f"a flooding run was not stopped at its time limit ({took:.1f} s, timed out: {timed_out})")
check(len(out) < 2 * KEEP + 4096, f"the grader kept {len(out)} bytes of its output (at most twice {KEEP})")
check("[grader: cut here:" in out and "bytes of output left out" in out, "the kept output says where it was cut")
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024
check(peak < 200, f"the grader's peak memory stayed small while the flood went by: {peak} MiB")

# 100 MB printed, then a normal end: the run is graded as it ended, its first and last lines kept.
code, out, timed_out = run_killable(["sh", "-c", "echo FIRST; head -c 100000000 /dev/zero | tr '\\0' x; echo; echo LAST"], 60)
check(code == 0 and not timed_out and out.startswith("FIRST") and out.rstrip().endswith("LAST"),
      f"a run that printed 100 MB kept its exit code {code} and its first and last lines")
check("bytes of output left out (the run printed 95 MB)" in out, "and says that the middle was left out: "
      + next((l for l in out.splitlines() if "grader:" in l), "no note"))

# A runner's log (wb_check writes it in the sandbox, up to its cap) is read the same way: head and tail,
# the cut said, what it printed counted, and a run that ended well not called stopped. A log swapped
# for a FIFO or a link is not read at all (a FIFO would stop the grader; a link could quote its files).
with tempfile.TemporaryDirectory() as tmp:
    tape = Path(tmp)
    (tape / "all").mkdir()
    with open(tape / "Ex01_1.log", "wb") as f:
        f.write(b"[ RUN      ] GlTest.Ex01_1_First\n" + b"x" * (100 << 20) + b"\nLAST\n")
    ran = supervised_run(tape, "01.1", 0, "", False, 60)
    check(not ran.stopped and ran.printed_mb == 100 and len(ran.output) < 2 * KEEP + 4096
          and ran.output.startswith("[ RUN") and ran.output.rstrip().endswith("LAST"),
          f"a 100 MB log: stopped {ran.stopped}, {ran.printed_mb} MB counted, {len(ran.output)} bytes kept")
    (tape / "all" / "stopped.txt").write_text("Ex01_1\t01.1 timed out after 4 s and was stopped: an endless loop?\n")
    ran = supervised_run(tape, "01.1", 0, "", False, 60)
    check(ran.timed_out and ran.stopped == [("GlTest.Ex01_1_First", "ERROR: 01.1 timed out after 4 s and was stopped: "
                                            "an endless loop?")], f"wb_check's words are the student's: {ran.stopped}")
    # A held-out run quotes nothing of it: not the reason, not the test's name (either could carry the
    # held-out inputs), only that it stopped, and whether at its time limit.
    (tape / "all" / "stopped.txt").write_text("Ex01_1\t01.1 timed out after 4 s SECRET-INPUT-0.25\n")
    (tape / "Ex01_1.log").write_text("[ RUN      ] SECRET-INPUT-0.5\n")
    ran = supervised_run(tape, "01.1", 0, "", False, 60, held_out=True)
    check(len(ran.stopped) == 1 and "SECRET" not in repr(ran.stopped) + ran.output and "time limit" in ran.stopped[0][1],
          f"a held-out run's stop quotes nothing: {ran.stopped}")
    # A picture is copied for the report only from the judge's own output, never through a link or
    # from a path the student's code printed.
    judged_out = tape / "judge-output"
    judged_out.mkdir()
    (judged_out / "mine.png").write_bytes(b"png")
    (tape / "stolen.png").symlink_to("/etc/passwd")
    (judged_out / "linked.png").symlink_to("/etc/passwd")
    kept = copy_images([("t", f"picture: {tape / 'stolen.png'} picture: {judged_out / 'linked.png'} "
                              f"picture: {judged_out / 'mine.png'}")], tape / "images", "01_1", judged_out)
    check([k[2] for k in kept] == ["01_1_judge-output_mine.png"], f"only the judge's own picture is copied: {kept}")
    (tape / "Ex01_1.log").unlink()
    os.mkfifo(tape / "Ex01_1.log")
    (tape / "all" / "stopped.txt").unlink()
    (tape / "all" / "stopped.txt").symlink_to("/etc/passwd")
    t0 = time.monotonic()
    ran = supervised_run(tape, "01.1", 0, "", False, 60)
    check(ran.output == "" and not ran.stopped and time.monotonic() - t0 < 5, "a FIFO log and a linked stopped.txt are not read")
    # The joined tape the judge copies: a link there (to another run's tape, a held-out one) is not followed.
    other = tape / "other"
    other.mkdir()
    (other / "tape.jsonl").write_text("{}\n")
    shutil.rmtree(tape / "all")
    (tape / "all").symlink_to(other)
    copy_tape(tape / "all", tape / "judged" / "all")
    check(not (tape / "judged" / "all" / "tape.jsonl").exists(), "a linked all/ is not copied for the judge")

# A run that closes its output and goes on (a child left holding nothing) still ends at its limit.
t0 = time.monotonic()
code, out, timed_out = run_killable(["sh", "-c", "exec >/dev/null 2>&1; sleep 100"], 2)
check(timed_out and time.monotonic() - t0 < 10, "a run that closed its output is still stopped at its limit")

# Builds are sized by the container's CPU quota, not the host's cores: Gradescope's half a CPU is one job.
import grading.common as common
real = common.cgroup_file
for quota, period, want in (("50000 100000", "", 1), ("max 100000", "", None), ("150000", "100000", 2), ("-1", "", None)):
    common.cgroup_file = lambda v2, v1, c, q=quota, p=period: q if v1 != "cpu.cfs_period_us" else (p or q)
    got = common.available_cpus()
    cores = len(os.sched_getaffinity(0))
    check(got == min(want or cores, cores), f"CPU quota {quota!r}: {got} jobs, want {want or 'all'}")
common.cgroup_file = real
finish("bounded output", "a flood costs the grader nothing: head and tail kept, the cut said, the run graded as it ended")
