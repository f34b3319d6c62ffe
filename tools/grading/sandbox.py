"""The sandbox every run of student code goes through, compile and run alike (docs/grading-trust.md).

The strongest isolation the machine allows, in this order:
- bubblewrap (bwrap): every namespace unshared (user, network, IPC, PID, UTS, mount), a private /tmp,
  /var/tmp and /dev/shm, read-only binds of exactly what a run needs (the toolchain in /usr, a few
  files of /etc, the student edition's tree and build) and writable binds of its own output folders
  only; --die-with-parent. Nothing else of the filesystem exists inside, so no copy of the solutions
  anywhere on the machine can be read, and no IPC object outlives the run.
- where bwrap cannot start (no user namespaces, as in some containers): unshare's network and PID
  namespaces, with empty tmpfs mounts on /tmp, /var/tmp and /dev/shm; the instructor's log says so.
- neither: processes in a session of their own, killed as a session.
On top, always: an unprivileged user per grading tree (when the grader is root), and rlimits on
memory, processes, file size and CPU time. A limit hit is named in the student's output.
"""
import itertools
import os
import re
import selectors
import shutil
import signal
import stat
import subprocess
import threading
import time
from pathlib import Path

from .cgroups import Cgroups
from .common import NOBODY, ROOT, SANDBOX_UID

GIB = 1 << 30
LIMITS = {  # generous for a lab, fatal for a bomb
    "memory": 2 * GIB,  # address space of a process: an allocation beyond it fails (std::bad_alloc)
    "run_memory": 4 * GIB,  # all the processes of a run together (a cgroup, where one can be made)
    "processes": 128,  # processes and threads of a run (llvmpipe runs a thread per core): a cgroup's
    # pids.max, else the rlimit of the sandbox user (then shared by that user's runs at the same time)
    "file_size": 1 * GIB,  # the largest file one process may write (a debug build's executable is < 100 MiB)
}
ETC_FILES = ("ld.so.cache", "ld.so.conf", "ld.so.conf.d", "alternatives", "passwd", "group", "nsswitch.conf")


# Where the container runs out of memory before a limit of ours is reached (no cgroup of our own:
# Gradescope), the kernel kills the process with the highest oom_score_adj: a run of student code
# raises its own to the most (no privilege needed; it is inherited), so that the grader is never
# the one chosen, and the run's failure names the memory.
OOM_FIRST = ["/bin/sh", "-c", '{ echo 1000 >/proc/self/oom_score_adj; } 2>/dev/null; exec "$@"', "sh"]

RUN_OOM = "[sandbox: the run's memory limit was reached and a process of it was killed]"


def describe_limit(code, out, cpu_seconds):
    """What a run that ended with `code` (exit code or -signal) and printed `out` ran into, in the
    student's words, or ""."""
    sig = -code if code < 0 else code - 128 if code > 128 else 0
    if sig == signal.SIGXCPU:
        return f"used more than {cpu_seconds} s of CPU time (the sandbox's limit): an endless loop?"
    if sig == signal.SIGXFSZ:
        return f"wrote a file larger than {LIMITS['file_size'] // GIB} GiB (the sandbox's limit)"
    if RUN_OOM in out:
        return f"used more than {LIMITS['run_memory'] // GIB} GiB of memory in all (the sandbox's limit for a run)"
    if "std::bad_alloc" in out or "Cannot allocate memory" in out:
        return f"used more than {LIMITS['memory'] // GIB} GiB of memory (the sandbox's limit)"
    if "Resource temporarily unavailable" in out and ("fork" in out or "thread" in out):
        return f"started more than {LIMITS['processes']} processes or threads (the sandbox's limit)"
    if sig == signal.SIGKILL:  # (not at a time limit: the caller says those first)
        return "was killed by the system (SIGKILL): most likely the grading machine ran out of memory"
    return ""


class Sandbox:
    """Runs commands of student code as above. `run` takes the folders a command needs: `ro` read
    only, `rw` writable, `hide` made empty (a tmpfs over a folder inside a bound one)."""

    def __init__(self, cpu_seconds=600):
        self.notes = []  # where isolation is weaker than intended (the instructor's log and results)
        self.cpu_seconds = cpu_seconds
        self.root = os.geteuid() == 0
        self.drop = self.root and shutil.which("setpriv") is not None  # run as an unprivileged user
        if self.root and not self.drop:
            self.notes.append("setpriv is missing: tests run as root")
        if self.drop and subprocess.run(self.user_prefix(NOBODY) + ["test", "-x", str(ROOT)],
                                        capture_output=True).returncode != 0:
            self.drop = False
            self.notes.append(f"the user nobody cannot enter {ROOT}: tests run as root (make every folder on "
                              "the way to it world-enterable to drop privileges)")
        self.cgroups = Cgroups(LIMITS["processes"], LIMITS["run_memory"]) if self.root else None
        self.groups = self.cgroups.available() if self.cgroups else set()
        if self.groups != {"pids", "memory"}:
            made = f"only {', '.join(sorted(self.groups))} could be made" if self.groups else \
                "none could be made here, as in a container without cgroup delegation such as Gradescope's"
            self.notes.append(f"no cgroup of its own for each run ({made}): memory is limited per process only, and "
                              "the process limit is per sandbox user, shared by its runs at once")
        self.runs = itertools.count()
        self.sessions, self.lock = set(), threading.Lock()  # the sessions of the runs going on (kill_strays)
        # WB_SANDBOX_MODE=unshare or session: a weaker mode than this machine allows, to test the grader
        # as it runs where namespaces cannot be made (Gradescope's container: tests/grading/run_weak_class.sh).
        forced = os.environ.get("WB_SANDBOX_MODE", "")
        if forced not in ("", "bwrap", "unshare", "session"):
            raise SystemExit(f"grade: WB_SANDBOX_MODE={forced}: use bwrap, unshare or session")
        if forced in ("unshare", "session"):
            self.notes.append(f"WB_SANDBOX_MODE={forced}: a weaker isolation than this machine allows, on request")
        self.mode = (forced != "unshare" and forced != "session" and self.try_bwrap()) or \
            (forced != "session" and self.try_unshare()) or "session"
        self.user = f"a user of their own (uid {SANDBOX_UID} and up)" if self.drop else "the grader's user"

    # --- which isolation this machine allows ---------------------------------------------------------
    def try_bwrap(self):
        if not shutil.which("bwrap"):
            self.notes.append("bubblewrap (bwrap) is not installed: the weaker isolation below is used "
                              "(apt-get install bubblewrap)")
            return None
        self.mode = "bwrap"
        r = subprocess.run(self.prefix(NOBODY) + ["true"], capture_output=True, text=True)
        if r.returncode == 0:
            return "bwrap"
        self.notes.append(f"bubblewrap cannot start here ({(r.stderr.strip().splitlines() or ['?'])[-1]}): the "
                          "weaker isolation below is used")
        return None

    def try_unshare(self):
        self.mode = "unshare"
        if shutil.which("unshare") and subprocess.run(self.ns_prefix() + ["true"], capture_output=True).returncode == 0:
            self.private = self.private_tmp()
            return "unshare"
        self.notes.append("network and PID namespaces are not available here (unshare failed): the tests ran with "
                          "network access and could see the container's processes (their command lines, not their "
                          "environment or files, which belong to another user), and a process a submission leaves "
                          "behind is killed by its session only; grade where user namespaces are allowed to isolate "
                          "them")
        return None

    def ns_prefix(self):
        return ["unshare", "--net", "--pid", "--ipc", "--fork", "--kill-child", "--mount-proc"] + \
            (["--"] if self.root else ["--map-current-user", "--"])

    # Mounts an empty tmpfs on each folder named before "--", then runs the rest.
    MOUNT_TMP = 'while [ "$1" != -- ]; do mount -t tmpfs -o mode=1777 tmpfs "$1" || exit 97; shift; done; shift; exec "$@"'

    def private_tmp(self):
        """(unshare mode) Empty world-writable folders of each command's own, where the mount namespace
        allows it. A folder that holds this checkout stays shared (the sweep empties it)."""
        dirs = [d for d in SHARED_TMP if Path(d).is_dir() and Path(d) not in ROOT.parents and Path(d) != ROOT]
        shared = [d for d in SHARED_TMP if Path(d).is_dir() and d not in dirs]
        wrap = ["sh", "-c", self.MOUNT_TMP, "sh", *dirs, "--"]
        if dirs and subprocess.run(self.ns_prefix() + wrap + ["true"], capture_output=True).returncode != 0:
            self.notes.append("no private /tmp for the tests (mounting a tmpfs failed): a submission's tests share "
                              "/tmp, /var/tmp and /dev/shm while it is graded")
            return []
        if shared:
            self.notes.append(f"{', '.join(shared)} holds the grader's checkout, so it is shared between a "
                              "submission's tests (and emptied between submissions)")
        return wrap if dirs else []

    def protections(self):
        """What is in force, in one line for the instructor's log."""
        where = {"bwrap": "bubblewrap (no network, IPC, PID, UTS or user namespace shared; a private /tmp; only "
                          "the toolchain, the student edition and the submission visible)",
                 "unshare": "unshare (no network; own PID and IPC namespaces; a private /tmp)",
                 "session": "a session of its own (no namespaces)"}[self.mode]
        group = f", {LIMITS['run_memory'] // GIB} GiB a run (cgroup)" if "memory" in self.groups else ""
        per = "a run (cgroup)" if "pids" in self.groups else "a sandbox user"
        return (f"{where}; as {self.user}; limits: {LIMITS['memory'] // GIB} GiB of memory a process{group}, "
                f"{LIMITS['processes']} processes {per}, {LIMITS['file_size'] // GIB} GiB files, "
                f"{self.cpu_seconds} s of CPU time per process")

    # --- the command line of one run -----------------------------------------------------------------
    def user_prefix(self, uid):
        return ["setpriv", f"--reuid={uid}", f"--regid={uid}", "--clear-groups", "--"] if self.drop else []

    def limit_prefix(self):
        nproc = LIMITS["processes"] * 8 if "pids" in self.groups else LIMITS["processes"]  # (a backstop)
        return ["prlimit", f"--as={LIMITS['memory']}", f"--nproc={nproc}",
                f"--fsize={LIMITS['file_size']}", f"--cpu={self.cpu_seconds}:{self.cpu_seconds + 5}", "--core=0", "--"] \
            if shutil.which("prlimit") else []

    def bwrap_args(self, ro, rw, hide, cwd):
        args = ["bwrap", "--unshare-all", "--die-with-parent", "--ro-bind", "/usr", "/usr"]
        for top in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):  # merged /usr: links; else binds
            p = Path("/") / top
            if p.is_symlink():
                args += ["--symlink", os.readlink(p), str(p)]
            elif p.is_dir():
                args += ["--ro-bind", str(p), str(p)]
        for name in ETC_FILES:
            if (Path("/etc") / name).exists():
                args += ["--ro-bind", f"/etc/{name}", f"/etc/{name}"]
        args += ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp", "--tmpfs", "/var/tmp"]
        for p in ro:
            args += ["--ro-bind", str(p), str(p)]
        for p in hide:
            args += ["--tmpfs", str(p)]
        for p in rw:
            args += ["--bind", str(p), str(p)]
        return args + ["--chdir", str(cwd or "/tmp"), "--"]

    def prefix(self, uid, ro=(), rw=(), hide=(), cwd=None):
        """The command prefix that runs a command in the sandbox as `uid` (when privileges drop)."""
        inner = {"bwrap": lambda: self.bwrap_args(ro, rw, hide, cwd),
                 "unshare": lambda: self.ns_prefix() + self.private,
                 "session": lambda: []}[self.mode]()
        return self.user_prefix(uid) + self.limit_prefix() + inner

    def run(self, cmd, timeout, cwd=None, env=None, uid=NOBODY, ro=(), rw=(), hide=()):
        """(exit code or -signal, output, timed_out), run in the sandbox as `uid`, in cgroups of its
        own where they can be made."""
        name = f"{os.getpid()}-{next(self.runs)}"
        join = self.cgroups.prefix(name) if self.groups else []
        session = []
        try:
            code, out, timed_out = run_killable(OOM_FIRST + join + self.prefix(uid, ro, rw, hide, cwd) + cmd, timeout,
                                                cwd=cwd, env=env, started=lambda sid: self.enter(session, sid))
            if self.groups and self.cgroups.oom_killed(name):
                out += "\n" + RUN_OOM
            return code, out, timed_out
        finally:
            if self.groups:
                self.cgroups.remove(name)
            with self.lock:
                self.sessions.difference_update(session)
            self.kill_strays(uid)

    def enter(self, session, sid):
        with self.lock:
            self.sessions.add(sid)
        session.append(sid)

    def kill_strays(self, uid):
        """In the weakest mode (no PID namespace) a process may leave its run's session (setsid) and
        outlive the run, to change its tape or a later run's: every process of `uid` that is in no
        running run's session is killed when a run ends. (bubblewrap and unshare end every process
        of a run with it.)"""
        if self.mode != "session":
            return
        with self.lock:
            kill_sandbox_processes([uid], spare=set(self.sessions))

    def checked(self, cmd, uid, env, what, ro=(), rw=(), cwd=None):
        """Runs a step of the grader's own (a build) in the sandbox; stops the grader when it fails."""
        code, out, timed_out = self.run(cmd, 3600, env=env, uid=uid, ro=ro, rw=rw, cwd=cwd)
        if code != 0 or timed_out:
            raise SystemExit(f"grade: could not {what}:\n{out[-4000:]}")


# What reaches a run of student code from the grader's environment: the few variables a program and
# the GL driver need, never the rest (Gradescope's, the grader's own). A run's own are added to it.
KEPT_ENV = ("PATH", "LANG", "LC_ALL", "TZ", "WB_FONT")
KEPT_ENV_PREFIXES = ("MESA_", "LP_", "GALLIUM_", "EGL_", "__EGL_", "LIBGL_", "WB_GL_")


def minimal_env(**extra):
    """The environment of a run of student code: KEPT_ENV and KEPT_ENV_PREFIXES, then `extra`."""
    env = {k: v for k, v in os.environ.items() if k in KEPT_ENV or k.startswith(KEPT_ENV_PREFIXES)}
    env.setdefault("PATH", "/usr/bin:/bin")
    env.update(extra)
    return env


# What a run may print: the grader keeps the first and last KEEP bytes of it, reading as it comes, so
# that no student process can make the grader itself run out of memory (it buffered everything
# before, and 3 GiB of prints had it OOM-killed). The run goes on: a flood costs nothing but its middle.
KEEP = 512 << 10


def run_killable(cmd, timeout, cwd=None, env=None, started=None):
    """Runs cmd in its own session: (exit code or -signal, output, timed_out). On time-out the whole
    session is killed (a test binary and any lab it started; a build's make and compilers), which
    subprocess.run(timeout=...) would not do: it kills only its child and leaves the rest running.
    Its output is read as it comes and bounded (KEEP: its head and its tail); where some was left
    out, the output says so."""
    proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, start_new_session=True)
    if started:
        started(proc.pid)  # (its session: the pid of its first process)
    deadline = time.monotonic() + timeout
    head, tail, total, timed_out, ended = bytearray(), bytearray(), 0, False, None
    fd = proc.stdout.fileno()
    with selectors.DefaultSelector() as sel:
        sel.register(fd, selectors.EVENT_READ)
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                timed_out = True
                break
            # Once the run's first process has ended, what it left behind (a daemon holding the
            # output) is not waited for: a second more of output, then the run is over.
            if ended is None and proc.poll() is not None:
                ended = time.monotonic()
            if ended is not None and time.monotonic() - ended > 1.0:
                break
            if not sel.select(min(left, 0.25)):
                continue
            chunk = os.read(fd, 1 << 16)
            if not chunk:  # every writer is gone
                break
            total += len(chunk)
            room = KEEP - len(head)
            head += chunk[:room]
            if len(chunk) > room:
                tail = (tail + chunk[room:])[-KEEP:]
    if not timed_out:
        try:
            proc.wait(timeout=max(0.1, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:  # (it closed its output and went on)
            timed_out = True
    if timed_out:
        kill_session(proc.pid)  # timeout(1) makes its own process group, hence the session
    proc.wait()
    proc.stdout.close()
    cut = total - len(head) - len(tail)
    out = head.decode(errors="replace")
    if cut > 0:
        out += f"\n[grader: cut here: {cut} bytes of output left out (the run printed {total >> 20} MB)]\n"
    out += tail.decode(errors="replace")
    return (-signal.SIGKILL if timed_out else proc.returncode), out, timed_out


def kill_session(sid):
    """Kills every process of session `sid` (a process group is not enough: timeout(1) leaves it)."""
    for _ in range(10):
        found = False
        for entry in Path("/proc").glob("[0-9]*/stat"):
            try:
                fields = entry.read_text().rsplit(")", 1)[1].split()
                if int(fields[3]) == sid:
                    os.kill(int(entry.parent.name), signal.SIGKILL)
                    found = True
            except (OSError, IndexError, ValueError):
                pass
        if not found:
            return
        time.sleep(0.1)


SHARED_TMP = ("/tmp", "/var/tmp", "/dev/shm")


def sandbox_owned(path, uids):
    """True when one of the sandbox users `uids` owns path."""
    try:
        return os.lstat(path).st_uid in uids
    except OSError:
        return False


def writable_by_others(path):
    try:
        return bool(os.lstat(path).st_mode & stat.S_IWOTH) and not os.path.islink(path)
    except OSError:
        return False


def sweep_leftovers(uids):
    """Removes what sandbox users left behind outside a bwrap sandbox (whose /tmp and IPC namespace
    die with it): files in the world-writable folders (a Mesa .drirc, a note for a later student),
    System V shared memory, semaphores and message queues, and any process still running as one.
    Only those of `uids` (one grading tree's users): another tree may be grading at the same time.
    The processes go first: one still running could make again what was removed before it."""
    kill_sandbox_processes(uids)
    for top in SHARED_TMP:
        for folder, dirs, files in os.walk(top):
            for name in files + dirs:
                p = Path(folder) / name
                if sandbox_owned(p, uids):
                    try:
                        shutil.rmtree(p) if p.is_dir() and not p.is_symlink() else p.unlink(missing_ok=True)
                    except OSError:
                        pass
            dirs[:] = [d for d in dirs if writable_by_others(Path(folder) / d)]
    for kind, flag in (("shm", "-m"), ("sem", "-s"), ("msg", "-q")):
        for ipc_id in sandbox_ipc(kind, uids):
            subprocess.run(["ipcrm", flag, ipc_id], capture_output=True)


def kill_sandbox_processes(uids, spare=frozenset()):
    """Kills every process running as one of `uids`, but those in the sessions `spare`."""
    for _ in range(3):  # (a process may fork while the list is read)
        pids = [p for p in sandbox_processes(uids) if session_of(p) not in spare]
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        if not pids:
            return
        time.sleep(0.05)


def sandbox_ipc(kind, uids):
    """The ids of System V IPC objects ("shm", "sem", "msg") that one of `uids` owns."""
    try:
        lines = Path(f"/proc/sysvipc/{kind}").read_text().splitlines()
    except OSError:
        return []
    head = lines[0].split() if lines else []
    if "id" not in head or "uid" not in head:
        return []
    at_id, at_uid = head.index("id"), head.index("uid")
    return [f[at_id] for f in (l.split() for l in lines[1:])
            if len(f) > max(at_id, at_uid) and int(f[at_uid]) in uids]


def session_of(pid):
    """The session id of process `pid` (0 where it is gone)."""
    try:
        return int(Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[3])
    except (OSError, IndexError, ValueError):
        return 0


def sandbox_processes(uids):
    """The pids of live processes (not zombies: an orphan waits for init to reap it) whose real uid
    is one of `uids`."""
    pids = []
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            text = status.read_text()
            m = re.search(r"^Uid:\s+(\d+)", text, re.M)
            if m and int(m.group(1)) in uids and not re.search(r"^State:\s+Z", text, re.M):
                pids.append(int(status.parent.name))
        except OSError:
            pass
    return pids

