"""A control group per run of student code, where the grader may make one (cgroup v1's pids and
memory controllers, or v2 where this process's group delegates them): a process limit and a memory
limit of the run's own, whoever else runs at the same time. The rlimits of sandbox.py are per
process (memory) or per user (processes), so without a group two runs of one student at once share
one process limit, and a fork bomb in one can starve the other."""
import os
import signal
import time
from pathlib import Path

ROOT_V1 = Path("/sys/fs/cgroup")


def own_group(controller):
    """This process's group in `controller` (v1), or in the unified hierarchy ("" controller)."""
    for line in Path("/proc/self/cgroup").read_text().splitlines():
        _, names, path = line.split(":", 2)
        if (controller and controller in names.split(",")) or (not controller and names == ""):
            return path.lstrip("/")
    return None


class Cgroups:
    """Makes, joins and removes one group per run: `prefix(name)` is the command prefix that puts the
    run in its groups before anything of the student's starts, and `remove(name)` kills what is left
    in them and deletes them."""

    def __init__(self, pids, memory):
        self.limits = {"pids.max": str(pids), "memory.limit_in_bytes": str(memory), "memory.max": str(memory)}
        self.parents = self.find_parents()

    def find_parents(self):
        """{controller: folder under which this process may make groups}, tried by making one: v1's
        own hierarchy per controller, else the unified one where this process's group delegates it."""
        found = {}
        for controller in ("pids", "memory"):
            candidates = []
            if own_group(controller) is not None:
                candidates.append(ROOT_V1 / controller / own_group(controller))
            unified = ROOT_V1 / own_group("") if own_group("") is not None else None
            control = unified / "cgroup.subtree_control" if unified else None
            if control and control.exists() and controller in control.read_text().split():
                candidates.append(unified)
            for base in candidates:
                probe = base / f"wb-probe-{os.getpid()}"
                try:
                    probe.mkdir()
                    probe.rmdir()
                    found[controller] = base
                    break
                except OSError:
                    pass
        return found

    def available(self):
        return set(self.parents)

    def folders(self, name):
        return sorted({parent / f"wb-{name}" for parent in self.parents.values()})

    def prefix(self, name):
        """Makes the run's groups with their limits, and returns the prefix that joins them (as root,
        before privileges drop)."""
        dirs = []
        for folder in self.folders(name):
            folder.mkdir(exist_ok=True)
            for key, value in self.limits.items():
                if (folder / key).exists():
                    (folder / key).write_text(value)
            dirs.append(str(folder))
        if not dirs:
            return []
        join = 'while [ "$1" != -- ]; do echo $$ > "$1/cgroup.procs" || exit 96; shift; done; shift; exec "$@"'
        return ["sh", "-c", join, "sh", *dirs, "--"]

    def oom_killed(self, name):
        """True when the memory limit of the run's group killed a process of it."""
        for folder in self.folders(name):
            for counter in ("memory.failcnt", "memory.events"):
                path = folder / counter
                if not path.exists():
                    continue
                text = path.read_text()
                if counter == "memory.failcnt" and text.strip() not in ("", "0"):
                    return True
                if counter == "memory.events" and any(l.split()[0] == "oom_kill" and l.split()[1] != "0"
                                                      for l in text.splitlines() if len(l.split()) == 2):
                    return True
        return False

    def remove(self, name):
        """Kills whatever is left in the run's groups and deletes them."""
        for folder in self.folders(name):
            for _ in range(20):
                try:
                    pids = [int(p) for p in (folder / "cgroup.procs").read_text().split()]
                except OSError:
                    break
                if not pids:
                    break
                for pid in pids:
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except OSError:
                        pass
                time.sleep(0.05)
            try:
                folder.rmdir()
            except OSError:
                pass
