"""The grading trees: the runner's student edition and the judge's solution build, prepared once
and reused for every submission, and the copy of a runner's tape the judge reads."""
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

from .common import BUILDER_UID, MAX_TAPE_BYTES, ROOT, SANDBOX_UID, open_regular
from .sandbox import minimal_env
from .submission import load_labs, student_files


# The framework's static libraries and the tests' main in a build folder (cmake/Framework.cmake).
FRAMEWORK_LIBRARIES = ("libglad.a", "common/libwb_common.a", "common/judge/libwb_testing.a",
                       "common/judge/CMakeFiles/wb_testing_main.dir/main.cpp.o")
FRAMEWORK_TARGETS = ["glad", "wb_common", "wb_testing", "wb_testing_main", "wb_check"]


def instructor_paths():
    """What the student edition leaves out (tools/grading/instructor_paths.txt), relative to ROOT."""
    lines = (ROOT / "tools/grading/instructor_paths.txt").read_text().splitlines()
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

    def __init__(self, index, labs, base, judge_build=None):
        self.uid = SANDBOX_UID + index  # runs the student's code (when the grader is root)
        self.heldout_uid = SANDBOX_UID + 100 + index  # and its held-out runs, apart from the visible ones
        self.builder = BUILDER_UID + index  # compiles it
        self.dir = base / f"w{index}"
        self.src = self.dir / "src"
        self.build = self.dir / "build"
        self.judge = base / "judge" / f"w{index}"  # the judge's runs (root's alone)
        # The judge's binaries: its own build, or an existing solution build of this checkout (--judge-build)
        self.judge_bin = Path(judge_build).resolve() if judge_build else self.judge
        self.stubs = self.dir / "stubs"  # the public stub shaders, for the runner's recording runs
        self.framework = self.dir / "framework"  # the judge build's framework libraries, which the runner links
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

    def remove_student_programs(self):
        """After a batch: the last submission's programs go, so that nobody runs one outside the
        sandbox by mistake (an instructor who tries a binary in build-grade/ would run that student's
        code as themselves, with all their rights). The next build links them again."""
        for lab in load_labs():
            for name in (f"lab{lab['nn']}", f"lab{lab['nn']}_tests"):
                (self.build / name).unlink(missing_ok=True)

    def runner_targets(self, labs):
        return [t for lab in labs for t in (f"lab{lab['nn']}", f"lab{lab['nn']}_tests")]

    def build_command(self, jobs, labs):
        """The build of a submission's `labs` in the prepared tree. Only exercise files change between
        submissions, never a CMake input, so one make goes straight to the targets' `all` rules in
        CMakeFiles/Makefile2, without CMake's check of the configuration (its globs and generators: about
        a second for every build). (Not the targets' names there: each runs a make of its own, and two
        of them at once would compile the shared exercise object at the same time.)"""
        if (self.build / "CMakeFiles" / "Makefile2").is_file():
            return ["make", "-f", "CMakeFiles/Makefile2", "-j", str(jobs)] + \
                [f"CMakeFiles/{t}.dir/all" for t in self.runner_targets(labs)]
        return ["cmake", "--build", str(self.build), "-j", str(jobs), "--target"] + self.runner_targets(labs)

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
        self.prepare_judge(jobs)
        flags = self.take_framework()
        cache = (self.build / "CMakeCache.txt").read_text() if (self.build / "CMakeCache.txt").exists() else None
        if cache is not None and (f"CMAKE_HOME_DIRECTORY:INTERNAL={self.src}\n" not in cache
                                  or "WB_REGISTER_TESTS:BOOL=OFF" not in cache):
            shutil.rmtree(self.build)  # a build of another source tree (an older grader's)
        own(self.build, self.builder, 0o755)
        env = minimal_env(HOME="/tmp")  # (a compile error could quote /proc/self/environ)
        sandbox.checked(["cmake", "-S", str(self.src), "-B", str(self.build), *flags, "-DWB_REGISTER_TESTS=OFF",
                         f"-DWB_PREBUILT_FRAMEWORK={self.framework}"],  # (discovery would run the student's code)
                        self.builder, env, "configure the runner's build (as the builder user)", **self.builder_binds())
        sandbox.checked(["cmake", "--build", str(self.build), "-j", str(jobs), "--target"] + self.runner_targets(self.labs),
                        self.builder, env, "build the runner's build (as the builder user)", **self.builder_binds())
        self.fresh_outputs()
        return time.time() - t0

    def take_framework(self):
        """Copies the framework's static libraries from the judge's build (the same source, which the
        student edition shares) for the runner's build to link, so that it compiles only the labs; returns
        the judge's build type and flags, which the runner's build takes too. The libraries hold no
        solution (cmake/Framework.cmake)."""
        cache = (self.judge_bin / "CMakeCache.txt").read_text()
        flags = [f"-D{key}={value}" for key, value in re.findall(r"^(CMAKE_BUILD_TYPE|CMAKE_C_FLAGS|CMAKE_CXX_FLAGS):"
                                                                  r"[A-Z]+=(.*)$", cache, re.M)]
        self.framework.mkdir(parents=True, exist_ok=True)
        os.chmod(self.framework, 0o755)
        for rel in FRAMEWORK_LIBRARIES + ("wb_check",):  # (wb_check: the runner's supervisor, as in check)
            src, dest = self.judge_bin / rel, self.framework / Path(rel).name
            if not dest.is_file() or dest.read_bytes() != src.read_bytes():
                shutil.copyfile(src, dest)  # (a new time only when it changed: make relinks the labs)
            os.chmod(dest, 0o755 if rel == "wb_check" else 0o644)
        return flags

    def prepare_judge(self, jobs):
        """Builds (or brings up to date) the judge's solution build: its own, or the instructor's
        existing build of this same checkout (--judge-build), which must be one."""
        if self.judge_bin != self.judge:
            cache = self.judge_bin / "CMakeCache.txt"
            if not cache.is_file() or f"CMAKE_HOME_DIRECTORY:INTERNAL={ROOT}\n" not in cache.read_text():
                raise SystemExit(f"grade: --judge-build {self.judge_bin} is not a build of {ROOT} (no CMakeCache.txt "
                                 "naming it): give the folder of ./workbook build (build/) or leave the option out")
        else:  # configured every time (a few seconds when nothing changed): a lab added since the last
            # run is otherwise an unknown target to the old Makefiles, which never get to regenerate
            run_checked(["cmake", "-S", str(ROOT), "-B", str(self.judge), "-DCMAKE_BUILD_TYPE=RelWithDebInfo"],
                        "configure the judge's build")
        # (wb_check: its --fill-missing, for a file written against an earlier edition of a lab)
        targets = [t for lab in self.labs for t in (f"lab{lab['nn']}_solution", f"lab{lab['nn']}_solution_tests")]
        targets.append("wb_check")
        if not (ROOT / "solutions").is_dir():  # a public image (PrairieLearn's): the framework alone, the
            targets = FRAMEWORK_TARGETS  # solutions come with each job (tools/grading/prairielearn)
        run_checked(["cmake", "--build", str(self.judge_bin), "-j", str(jobs), "--target"] + targets,
                    "build the judge's build")

    def uids(self):
        """The sandbox users of this tree: its builder, runner and held-out runner."""
        return {self.builder, self.uid, self.heldout_uid}

    def builder_binds(self):
        """What a build of the student's code sees in the sandbox: the student edition (read only) and
        its build folder, less the runners' tapes and outputs."""
        return {"ro": [self.src, self.framework], "rw": [self.build], "cwd": self.build}

    def runner_binds(self, tape, held_out):
        """What a runner sees: the student edition, its build, the stub shaders and the framework (whose
        wb_check supervises it), read only; its own tape folder, writable; no other runner's tape, and a
        test-output/ of its own (empty, gone when it ends) so nothing is written in common by a held-out
        run and a visible one."""
        hide = [self.build / "tapes", self.build / "test-output"]
        return {"ro": [self.src, self.build, self.stubs, self.framework], "rw": [tape], "hide": hide}

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
    finds no result there. `src` itself may be the student's (wb_check's all/): a link there is not
    followed (it could point at another run's tape, a held-out one)."""
    shutil.rmtree(dest.parent, ignore_errors=True)
    dest.mkdir(parents=True)
    os.chmod(dest.parent, 0o700)
    total = 0
    for entry in sorted(os.scandir(src), key=lambda e: e.name) if src.is_dir() and not src.is_symlink() else []:
        if not entry.is_file(follow_symlinks=False) or not (entry.name == "tape.jsonl" or entry.name.startswith("file-")):
            continue  # only the tape's own files (common/judge/tape.cpp names them)
        size = entry.stat(follow_symlinks=False).st_size
        if total + size > MAX_TAPE_BYTES:
            continue
        total += size
        f_in = open_regular(entry.path)  # (a FIFO swapped in since scandir is not opened)
        if f_in is None:
            continue
        with f_in, open(dest / entry.name, "wb") as f_out:
            f_out.write(f_in.read(size))


def run_checked(cmd, what):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"grade: could not {what}:\n{r.stdout[-3000:]}{r.stderr[-3000:]}")
