"""What every part of the grader shares: where the checkout is, the sandbox users, size limits, and
what the machine (or the container) it runs in may use."""
import math
import os
import stat
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOBODY = 65534
SANDBOX_UID = 61000  # grading tree k runs student code as uid 61000 + k (when the grader is root)
BUILDER_UID = 61500  # and compiles it as uid 61500 + k
MAX_TAPE_BYTES = 64 << 20  # what a judge reads of a runner's tape at most
MAX_FILE_BYTES = 1 << 20  # a larger "exercise file" is not source code


def open_regular(path):
    """The regular file at `path` open for reading ("rb"), or None: for a file the sandbox's user may
    have written, so no link is followed and nothing else is opened (non-blocking: a FIFO swapped in
    would stop the grader at open)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return None
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        return None
    return os.fdopen(fd, "rb")


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def cgroup_file(name_v2, name_v1, controller):
    """The text of this process's cgroup file (v2 `name_v2`, else v1 `controller`/`name_v1`), or ""."""
    try:
        for line in Path("/proc/self/cgroup").read_text().splitlines():
            _, controllers, path = line.split(":", 2)
            if controllers == "":  # v2 (a container may see its own group as the root)
                for f in (Path("/sys/fs/cgroup") / path.lstrip("/") / name_v2, Path("/sys/fs/cgroup") / name_v2):
                    if f.exists():
                        return f.read_text().strip()
            if controller in controllers.split(","):
                for base in (Path("/sys/fs/cgroup") / controller, Path("/sys/fs/cgroup") / controllers):
                    if (base / path.lstrip("/") / name_v1).exists():
                        return (base / path.lstrip("/") / name_v1).read_text().strip()
                    if (base / name_v1).exists():  # (a container sees its own group as the root)
                        return (base / name_v1).read_text().strip()
    except (OSError, ValueError):
        pass
    return ""


def available_cpus():
    """How many CPUs this process may use: the affinity mask, and the container's CPU quota (cgroup v2
    cpu.max, v1 cpu.cfs_quota_us / cfs_period_us), rounded up; at least 1. Gradescope's default is half
    a CPU, where os.cpu_count() says the host's count."""
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    quota = cgroup_file("cpu.max", "cpu.cfs_quota_us", "cpu").split()
    try:
        if len(quota) == 2 and quota[0] != "max":  # v2: "QUOTA PERIOD"
            cpus = min(cpus, math.ceil(int(quota[0]) / int(quota[1])))
        elif len(quota) == 1 and int(quota[0]) > 0:  # v1: the quota; the period is a file of its own
            period = int((cgroup_file("cpu.max", "cpu.cfs_period_us", "cpu").split() or ["100000"])[0])
            cpus = min(cpus, math.ceil(int(quota[0]) / period))
    except ValueError:
        pass
    return max(1, cpus)


def available_memory():
    """The bytes this process's container may use (cgroup v2 memory.max, v1 memory.limit_in_bytes),
    or the machine's memory where there is no limit."""
    limit = cgroup_file("memory.max", "memory.limit_in_bytes", "memory")
    total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    return min(total, int(limit)) if limit.isdigit() else total
