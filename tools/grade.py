#!/usr/bin/python3
"""Grades student submissions of the Shadow Lab Workbook: ./workbook grade (see docs/instructors.md).

A submission is a folder or an archive (.zip, .tar, .tar.gz, .tgz) holding a student's copy of the
workbook, or just its labs/ folder, or (when one lab is graded) just the exercise files, flat. Only
the exercise files that labs/*/exercises.json names are taken from it. They go into a copy of this
tree without the instructor material, prebuilt, where an unprivileged user compiles them (one
compile per lab) and another runs them as the *runner*, without network, recording what the
exercises produce; the solution's build, the *judge*, decides every score from that record and draws
every graded scene itself (docs/grading-trust.md). A build that runs past --build-timeout is stopped
and costs the exercises it was building; whatever else goes wrong with one submission (even a fault
of the grader) is recorded in its results, never stops a batch.

Outputs per submission (in --out): results.json (Gradescope, rewritten after every exercise so a
crash mid-way leaves a valid file), junit.xml, report.md and report.html with the reference, result
and diff images of failed scene tests. With --batch: one such folder per student, gradebook.csv and
summary.md.
"""
import argparse
import atexit
import concurrent.futures
import csv
import html
import json
import os
import re
import shutil
import secrets
import signal
import stat
import subprocess
import sys
import tarfile
import tempfile
import threading
import time
import traceback
import zipfile
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

ROOT = Path(__file__).resolve().parent.parent
NOBODY = 65534
SANDBOX_UID = 61000  # grading tree k runs student code as uid 61000 + k (when the grader is root)
BUILDER_UID = 61500  # and compiles it as uid 61500 + k
MAX_TAPE_BYTES = 64 << 20  # what a judge reads of a runner's tape at most
MAX_FILE_BYTES = 1 << 20  # a larger "exercise file" is not source code


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# --- The manifests --------------------------------------------------------------------------------
def load_labs(only=None):
    """Every lab with its exercises (id, title, file, points, extension) and its held-out tests."""
    labs = []
    for manifest in sorted((ROOT / "labs").glob("*/exercises.json")):
        data = json.loads(manifest.read_text())
        lab = manifest.parent.name
        if only and lab[:2] not in only:
            continue
        hidden_file = ROOT / "tests/hidden" / lab / "hidden.json"
        hidden = json.loads(hidden_file.read_text()) if hidden_file.exists() else {"points": {}}
        labs.append({"name": lab, "nn": lab[:2], "title": data.get("title", lab), "exercises": data["exercises"],
                     "hidden_points": hidden.get("points", {}),
                     "hidden_visibility": hidden.get("visibility", "after_due_date")})
    if not labs:
        raise SystemExit("grade: no labs found" + (f" for --labs {','.join(only)}" if only else ""))
    return labs


def student_files(lab):
    """The whitelisted files of a lab, relative to labs/NN_name."""
    return sorted({e["file"] for e in lab["exercises"]})


# --- Submissions ----------------------------------------------------------------------------------
ARCHIVE_SUFFIXES = (".tar.gz", ".tgz", ".zip", ".tar")  # longest first: "x.tar.gz" is "x"


def archive_suffix(path):
    """The archive suffix of a file name (.zip, .tar, .tar.gz, .tgz, any case), or "" for none."""
    lower = path.name.lower()
    return next((s for s in ARCHIVE_SUFFIXES if lower.endswith(s) and len(lower) > len(s)), "")


def submission_name(path):
    """A student's name from a submission: the whole name less a known archive suffix, so that
    erin.smith.zip is "erin.smith" and erin.jones (a folder) is "erin.jones"."""
    suffix = archive_suffix(path) if path.is_file() else ""
    return path.name[:len(path.name) - len(suffix)] if suffix else path.name


def unique_names(subs):
    """{submission: name}: submission_name, with -2, -3, ... after a name that an earlier submission
    (in sorted order) already has (erin/ and erin.zip are "erin" and "erin-2"), so no result
    overwrites another."""
    names, taken = {}, set()
    for sub in sorted(subs):
        base = submission_name(sub)
        name, k = base, 2
        while name in taken:
            name, k = f"{base}-{k}", k + 1
        taken.add(name)
        names[sub] = name
    return names


def unpack(submission, scratch):
    """A folder to read the submission from (archives are extracted safely into scratch). A folder
    that holds nothing but one archive (an upload of a zip that was not unpacked) is that archive."""
    path = Path(submission)
    if path.is_dir():
        entries = [p for p in path.iterdir() if not p.name.startswith(".")]
        if len(entries) == 1 and entries[0].is_file() and not entries[0].is_symlink() and archive_suffix(entries[0]):
            path = entries[0]
        else:
            return path
    if not path.exists():
        raise ValueError(f"no such submission: {path}")
    dest = Path(tempfile.mkdtemp(prefix="submission-", dir=scratch))
    if zipfile.is_zipfile(path):
        with zipfile.ZipFile(path) as z:
            for info in z.infolist():
                target = (dest / info.filename).resolve()
                if not str(target).startswith(str(dest.resolve())) or info.file_size > 64 * MAX_FILE_BYTES:
                    continue  # a path outside the folder, or a huge member: ignored
                z.extract(info, dest)
    elif tarfile.is_tarfile(path):
        with tarfile.open(path) as t:
            members = [m for m in t.getmembers() if (m.isfile() or m.isdir()) and not m.name.startswith("/")
                       and ".." not in Path(m.name).parts and m.size <= 64 * MAX_FILE_BYTES]
            t.extractall(dest, members=members)
    else:
        raise ValueError(f"{path.name} is neither a folder nor a .zip/.tar archive")
    return dest


def regular_inside(path, folder):
    """True when `path` is a regular file reached from `folder` without following any link (a linked
    file or a linked folder on the way could point at the solutions)."""
    try:
        current = folder
        for part in path.relative_to(folder).parts:
            current = current / part
            if stat.S_ISLNK(os.lstat(current).st_mode):
                return False
        return stat.S_ISREG(os.lstat(path).st_mode)
    except (ValueError, OSError):
        return False


def find_student_file(folder, lab, rel, assignment_labs=None):
    """(path or None, note or None): the submission's copy of labs/<lab>/<rel>. It is looked for at
    that path under the folder or under one level of nesting (an archive with a top folder), then as
    the only file whose path ends with <lab>/<rel>, then as a flat upload: the file alone
    (exercise.cpp, exercise.glsl or shaders/exercise.glsl at the top of the upload), which belongs to
    the lab only when the assignment (assignment_labs, the names of the labs graded) has one lab;
    with several, a flat file is ambiguous and the note says so."""
    regular = lambda p: regular_inside(p, folder)  # noqa: E731
    bases = [folder] + sorted(d for d in folder.iterdir() if d.is_dir() and not d.is_symlink())
    for base in bases:
        candidate = base / "labs" / lab / rel
        if regular(candidate):
            return candidate, None
        if os.path.lexists(candidate):  # there, but a link (or not a file): never followed
            return None, f"labs/{lab}/{rel} is a link or not a regular file: it is not followed (submit the file itself)"
    matches = [p for p in folder.rglob(Path(rel).name) if p.as_posix().endswith(f"{lab}/{rel}") and regular(p)]
    if len(matches) == 1:
        return matches[0], None
    flat = next((p for base in bases for p in (base / rel, base / Path(rel).name) if regular(p)), None)
    if flat is None:
        return None, None
    shown = flat.relative_to(folder).as_posix()
    labs = list(assignment_labs or [])
    if labs == [lab]:
        return flat, f"{shown} (uploaded without its folder) is graded as labs/{lab}/{rel}"
    return None, (f"{shown} is in the upload without its folder, and this assignment grades labs "
                  f"{', '.join(l[:2] for l in labs)}: it cannot tell which lab it belongs to, so labs/{lab}/{rel} "
                  f"is not graded from it; upload it as labs/{lab}/{rel}")


# --- The sandbox ----------------------------------------------------------------------------------
class Sandbox:
    """Runs a command in its own session with a time limit, without network (a new network
    namespace), in a new PID namespace (every process it starts, daemons included, is killed when it
    ends) and, when the grader is root, as an unprivileged user of its own (one per grading tree,
    so two students graded at once cannot touch each other's files)."""

    def __init__(self):
        self.notes = []
        self.root = os.geteuid() == 0
        self.drop = self.root and shutil.which("setpriv") is not None  # run as an unprivileged user
        if self.root and not self.drop:
            self.notes.append("setpriv is missing: tests run as root")
        self.ns = ["unshare", "--net", "--pid", "--fork", "--kill-child", "--mount-proc"]
        self.ns += ["--"] if self.root else ["--map-current-user", "--"]
        if not shutil.which("unshare") or subprocess.run(self.ns + ["true"], capture_output=True).returncode != 0:
            self.ns = []
            self.notes.append("network and PID namespaces are not available here (unshare failed): tests run "
                              "with the network, and a process a submission leaves behind is killed by session "
                              "only")
        self.private = self.private_tmp() if self.ns else []
        if self.drop and subprocess.run(self.prefix(NOBODY) + ["test", "-x", str(ROOT)],
                                        capture_output=True).returncode != 0:
            self.drop = False
            self.notes.append(f"the user nobody cannot enter {ROOT}: tests run as root (make every folder on "
                              "the way to it world-enterable to drop privileges)")
        self.user = f"a user of their own (uid {SANDBOX_UID} and up)" if self.drop else "the grader's user"

    # Mounts an empty tmpfs on each folder named before "--", then runs the rest.
    MOUNT_TMP = 'while [ "$1" != -- ]; do mount -t tmpfs -o mode=1777 tmpfs "$1" || exit 97; shift; done; shift; exec "$@"'

    def private_tmp(self):
        """The world-writable folders each sandboxed command gets empty, of its own (so one runner
        cannot leave a held-out input in /dev/shm for a later, visible one to print), where the mount
        namespace allows it. A folder that holds this checkout stays shared (the sweep between
        submissions still empties it)."""
        dirs = [d for d in SHARED_TMP if Path(d).is_dir() and Path(d) not in ROOT.parents and Path(d) != ROOT]
        shared = [d for d in SHARED_TMP if Path(d).is_dir() and d not in dirs]
        wrap = ["sh", "-c", self.MOUNT_TMP, "sh", *dirs, "--"]
        if dirs and subprocess.run(self.ns + wrap + ["true"], capture_output=True).returncode != 0:
            self.notes.append("no private /tmp for the tests (mounting a tmpfs failed): a submission's tests share "
                              "/tmp, /var/tmp and /dev/shm while it is graded")
            return []
        if shared:
            self.notes.append(f"{', '.join(shared)} holds the grader's checkout, so it is shared between a "
                              "submission's tests (and emptied between submissions)")
        return wrap if dirs else []

    def prefix(self, uid):
        """The command prefix that runs a command in the namespaces (with a /tmp, /var/tmp and /dev/shm
        of its own), as `uid` when privileges drop."""
        drop = ["setpriv", f"--reuid={uid}", f"--regid={uid}", "--clear-groups", "--"] if self.drop else []
        return self.ns + self.private + drop

    def run(self, cmd, timeout, cwd=None, env=None, uid=NOBODY):
        """(exit code or -signal, output, timed_out), as `uid` when the sandbox drops privileges."""
        return run_killable(self.prefix(uid) + cmd, timeout, cwd=cwd, env=env)

    def checked(self, cmd, uid, env, what):
        """Runs a step of the grader's own (a build) as `uid`; stops the grader when it fails."""
        code, out, timed_out = self.run(cmd, 3600, env=env, uid=uid)
        if code != 0 or timed_out:
            raise SystemExit(f"grade: could not {what}:\n{out[-4000:]}")


def run_killable(cmd, timeout, cwd=None, env=None):
    """Runs cmd in its own session: (exit code or -signal, output, timed_out). On time-out the whole
    session is killed (a test binary and any lab it started; a build's make and compilers), which
    subprocess.run(timeout=...) would not do: it kills only its child and leaves the rest running."""
    proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=timeout)
        return proc.returncode, out.decode(errors="replace"), False
    except subprocess.TimeoutExpired:
        kill_session(proc.pid)  # timeout(1) makes its own process group, hence the session
        out, _ = proc.communicate()
        return -signal.SIGKILL, out.decode(errors="replace"), True


def kill_session(sid):
    """Kills every process of session `sid` (a process group is not enough: timeout(1) leaves it)."""
    for _ in range(10):
        found = False
        for stat in Path("/proc").glob("[0-9]*/stat"):
            try:
                fields = stat.read_text().rsplit(")", 1)[1].split()
                if int(fields[3]) == sid:
                    os.kill(int(stat.parent.name), signal.SIGKILL)
                    found = True
            except (OSError, IndexError, ValueError):
                pass
        if not found:
            return
        time.sleep(0.1)


# --- The grading build ----------------------------------------------------------------------------
def instructor_paths():
    """What the student edition leaves out (tools/instructor_paths.txt), relative to ROOT."""
    lines = (ROOT / "tools/instructor_paths.txt").read_text().splitlines()
    return [l.strip() for l in lines if l.strip() and not l.startswith("#")]


def edition_ignore(root_dir):
    """A copytree ignore: the instructor material, git, build folders and caches of the checkout."""
    left_out = {ROOT / p for p in instructor_paths()}

    def ignore(folder, names):
        here = Path(folder)
        return {n for n in names if here / n in left_out or n in (".git", "__pycache__", "node_modules")
                or (here == root_dir and (n.startswith("build") or n == "grades"))}
    return ignore


def sync_tree(src, dest, ignore):
    """Makes dest a copy of src (less what ignore leaves out), writing only the files whose content
    differs, so an unchanged tree is not rebuilt."""
    dest.mkdir(parents=True, exist_ok=True)
    names = set(os.listdir(src)) - ignore(str(src), os.listdir(src))
    for stale in set(os.listdir(dest)) - names:
        p = dest / stale
        shutil.rmtree(p) if p.is_dir() and not p.is_symlink() else p.unlink()
    for n in names:
        s, d = src / n, dest / n
        if s.is_symlink() or not (s.is_dir() or s.is_file()):
            continue
        if s.is_dir():
            sync_tree(s, d, ignore)
            continue
        st = s.stat()
        if not d.is_file() or d.stat().st_size != st.st_size or d.read_bytes() != s.read_bytes():
            shutil.copyfile(s, d)  # a new time: make rebuilds what depends on it
        os.chmod(d, 0o644 | (st.st_mode & 0o111))


class Workspace:
    """One pair of prebuilt grading trees:
    - the runner's, build-grade/wK: src/ is the student edition of this checkout (no solutions, no
      held-out tests, no mutants, no grader) with one submission's exercise files in labs/, built in
      build/ by the builder user (uid 61500 + k) into labNN and labNN_tests; the runner user
      (uid 61000 + k) runs them and writes only its tapes and test-output/;
    - the judge's, build-grade/judge/wK (root's alone): this checkout's solution build, labNN_solution
      and labNN_solution_tests, which judge the tapes and draw every scene (docs/grading-trust.md)."""

    def __init__(self, index, labs, base):
        self.uid = SANDBOX_UID + index  # runs the student's code (when the grader is root)
        self.heldout_uid = SANDBOX_UID + 100 + index  # and its held-out runs, apart from the visible ones
        self.builder = BUILDER_UID + index  # compiles it
        self.dir = base / f"w{index}"
        self.src = self.dir / "src"
        self.build = self.dir / "build"
        self.judge = base / "judge" / f"w{index}"
        self.stubs = self.dir / "stubs"  # the public stub shaders, for the runner's recording runs
        self.labs = labs

    def lab_dir(self, lab):
        return self.src / "labs" / lab

    def reset_to_stubs(self):
        for lab in load_labs():  # every lab, so the build is configured the same whatever --labs says
            for rel in student_files(lab):
                self.place(lab["name"], rel, (ROOT / "labs" / lab["name"] / rel).read_bytes())

    def place(self, lab, rel, content):
        """Writes a file only when its content changes, so make rebuilds only what changed."""
        target = self.lab_dir(lab) / rel
        if target.exists() and target.read_bytes() == content:
            return
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)

    def after_killed_build(self, labs):
        """A build killed mid-way may leave a half-written object or executable that is newer than its
        sources, which make would take as up to date: the executables go and the exercise files are
        touched, so the next build of these labs redoes both."""
        for lab in labs:
            for name in (f"lab{lab['nn']}", f"lab{lab['nn']}_tests"):
                (self.build / name).unlink(missing_ok=True)
            for rel in student_files(lab):
                target = self.lab_dir(lab["name"]) / rel
                if target.exists():
                    target.touch()

    def runner_targets(self, labs):
        return [t for lab in labs for t in (f"lab{lab['nn']}", f"lab{lab['nn']}_tests")]

    def prepare(self, jobs, sandbox):
        """Builds the judge's tree (root) and the runner's (the builder user, stubs in place)."""
        t0 = time.time()
        for p in (self.dir.parent, self.dir):
            p.mkdir(parents=True, exist_ok=True)
            os.chmod(p, 0o755)
        self.judge.mkdir(parents=True, exist_ok=True)
        os.chmod(self.judge.parent, 0o700)
        sync_tree(ROOT, self.src, edition_ignore(ROOT))
        stub_shaders = {Path(f).name for lab in self.labs for f in student_files(lab) if f.startswith("shaders/")}
        sync_tree(ROOT / "labs", self.stubs, lambda folder, names: {n for n in names if Path(folder, n).is_file()
                                                                    and n not in stub_shaders})
        self.reset_to_stubs()
        # Configured every time (a few seconds when nothing changed): a lab added since the last run
        # is otherwise an unknown target to the old Makefiles, which never get to regenerate.
        run_checked(["cmake", "-S", str(ROOT), "-B", str(self.judge), "-DCMAKE_BUILD_TYPE=RelWithDebInfo"],
                    "configure the judge's build")
        targets = [t for lab in self.labs for t in (f"lab{lab['nn']}_solution", f"lab{lab['nn']}_solution_tests")]
        run_checked(["cmake", "--build", str(self.judge), "-j", str(jobs), "--target"] + targets,
                    "build the judge's build")
        cache = (self.build / "CMakeCache.txt").read_text() if (self.build / "CMakeCache.txt").exists() else None
        if cache is not None and (f"CMAKE_HOME_DIRECTORY:INTERNAL={self.src}\n" not in cache
                                  or "WB_REGISTER_TESTS:BOOL=OFF" not in cache):
            shutil.rmtree(self.build)  # a build of another source tree (an older grader's)
        own(self.build, self.builder, 0o755)
        env = dict(os.environ, HOME="/tmp")
        sandbox.checked(["cmake", "-S", str(self.src), "-B", str(self.build), "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                         "-DWB_REGISTER_TESTS=OFF"],  # (discovery would run the student's code in the build)
                        self.builder, env, "configure the runner's build (as the builder user)")
        sandbox.checked(["cmake", "--build", str(self.build), "-j", str(jobs), "--target"] + self.runner_targets(self.labs),
                        self.builder, env, "build the runner's build (as the builder user)")
        self.fresh_outputs()
        return time.time() - t0

    def fresh_outputs(self):
        """Empties the runners' folders, so nothing one submission's code left there meets the next:
        test-output/ is the visible runner's; tapes/ is root's, enterable by both runners, each tape
        in it its runner's alone."""
        for name in ("test-output", "tapes"):
            shutil.rmtree(self.build / name, ignore_errors=True)
        own(self.build / "test-output", self.uid)
        (self.build / "tapes").mkdir()
        os.chmod(self.build / "tapes", 0o711)

    def fresh_tape(self, tag, uid):
        """An empty folder for one runner's tape, its user's (`uid`) alone."""
        tape = self.build / "tapes" / tag
        shutil.rmtree(tape, ignore_errors=True)
        own(tape, uid)
        return tape


def own(folder, uid, mode=0o700):
    """Creates `folder` (if needed) and gives it, and what is in it, to `uid` (when root), the folder
    itself with `mode` (the user's alone by default)."""
    folder.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0:
        return
    for p in [folder] + list(folder.rglob("*")):
        try:
            os.lchown(p, uid, uid)
        except OSError:
            pass
    os.chmod(folder, mode)


def copy_tape(src, dest):
    """Copies a runner's tape for the judge: its regular files named as a tape's (no links, devices,
    folders or other files), up to MAX_TAPE_BYTES in all; what does not fit is left out, so the judge
    finds no result there."""
    shutil.rmtree(dest.parent, ignore_errors=True)
    dest.mkdir(parents=True)
    os.chmod(dest.parent, 0o700)
    total = 0
    for entry in sorted(os.scandir(src), key=lambda e: e.name) if src.is_dir() else []:
        if not entry.is_file(follow_symlinks=False) or not (entry.name == "tape.jsonl" or entry.name.startswith("file-")):
            continue  # only the tape's own files (tests/harness/tape.cpp names them)
        size = entry.stat(follow_symlinks=False).st_size
        if total + size > MAX_TAPE_BYTES:
            continue
        total += size
        try:
            fd = os.open(entry.path, os.O_RDONLY | os.O_NOFOLLOW)
        except OSError:
            continue
        with os.fdopen(fd, "rb") as f_in, open(dest / entry.name, "wb") as f_out:
            f_out.write(f_in.read(size))


def run_checked(cmd, what):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"grade: could not {what}:\n{r.stdout[-3000:]}{r.stderr[-3000:]}")


# --- Exercise chunks (as in common/glsl_harness.cpp) ----------------------------------------------
def find_marker(text, ex_id):
    """Where exercise ex_id's marker is: the exact id ("// EXERCISE 01" is not 01.3's), or -1."""
    m = re.search(r"// EXERCISE " + re.escape(ex_id) + r"(?=[ \t\r\n:]|$)", text)
    return m.start() if m else -1


def chunk(text, ex_id):
    marker = f"// EXERCISE {ex_id}"
    begin = find_marker(text, ex_id)
    if begin < 0:
        return None
    begin = text.rfind("\n", 0, begin) + 1
    end = text.find("// EXERCISE ", begin + len(marker))
    end = len(text) if end < 0 else text.rfind("\n", 0, end) + 1
    return begin, end


STUB_CODE = "stub of another exercise"


def keep_only_chunks(mine, stub, keep, path):
    """The student's whole file (helpers above the first marker included) with every exercise chunk
    whose id is not in `keep` swapped for the stub's (public code: no solution text is ever compiled
    with a student's; the judge runs the solution's code for those exercises anyway). The file is
    written at `path`; #line keeps compiler messages on the student's line numbers."""
    starts = [0 if p == 0 else mine.rfind("\n", 0, p) + 1 for p in
              (m.start() for m in re.finditer(r"// EXERCISE ", mine))]
    # (the stubs throw wb::NotImplemented, which the student's own includes may not declare)
    out = f'#include "common/error.hpp"\n#line 1 "{path}"\n' + mine[:starts[0] if starts else len(mine)]
    for k, begin in enumerate(starts):
        end = starts[k + 1] if k + 1 < len(starts) else len(mine)
        ex_id = re.match(r"[^\s:]+", mine[mine.index("// EXERCISE ", begin) + 12:])
        ex_id = ex_id.group(0) if ex_id else ""
        first = ex_id and mine.rfind("\n", 0, find_marker(mine, ex_id)) + 1 == begin  # the id's first marker
        theirs = chunk(stub, ex_id) if first and ex_id not in keep else None
        if not theirs:
            out += mine[begin:end]
            continue
        out += f'#line {stub.count(chr(10), 0, theirs[0]) + 1} "{STUB_CODE}"\n' + stub[theirs[0]:theirs[1]]
        out += ("" if out.endswith("\n") else "\n") + f'#line {mine.count(chr(10), 0, end) + 1} "{path}"\n'
    return out


def compiler_errors(output, limit=12):
    lines = [l for l in output.splitlines() if re.search(r"error|Error|undefined reference", l)]
    keep = lines[:limit] or output.strip().splitlines()[-limit:]
    return "\n".join(l[:300] for l in keep)


# --- Grading one submission -----------------------------------------------------------------------
BUILD_TIMED_OUT = "ERROR: the build timed out"
DEFAULT_BUILD_TIMEOUT = 300  # seconds for one build of a submission's code (--build-timeout)


SHARED_TMP = ("/tmp", "/var/tmp", "/dev/shm")


def sandbox_owned(path):
    """True when a sandbox user (uids 61000 to 61599: runners, held-out runners, builders) owns path."""
    try:
        return SANDBOX_UID <= os.lstat(path).st_uid < SANDBOX_UID + 600
    except OSError:
        return False


def writable_by_others(path):
    try:
        return bool(os.lstat(path).st_mode & stat.S_IWOTH) and not os.path.islink(path)
    except OSError:
        return False


def sweep_shared_tmp():
    """Removes what sandbox users left in the world-writable folders, so nothing one submission's code
    leaves there meets the next one's (a Mesa .drirc, a note for a later student). Only folders a
    sandbox user can write into are searched (not, say, a build tree in /tmp)."""
    for top in SHARED_TMP:
        for folder, dirs, files in os.walk(top):
            for name in files + dirs:
                p = Path(folder) / name
                if sandbox_owned(p):
                    try:
                        shutil.rmtree(p) if p.is_dir() and not p.is_symlink() else p.unlink(missing_ok=True)
                    except OSError:
                        pass
            dirs[:] = [d for d in dirs if writable_by_others(Path(folder) / d)]


def runner_stopped(code, out, timed_out, timeout):
    """[(test, message)] saying why a runner ended early (a time-out or a crash), or []."""
    running = re.findall(r"\[ RUN      \] (\S+)", out)
    test = running[-1] if running else ""
    if timed_out:
        return [(test, f"ERROR: timed out after {timeout} s (an endless loop in C++?); the process was killed")]
    if code < 0 or code > 128:
        sig = -code if code < 0 else code - 128
        name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else f"exit {code}"
        tail = "\n".join(out.strip().splitlines()[-8:])
        return [(test, f"ERROR: the tests crashed ({name}) in {test or 'start-up'}:\n{tail}")]
    return []


def build_failure(output):
    """What a failed build says about an exercise: the time-out message as it is, else the compiler's errors."""
    return output if output.startswith(BUILD_TIMED_OUT) else compiler_errors(output)


class Grader:
    def __init__(self, ws, labs, sandbox, timeout, jobs, build_timeout=DEFAULT_BUILD_TIMEOUT):
        self.ws, self.labs, self.sandbox, self.timeout = ws, labs, sandbox, timeout
        self.build_timeout = build_timeout  # seconds for one build of the submission's code
        self.build_jobs = self.test_jobs = max(1, jobs)  # cores for this submission
        self.build_timeouts = 0  # how many builds of this submission were stopped
        # A fresh variation of every scene per submission, unless the instructor fixes one to reproduce a grade.
        self.vary_seed = int(os.environ.get("WB_GRADE_SEED") or secrets.randbelow(1 << 32))

    def build(self, labs):
        """Builds the submission app and tests of `labs`: (ok, compiler output). A build that runs past
        the build time limit (compile-time work that takes too long: template or constexpr recursion,
        a huge file) is killed with its compilers and fails with a message that starts with
        BUILD_TIMED_OUT."""
        # The builder user compiles, in the sandbox: no network, no view of the solutions.
        code, out, timed_out = self.sandbox.run(
            ["cmake", "--build", str(self.ws.build), "-j", str(self.build_jobs), "--target"]
            + self.ws.runner_targets(labs), self.build_timeout, env=dict(os.environ, HOME="/tmp"), uid=self.ws.builder)
        if timed_out:
            self.build_timeouts += 1
            self.ws.after_killed_build(labs)
            return False, (f"{BUILD_TIMED_OUT} after {self.build_timeout} s and was stopped (compile-time work "
                           "that takes too long, such as deep template or constexpr recursion, or a huge file?)")
        return code == 0, out

    def build_lab(self, lab):
        return self.build([lab])

    def compile_lab(self, lab, files):
        """Builds the lab from the student's files. When exercise.cpp does not compile (or its build
        runs past the time limit), each C++ exercise is tried alone in the stub's file, so an error
        costs only the exercises it is in. Returns {exercise id: compiler message} for the exercises
        that cannot be graded. The student's `files` are already in place."""
        ok, out = self.build_lab(lab)
        if ok:
            return {}
        cpp_ids = [e["id"] for e in lab["exercises"] if e["file"] == "exercise.cpp"]
        stub = ROOT / "labs" / lab["name"] / "exercise.cpp"
        mine = files.get("exercise.cpp", b"").decode(errors="replace")
        failed, good = {}, {}
        if "exercise.cpp" not in files or not stub.exists():
            return {i: build_failure(out) for i in cpp_ids} or {e["id"]: build_failure(out) for e in lab["exercises"]}
        base = stub.read_text()
        for ex_id in cpp_ids:
            if chunk(mine, ex_id) is None:
                failed[ex_id] = f"the file has no '// EXERCISE {ex_id}' marker any more; keep the markers"
                continue
            hybrid = keep_only_chunks(mine, base, {ex_id}, self.ws.lab_dir(lab["name"]) / "exercise.cpp")
            self.ws.place(lab["name"], "exercise.cpp", hybrid.encode())
            ok, out1 = self.build_lab(lab)
            if ok:
                good[ex_id] = True
            else:
                failed[ex_id] = build_failure(out1)
        combined = keep_only_chunks(mine, base, set(good), self.ws.lab_dir(lab["name"]) / "exercise.cpp")
        self.ws.place(lab["name"], "exercise.cpp", combined.encode())
        ok, out2 = self.build_lab(lab)
        if not ok:  # the parts compile alone but not together: nothing C++ can be graded
            self.ws.place(lab["name"], "exercise.cpp", base.encode())
            ok, _ = self.build_lab(lab)
            failed.update({i: build_failure(out2) for i in good})
        if not ok:
            return {e["id"]: build_failure(out) for e in lab["exercises"]}
        return failed

    def list_tests(self, lab):
        exe = self.ws.build / f"lab{lab['nn']}_tests"
        if not exe.exists():  # the lab could not be built at all (every exercise is then marked broken)
            return []
        # The list comes from the judge (the same test sources, built with the solution): a submission
        # cannot hide a test by printing another list.
        judge = self.ws.judge / f"lab{lab['nn']}_solution_tests"
        code, out, _ = run_killable([str(judge), "--gtest_list_tests"], 60, cwd=self.ws.judge)
        tests, suite = [], ""
        for line in out.splitlines():
            if line and not line.startswith(" "):
                suite = line.split()[0]
            elif line.strip():
                tests.append(suite + line.split()[0])
        return tests

    def run_tests(self, lab, gfilter, tag, held_out=False, replay_uses=()):
        """Grades one exercise's tests: (passed, failures [(test, message)], runner output). The
        student's test binary runs as the *runner* in the sandbox and records what its C++ exercises
        produce on a tape; the solution's test binary, the *judge*, replays that tape, draws every
        scene itself (with the student's recorded C++ results, or the student's GLSL chunk) and
        decides. The runner's exit code, output and files claim nothing (tests/harness/tape.hpp).
        Held-out tests are in the judge only: a planning pass of the judge says which lab runs the
        runner must record (`held_out`)."""
        runner = self.ws.build / f"lab{lab['nn']}_tests"
        judge = self.ws.judge / f"lab{lab['nn']}_solution_tests"
        uid = self.ws.heldout_uid if held_out else self.ws.uid  # (held-out inputs: not for a visible run)
        tape = self.ws.fresh_tape(tag, uid)
        judged = self.ws.judge / "runs" / tag
        shutil.rmtree(judged, ignore_errors=True)
        judged.mkdir(parents=True)
        # WB_VARY_SEED: scene tests turn the scene a little and compare with the solution's render of
        # the same variation, not with the published golden (tests/harness/harness.cpp). Each
        # process has a home of its own: nothing in a shared /tmp (a Mesa .drirc) reaches it.
        env = dict(os.environ, HOME=str(tape), TMPDIR=str(tape), WB_STRICT_GL="1",
                   WB_VARY_SEED=str(self.vary_seed), WB_RECORD_SHADERS=str(self.ws.stubs / lab["name"] / "shaders"))
        # WB_REPLAY_USES: the used exercises (manifest "uses") that failed their own tests, the only
        # ones whose recorded results the judge replays beside the graded one; WB_HELD_OUT: quote
        # nothing the runner wrote (it could carry held-out inputs).
        jenv = dict(env, HOME=str(judged), TMPDIR=str(judged), WB_SUBMISSION_DIR=str(self.ws.lab_dir(lab["name"])),
                    WB_REPLAY_USES=",".join(replay_uses), WB_HELD_OUT="1" if held_out else "")
        what = ["--requests", str(self.plan(lab, judge, gfilter, judged, jenv, tape, uid))] if held_out \
            else [f"--gtest_filter={gfilter}"]
        code, out, timed_out = self.sandbox.run([str(runner)] + what + ["--runner", str(tape)], self.timeout,
                                                env=env, cwd=tape, uid=uid)
        if held_out:  # the held-out inputs go as soon as they are used, and nothing of them is quoted
            shutil.rmtree(tape / "inputs", ignore_errors=True)
            (tape / "requests.jsonl").unlink(missing_ok=True)
            out = ""
        stopped = runner_stopped(code, out, timed_out, self.timeout)  # shown before what the judge found
        copy_tape(tape, judged / "tape")
        report = judged / "report.json"
        jcode, jout, jtimed = run_killable([str(judge), f"--gtest_filter={gfilter}", "--judge", str(judged / "tape"),
                                            f"--gtest_output=json:{report}"], self.timeout, env=jenv, cwd=judged)
        if jtimed:
            return False, stopped + [("", f"ERROR: timed out after {self.timeout} s while the judge drew this "
                                      "exercise with your shaders (an endless loop in a shader?)")], out
        if not report.exists():
            return False, stopped + [("", "ERROR: the judge could not finish (a fault of the grader, not of the "
                                      f"submission: tell the instructor):\n{jout[-2000:]}")], out
        data = json.loads(report.read_text())
        failures, count = [], 0
        for suite in data.get("testsuites", []):
            for t in suite.get("testsuite", []):
                count += 1
                for f in t.get("failures", []):
                    failures.append((f"{suite['name']}.{t['name']}", f["failure"]))
        if count == 0:
            return False, stopped + [("", "ERROR: no tests ran")], out
        failures = stopped + failures
        return not failures, failures, out

    def plan(self, lab, judge, gfilter, judged, env, tape, uid):
        """The judge's planning pass over held-out tests: the lab runs (JSON lines {key, args}) and the
        calls of C++ exercises on held-out inputs ({key, call, inputs}) the runner must record, written into its tape folder as requests.jsonl, with each input file of
        the instructor's (a held-out scene) copied beside it, since the runner cannot read them."""
        plan = judged / "plan.jsonl"
        (judged / "empty").mkdir()
        code, _, timed_out = run_killable([str(judge), f"--gtest_filter={gfilter}", "--judge", str(judged / "empty")],
                                            self.timeout, env=dict(env, WB_PLAN=str(plan)), cwd=judged)
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

    def grade_exercise(self, lab, e, tests, broken, replay_uses=()):
        """(ok, failures, images, hidden result, has hidden tests) of one exercise with the current build."""
        ex_id, tag = e["id"], e["id"].replace(".", "_")
        mine = [t for t in tests if f".Ex{tag}_" in t]
        has_hidden = any(t.startswith("Hidden") for t in mine)
        if ex_id in broken:
            msg = broken[ex_id]
            msg = msg if msg.startswith("ERROR") else f"ERROR: does not compile: {first_line(msg)}\n{msg}"
            return False, [("", msg)], [], None, has_hidden
        ok, failures, _ = self.run_tests(lab, f"*.Ex{tag}_*-Hidden*.*", f"{tag}_visible", replay_uses=replay_uses)
        hidden_result = None
        if has_hidden and any("timed out after" in m for _, m in failures):  # another wait would tell nothing new
            hidden_result = (False, [("", "ERROR: not run: the exercise's other tests timed out")], "")
        elif has_hidden:
            hidden_result = self.run_tests(lab, f"Hidden*.Ex{tag}_*", f"{tag}_hidden", held_out=True,
                                           replay_uses=replay_uses)
        kept = copy_images(failures + (hidden_result[1] if hidden_result else []), self.images, tag)
        return ok, failures, kept, hidden_result, has_hidden

    def grade_alone(self, lab, e, mine, tests, replay_uses=()):
        """Grades C++ exercise `e` with only its own chunk from `mine`, and those of the exercises it
        takes its inputs from ("uses" in the manifest: the judge replays those too), the stubs for the
        others."""
        stub = ROOT / "labs" / lab["name"] / "exercise.cpp"
        keep = {e["id"], *e.get("uses", [])}
        hybrid = keep_only_chunks(mine, stub.read_text(), keep, self.ws.lab_dir(lab["name"]) / "exercise.cpp") \
            if stub.exists() and chunk(mine, e["id"]) else None
        if hybrid is None:
            return None
        self.ws.place(lab["name"], "exercise.cpp", hybrid.encode())
        ok, _ = self.build_lab(lab)
        if not ok:
            return None
        return self.grade_exercise(lab, e, tests, {}, replay_uses)

    def grade(self, submission, out_dir, name):
        """Grades one submission into out_dir and returns its result. Whatever goes wrong is recorded
        in the result, never raised: an exception of the grader itself costs the exercises not graded
        yet (with the exception as their reason), and the batch goes on."""
        t0 = time.time()
        out_dir.mkdir(parents=True, exist_ok=True)
        os.chmod(out_dir, 0o700)  # private while it is being written; readable once finished
        self.images = out_dir / "images"
        results = Results(out_dir, name, self.labs, self.sandbox)
        results.vary_seed = self.vary_seed
        try:
            self.grade_into(results, submission)
        except Exception as exc:  # a bug of the grader, or of the machine: this submission only
            log(f"grade: the grader failed on {name}:\n{traceback.format_exc()}")
            results.problems.append(grader_failed(exc))
            results.fail_rest(f"ERROR: {grader_failed(exc)}; this exercise was not graded (a fault of the "
                              "grader, not of the submission: tell the instructor)")
        if self.build_timeouts:
            n = self.build_timeouts
            results.problems.append(f"{n} build{'s' if n > 1 else ''} of this submission ran past the build time "
                                    f"limit of {self.build_timeout} s and {'were' if n > 1 else 'was'} stopped: the "
                                    "exercises that could not be built scored 0")
        sweep_shared_tmp()
        try:
            return results.finish(time.time() - t0)
        finally:
            os.chmod(out_dir, 0o755)

    def grade_into(self, results, submission):
        with tempfile.TemporaryDirectory(prefix="grade-") as scratch:
            try:
                folder = unpack(submission, scratch)
            except (ValueError, OSError, zipfile.BadZipFile, tarfile.TarError) as e:
                results.fail_all(f"ERROR: the submission could not be read: {e}")
                return
            self.ws.reset_to_stubs()
            self.ws.fresh_outputs()
            t_build = time.time()
            found_files = {}
            for lab in self.labs:  # every lab's files first: one parallel build for all when they compile
                files, notes = {}, []
                for rel in student_files(lab):
                    found, note = find_student_file(folder, lab["name"], rel, [l["name"] for l in self.labs])
                    if note:
                        notes.append(note)
                    if found is None:
                        notes.append(f"labs/{lab['name']}/{rel} is not in the submission: the stub is graded")
                    elif found.stat().st_size > MAX_FILE_BYTES:
                        notes.append(f"labs/{lab['name']}/{rel} is over 1 MiB: the stub is graded")
                    else:
                        files[rel] = found.read_bytes()
                found_files[lab["name"]] = (files, notes)
                for rel, content in files.items():
                    self.ws.place(lab["name"], rel, content)
            all_built, _ = self.build(self.labs)  # one parallel build when every lab compiles
            results.timing["build"] = time.time() - t_build
            t_tests = time.time()
            for lab in self.labs:
                files, notes = found_files[lab["name"]]
                broken = {}
                if not all_built:
                    broken = self.compile_lab(lab, files)
                tests = self.list_tests(lab)
                with concurrent.futures.ThreadPoolExecutor(self.test_jobs) as pool:  # one process each
                    outcome, failed_uses = {}, {}
                    pending = list(lab["exercises"])
                    while pending:  # in "uses" order: an exercise after those whose results it takes
                        wave = [e for e in pending if all(u in outcome for u in e.get("uses", []))] or pending
                        for e in wave:
                            failed_uses[e["id"]] = [u for u in e.get("uses", []) if u in outcome and not outcome[u][0]]
                        futures = {e["id"]: pool.submit(self.grade_exercise, lab, e, tests, broken,
                                                        failed_uses[e["id"]]) for e in wave}
                        outcome.update({i: f.result() for i, f in futures.items()})
                        pending = [e for e in pending if e["id"] not in outcome]
                # A C++ exercise runs in the app with the student's other C++ exercises: when several
                # fail, one may be failing because of another (a crash, a loop, a wrong light fit).
                # Each is then graded again in the stub's file with only its own chunk.
                cpp_ids = [e["id"] for e in lab["exercises"] if e["file"] == "exercise.cpp"]
                failing = [i for i in cpp_ids if i in broken or not outcome[i][0]]
                failed = [e for e in lab["exercises"] if e["id"] in failing and e["id"] not in broken
                          and runs_app(outcome[e["id"]])]
                if failed and len(failing) >= 2 and "exercise.cpp" in files:
                    for e in failed:
                        alone = self.grade_alone(lab, e, files["exercise.cpp"].decode(errors="replace"), tests,
                                                 failed_uses[e["id"]])
                        if alone is not None:
                            outcome[e["id"]] = alone
                for e in lab["exercises"]:
                    ok, failures, kept, hidden_result, has_hidden = outcome[e["id"]]
                    results.add(lab, e, ok, failures, kept, notes, hidden_result=hidden_result, hidden=has_hidden)
            results.timing["tests"] = time.time() - t_tests


def grader_failed(exc):
    return f"the grader failed on this submission: {type(exc).__name__}: {exc}".rstrip(": ")


def runs_app(outcome):
    """Whether a failure came from a test that runs the lab app (by convention their names have Scene
    or Measured in them), where the student's other C++ exercises run too."""
    _, failures, _, hidden_result, _ = outcome
    every = failures + (hidden_result[1] if hidden_result else [])
    return any("Scene" in test or "Measured" in test for test, _ in every)


def copy_images(failures, images, tag):
    kept = []
    for test, msg in failures:
        for label, path in re.findall(r"(diff|reference|result): (\S+\.png)", msg):
            src = Path(path)
            if src.exists():
                images.mkdir(parents=True, exist_ok=True)
                dest = images / f"{tag}_{src.parent.name}_{label}.png"
                shutil.copyfile(src, dest)
                kept.append((test, label, dest.name))
    return kept


# --- Results: results.json, junit.xml, report.md, report.html -------------------------------------
def first_line(msg):
    """The diagnosis: the first line that starts at NOT IMPLEMENTED, WRONG or ERROR (gtest puts the
    test's file and line first), else the first line."""
    for line in msg.splitlines():
        for key in ("NOT IMPLEMENTED", "WRONG", "ERROR"):
            if key in line:
                return line[line.index(key):].strip()
    for line in msg.splitlines():
        if line.strip():
            return line.strip()
    return ""


def status_of(failures):
    text = " ".join(m for _, m in failures)
    return ("error" if "ERROR" in text else "wrong" if "WRONG" in text
            else "not implemented" if "NOT IMPLEMENTED" in text else "wrong")


# What students see on Gradescope holds none of the grader's paths or build commands (the instructor's
# report.md, report.html and junit.xml keep them): a line of make or of a compiler command goes, the
# student's own file is named as labs/NN_name/..., and any other path shrinks to its file name.
_BUILD_LINE = re.compile(r"^\s*(g?make(\[\d+\])?: |\[\s*\d+%\]|cd /|/usr/bin/(c\+\+|g\+\+|gcc|cc|clang|ld)\b|"
                         r"(/\S+/)?cmake (--build|-S|-E)\b|ninja: |Scanning dependencies|Consolidate compiler)")
_STUDENT_FILE = re.compile(r"(?:[\w.+-]*/)*(labs/\d\d_[\w-]+/[^\s:'\"()\[\],]+)")
_ANY_PATH = re.compile(r"(?<![\w.~-])(?:/|(?:\.{1,2}|[\w.+-]+)/)(?:[^\s/:'\"()\[\],]+/)+([^\s/:'\"()\[\],]+)")


def student_visible(text):
    """`text` without grader paths, build commands or absolute paths (see above)."""
    lines = [l for l in text.replace(str(ROOT) + "/", "").splitlines() if not _BUILD_LINE.search(l)]
    out = "\n".join(lines)
    out = _STUDENT_FILE.sub(r"\1", out)
    return _ANY_PATH.sub(lambda m: m.group(0) if m.group(0).startswith("labs/") else m.group(1), out)


VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")


def gradescope_visibility(visibility, points):
    """The visibility written for a test with `points`. Gradescope's specification: students do not see
    their total score while a test is hidden, but `hidden` tests do not count for that, since they are
    meant to carry no points; held-out points under `hidden` would show in the total, so such a test
    is written as after_published (shown when the instructor publishes the grades)."""
    if visibility not in VISIBILITIES:
        raise ValueError(f"visibility {visibility!r} is not one of {', '.join(VISIBILITIES)}")
    return "after_published" if visibility == "hidden" and points > 0 else visibility


class Results:
    def __init__(self, out_dir, name, labs, sandbox):
        self.out, self.name, self.labs, self.sandbox = out_dir, name, labs, sandbox
        self.entries = []  # one per exercise (and one per exercise's held-out tests)
        self.timing = {"build": 0.0, "tests": 0.0}
        self.problems = []  # what stopped the grading of some of it (build time-outs, grader failures)
        self.max_score = sum(e["points"] for l in labs for e in l["exercises"] if not e.get("extension"))
        self.write_json(partial=True)

    def fail_all(self, message):
        for lab in self.labs:
            for e in lab["exercises"]:
                self.add(lab, e, False, [("", message)], [], [])

    def fail_rest(self, message):
        """Every exercise that has no result yet fails with `message` (those graded keep theirs)."""
        graded = {(x["lab"], x["id"]) for x in self.entries}
        for lab in self.labs:
            for e in lab["exercises"]:
                if (lab["name"], e["id"]) not in graded:
                    self.add(lab, e, False, [("", message)], [], [])

    def add(self, lab, e, ok, failures, images, notes, hidden_result=None, hidden=False):
        hidden_points = lab["hidden_points"].get(e["id"], 0) if hidden else 0
        visible_points = e["points"] - hidden_points
        bonus = " (extension: bonus points)" if e.get("extension") else ""
        entry = {"lab": lab["name"], "id": e["id"], "title": e["title"] + bonus, "points": visible_points,
                 "score": visible_points if ok else 0, "ok": ok, "failures": failures, "images": images,
                 "notes": notes, "visibility": "visible", "extension": bool(e.get("extension")),
                 "status": "done" if ok else status_of(failures)}
        self.entries.append(entry)
        if hidden:
            h_ok, h_failures = (hidden_result[0], hidden_result[1]) if hidden_result else (False, failures)
            self.entries.append({"lab": lab["name"], "id": e["id"], "title": e["title"] + " (held-out tests)",
                                 "points": hidden_points, "score": hidden_points if h_ok else 0, "ok": h_ok,
                                 "failures": h_failures, "images": [], "notes": [], "extension": False,
                                 "visibility": gradescope_visibility(lab["hidden_visibility"], hidden_points),
                                 "status": "done" if h_ok else status_of(h_failures)})
        self.write_json(partial=True)

    def score(self):
        return sum(x["score"] for x in self.entries)

    def entry_output(self, x):
        """Markdown for Gradescope: the status, notes and first failures, without the grader's paths."""
        lines = [f"**{x['status']}**"] + [f"- {n}" for n in x["notes"]]
        for test, msg in x["failures"][:5]:
            lines.append(f"\n`{test}`\n```\n{msg.strip()[:2000]}\n```" if test else f"\n```\n{msg.strip()[:2000]}\n```")
        return student_visible("\n".join(lines))

    def environment(self):
        """How the tests ran, for the instructor: a Gradescope test that students never see, with no
        points, failed when the isolation was weaker than intended (no network namespace in the
        container, tests not run as nobody)."""
        notes = self.sandbox.notes
        seed = getattr(self, "vary_seed", None)
        text = (f"Tests ran as {self.sandbox.user}, each exercise in its own process" +
                (f"; scenes varied with seed {seed} (WB_GRADE_SEED={seed} reproduces this grade)" if seed is not None
                 else "") + ".\n\n" +
                ("".join(f"- **{n}**\n" for n in notes) if notes else "- Isolation as intended: no network, an "
                 "unprivileged user."))
        return {"name": "Grading environment (instructors only)", "score": 0, "max_score": 0,
                "status": "failed" if notes else "passed", "output": text, "output_format": "md",
                "tags": ["grading-environment"], "visibility": "hidden"}

    def summary(self, partial):
        """The top-level output, which students always see: the points of the tests they can see now,
        never the total while held-out tests (after_due_date, after_published) are still hidden."""
        if partial:
            done = len({(x["lab"], x["id"]) for x in self.entries})
            total = sum(len(l["exercises"]) for l in self.labs)
            return f"Graded {done} of {total} exercises so far (grading stopped or is still running)."
        later = [x for x in self.entries if x["visibility"] != "visible" and x["points"] > 0 and not x["extension"]]
        if later:
            seen = [x for x in self.entries if x["visibility"] == "visible"]
            text = (f"{sum(x['score'] for x in seen)} of {sum(x['points'] for x in seen if not x['extension'])} "
                    f"points in the tests shown now. Held-out tests decide {sum(x['points'] for x in later)} more "
                    "points; they and the total are shown after the due date (or when grades are published).")
        else:
            text = f"{self.score()} of {self.max_score} points."
        return student_visible(text + "".join(f"\n\n**Note:** {p}." for p in self.problems))

    def write_json(self, partial, elapsed=0.0):
        """results.json, with only the keys of Gradescope's autograder specification (docs/gradescope.md).
        The top-level score is the total (the grade); Gradescope hides it from students while a test
        that carries points is not visible yet."""
        tests = [{"name": f"{x['id']} {x['title']}", "number": x["id"], "score": x["score"],
                  "max_score": 0 if x["extension"] else x["points"], "status": "passed" if x["ok"] else "failed",
                  "output": self.entry_output(x), "output_format": "md", "visibility": x["visibility"]}
                 for x in self.entries]
        doc = {"score": self.score(), "output": self.summary(partial), "output_format": "md",
               "visibility": "visible", "stdout_visibility": "hidden",
               "extra_data": {"max_score": self.max_score, "student": self.name},
               "tests": tests + [self.environment()]}
        if not partial:
            doc["execution_time"] = round(elapsed, 1)
        tmp = self.out / "results.json.tmp"
        tmp.write_text(json.dumps(doc, indent=2))
        os.replace(tmp, self.out / "results.json")  # always a whole, valid file

    def finish(self, elapsed):
        self.write_json(partial=False, elapsed=elapsed)
        self.write_junit(elapsed)
        self.write_reports(elapsed)
        return {"name": self.name, "score": self.score(), "max_score": self.max_score, "entries": self.entries,
                "seconds": elapsed, "timing": self.timing, "problems": self.problems,
                "environment": list(self.sandbox.notes)}

    def write_junit(self, elapsed):
        parts = ['<?xml version="1.0" encoding="UTF-8"?>',
                 f'<testsuites name={quoteattr(self.name)} tests="{len(self.entries)}" '
                 f'failures="{sum(not x["ok"] for x in self.entries)}" time="{elapsed:.1f}">']
        for lab in self.labs:
            mine = [x for x in self.entries if x["lab"] == lab["name"]]
            parts.append(f'  <testsuite name="lab{lab["nn"]}" tests="{len(mine)}" '
                         f'failures="{sum(not x["ok"] for x in mine)}">')
            for x in mine:
                parts.append(f'    <testcase classname="lab{lab["nn"]}" name={quoteattr(x["id"] + " " + x["title"])}>')
                if not x["ok"]:
                    text = "\n\n".join(f"{t}\n{m}" for t, m in x["failures"])
                    parts.append(f'      <failure message={quoteattr(first_line(text) or x["status"])}>'
                                 f'{escape(text[:8000])}</failure>')
                parts.append("    </testcase>")
            parts.append("  </testsuite>")
        parts.append("</testsuites>")
        (self.out / "junit.xml").write_text("\n".join(parts) + "\n")

    def write_reports(self, elapsed):
        md = [f"# Grading report: {self.name}", "",
              f"**{self.score()} of {self.max_score} points** (graded in {elapsed:.0f} s: build "
              f"{self.timing['build']:.0f} s, tests {self.timing['tests']:.0f} s; tests ran as "
              f"{self.sandbox.user}, each exercise in its own process)."]
        md += [f"- **isolation: {n}**" for n in self.sandbox.notes]
        md += [f"- **{p}**" for p in self.problems]
        body = [f"<h1>Grading report: {html.escape(self.name)}</h1>",
                f"<p><b>{self.score()} of {self.max_score} points</b> (graded in {elapsed:.0f} s)</p>"]
        body += [f"<p><b>{html.escape(p)}</b></p>" for p in self.problems]
        body += [f"<p><b>isolation: {html.escape(n)}</b></p>" for n in self.sandbox.notes]
        for lab in self.labs:
            mine = [x for x in self.entries if x["lab"] == lab["name"]]
            md += ["", f"## Lab {lab['nn']}: {lab['title']}", "", "| exercise | status | points |", "|---|---|---|"]
            md += [f"| {x['id']} {x['title']} | {x['status']} | {x['score']} / {x['points']} |" for x in mine]
            body.append(f"<h2>Lab {lab['nn']}: {html.escape(lab['title'])}</h2><table border=1 cellpadding=4>"
                        "<tr><th>exercise</th><th>status</th><th>points</th></tr>")
            body += [f"<tr><td>{x['id']} {html.escape(x['title'])}</td><td>{x['status']}</td>"
                     f"<td>{x['score']} / {x['points']}</td></tr>" for x in mine]
            body.append("</table>")
            for x in mine:
                if x["ok"] and not x["notes"]:
                    continue
                md += ["", f"### {x['id']} {x['title']}: {x['status']}"] + [f"- {n}" for n in x["notes"]]
                body.append(f"<h3>{x['id']} {html.escape(x['title'])}: {x['status']}</h3>")
                body += [f"<p>{html.escape(n)}</p>" for n in x["notes"]]
                for test, msg in x["failures"][:5]:
                    md += ["", f"`{test}`" if test else "", "```", msg.strip()[:3000], "```"]
                    body.append(f"<p><code>{html.escape(test)}</code></p><pre>{html.escape(msg.strip()[:3000])}</pre>")
                for test, label, img in x["images"]:
                    md.append(f"![{label}](images/{img})")
                    body.append(f"<figure style='display:inline-block'><img src='images/{img}' width=256>"
                                f"<figcaption>{label}</figcaption></figure>")
        (self.out / "report.md").write_text("\n".join(md) + "\n")
        (self.out / "report.html").write_text("<!doctype html><meta charset=utf-8><title>Grading report</title>"
                                              "<body style='font-family:sans-serif'>" + "\n".join(body) + "</body>\n")


# --- Batch ------------------------------------------------------------------------------------------
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
    md += ["", "| student | score | seconds (build + tests) |", "|---|---|---|"]
    md += [f"| {r['name']} | {r['score']} / {r['max_score']} | {r['seconds']:.1f} ({r['timing']['build']:.1f} + "
           f"{r['timing']['tests']:.1f}) |" for r in sorted(results, key=lambda r: r["name"])]
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


def hide_from_sandbox(paths):
    """Makes `paths` (the checkout's solutions, held-out tests, git history and other builds; the
    submissions and the results) unreadable to the sandbox users while grading runs, and puts their
    modes back when it ends. Only the student edition in build-grade/wK stays in their reach."""
    modes = {}
    for p in paths:
        try:
            st = os.lstat(p)
            if not stat.S_ISLNK(st.st_mode):
                modes[p] = stat.S_IMODE(st.st_mode)
                os.chmod(p, modes[p] & ~0o077)
        except OSError:
            pass
    atexit.register(lambda: [os.chmod(p, m) for p, m in modes.items() if p.exists()])


def main():
    ap = argparse.ArgumentParser(prog="workbook grade", description=__doc__.split("\n")[0])
    ap.add_argument("submission", nargs="?", help="a submission (folder or archive), or with --batch a folder of them")
    ap.add_argument("--prepare-only", action="store_true", help="only build the grading framework (Gradescope's setup)")
    ap.add_argument("--batch", action="store_true", help="grade every folder or archive inside SUBMISSION")
    ap.add_argument("--out", help="where the results go (default: grades/<name>)")
    ap.add_argument("--labs", help="only these labs, e.g. 01,02")
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
    ap.add_argument("--name", help="the student's name in the reports (default: the submission's name)")
    args = ap.parse_args()
    only = [x.strip().zfill(2) for x in args.labs.split(",")] if args.labs else None
    labs = load_labs(only)
    sandbox = Sandbox()
    if args.prepare_only:
        secs = Workspace(0, labs, ROOT / "build-grade").prepare(os.cpu_count() or 2, sandbox)
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
    base = ROOT / "build-grade"
    if sandbox.drop:  # what the student's code must not read: everything of the instructor's but its trees
        hide_from_sandbox([p for p in ROOT.iterdir() if p.name != "build-grade"] + [out] + ([src] if args.batch else []))
    for n in sandbox.notes:
        log(f"grade: note: {n}")
    spaces = [Workspace(k, labs, base) for k in range(workers)]
    for ws in spaces:
        log(f"grade: preparing the grading build {ws.dir} (the first time builds the framework) ...")
        secs = ws.prepare(max(1, (os.cpu_count() or 2)), sandbox)
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
        cores = max(1, (os.cpu_count() or 2) // workers)
        return Grader(ws, labs, sandbox, args.timeout, cores, args.build_timeout).grade(sub, dest, name)

    def fail_one(sub, problem, elapsed):
        name, dest = where(sub)
        return salvage(dest, name, labs, sandbox, problem, elapsed)

    def progress(r):
        done[0] += 1
        print(f"\r[{done[0]}/{len(subs)}] {r['name']}: {r['score']} of {r['max_score']} "
              f"({r['seconds']:.0f} s)" + " " * 20, end="" if args.batch else "\n", file=sys.stderr, flush=True)

    t0 = time.time()
    results = grade_all(subs, spaces, grade_one, fail_one, progress)
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


if __name__ == "__main__":
    sys.exit(main())
