#!/usr/bin/python3
"""The grader's sandbox on its own (tools/grading/sandbox.py), in seconds, without a build: what a run
of student code can see, keep and use. ctest -L grading; the synthetic class tries the same through
real submissions (tests/grading/redteam.py)."""
import concurrent.futures
import os
import sys
import time
import tempfile
from pathlib import Path

from grader_test_support import ROOT, check, finish

sys.path.insert(0, str(ROOT / "tools"))
from grading.sandbox import (LIMITS, Sandbox, describe_limit, sandbox_ipc, sandbox_processes,
                             sweep_leftovers)

UID = 61099  # a sandbox user no grading tree uses
sandbox = Sandbox(cpu_seconds=5)
print(f"sandbox: {sandbox.protections()}")
for note in sandbox.notes:
    print(f"note: {note}")
if sandbox.mode != "bwrap":
    print("SKIP: bubblewrap cannot run here; the grader falls back (the notes above say why)")
    sys.exit(0)

with tempfile.TemporaryDirectory(prefix="wb-sandbox-test-") as tmp:
    tmp = Path(tmp)
    os.chmod(tmp, 0o755)
    mine, out = tmp / "mine", tmp / "out"
    mine.mkdir()
    out.mkdir()
    (mine / "readable.txt").write_text("the submission\n")
    (tmp / "elsewhere.txt").write_text("a second copy of the solutions\n")
    for p in (tmp / "elsewhere.txt", mine / "readable.txt"):
        os.chmod(p, 0o644)
    if os.geteuid() == 0:
        os.chown(out, UID, UID)

    def run(script, **kw):
        return sandbox.run(["/bin/sh", "-c", script], 30, cwd=out, uid=UID, ro=[mine], rw=[out], **kw)

    # Only what was bound exists: the submission, the run's own folder, the toolchain.
    code, text, _ = run(f"cat {mine}/readable.txt; cat {tmp}/elsewhere.txt; ls {ROOT}/solutions; ls /root /home /opt")
    check("the submission" in text, f"the bound submission is not readable: {text}")
    check("second copy" not in text, f"a world-readable file outside the binds was read: {text}")
    check("exercise" not in text, f"the checkout's solutions are listed: {text}")
    code, text, _ = run(f"echo x > {mine}/written.txt || echo refused")
    check("refused" in text and not (mine / "written.txt").exists(), "a read-only bind was written")
    code, text, _ = run(f"echo kept > {out}/result.txt && echo ok")
    check((out / "result.txt").exists(), f"the run's own folder is not writable: {text}")
    # Nothing in /tmp, /dev/shm or System V shared memory outlives a run.
    run("echo secret > /tmp/wb_note; echo secret > /dev/shm/wb_note; ipcmk -M 4096 -p 0666")
    code, text, _ = run("cat /tmp/wb_note /dev/shm/wb_note 2>/dev/null; ipcs -m | grep -c 0x || true")
    check("secret" not in text, f"a file in /tmp or /dev/shm outlived its run: {text}")
    check(text.strip().endswith("0"), f"a shared-memory segment outlived its run: {text}")
    check(not sandbox_ipc("shm", {UID}), "a shared-memory segment of the sandbox user is on the machine")
    # No network: only a loopback device, and it is down.
    code, text, _ = run("cat /proc/net/dev")
    devices = [l.split(":")[0].strip() for l in text.splitlines() if ":" in l]
    check(devices == ["lo"], f"network devices in the sandbox: {devices}")
    # No process outlives a run: a daemon that left its session dies with the sandbox.
    code, text, _ = run("setsid sh -c 'sleep 300' & echo started")
    for _ in range(20):  # (the kernel ends the namespace's processes as its first one ends)
        left = sandbox_processes({UID})
        if not left:
            break
        time.sleep(0.1)
    check(not left, f"processes of the sandbox user outlived their run: {left}")
    # The limits, and their names.
    code, text, _ = run("/usr/bin/python3 -c 'b = bytearray(3 << 30)'")
    check(code != 0 and "MemoryError" in text, f"3 GiB was allocated: exit {code} {text[-200:]}")
    check("2 GiB of memory" in describe_limit(134, "terminate called after throwing an instance of "
                                              "'std::bad_alloc'", 5), "a bad_alloc is not named as the memory limit")
    forks = LIMITS["processes"] + 100
    code, text, _ = run(f"n=0; while [ $n -lt {forks} ]; do sleep 2 & n=$((n+1)); done 2>&1 | tail -1; wait")
    check("fork" in text.lower() or "resource" in text.lower(), f"{forks} processes started: {text[-200:]}")
    # Two runs of one student at once each have the whole process limit (a cgroup each, where the
    # grader can make them): one's fork bomb cannot starve the other, so a grade does not depend on
    # which exercises happened to run together.
    if "pids" in sandbox.groups:
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            both = list(pool.map(lambda _: run("n=0; while [ $n -lt 100 ]; do sleep 2 & n=$((n+1)); done; "
                                               "echo started $n; wait"), range(2)))
        check(all("started 100" in t and "fork" not in t.lower() for _, t, _ in both),
              f"two runs at once could not each start 100 processes: {[t[-120:] for _, t, _ in both]}")
    code, text, _ = run("while :; do :; done")
    check("CPU time" in describe_limit(code, text, 5), f"an endless loop was not stopped by the CPU limit: {code}")
    # A run's processes together: three of 200 MB each against a run limit of 300 MiB (a cgroup).
    if "memory" in sandbox.groups:
        LIMITS["run_memory"] = 300 << 20
        small = Sandbox(cpu_seconds=5)
        hog = "/usr/bin/python3 -c 'import time; b = bytearray(200 << 20); time.sleep(2)'"
        code, text, _ = small.run(["/bin/sh", "-c", f"{hog} & {hog} & {hog} & wait"], 30, uid=UID)
        check("in all" in describe_limit(code, text, 5), f"the run's memory limit was not reached or named: {text[-300:]}")
    sweep_leftovers({UID})

finish("sandbox")
