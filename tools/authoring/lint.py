#!/usr/bin/python3
"""The repository's own sources pass the linters that CONTRIBUTING.md names (ctest label framework):

  lint.py clang-format [ROOT]  every C++ (and C) file of common/, labs/, solutions/, tests/ and tools/
                               is as `clang-format --dry-run --Werror` (with ROOT/.clang-format) has it
                               (in the student edition, not the exercise files a student edits)
  lint.py pyflakes [ROOT]      every Python file passes pyflakes (unused imports, undefined names)
  lint.py shellcheck [ROOT]    every shell script (*.sh, and scripts without an extension such as
                               ./workbook and .ci/run) passes shellcheck (with ROOT/.shellcheckrc)
  lint.py --self-test          plant a fault of each kind in a scratch student edition that is no git
                               checkout, and prove that each check fails naming the file, and passes
                               over third_party/, build folders and a student's exercise file

The files are the tracked ones (`git ls-files`) where ROOT is a git checkout, and a walk of ROOT
otherwise (the student edition, ./workbook export-student, is no git repository). third_party/
(glad, generated) and build folders are never checked. Exit 0: clean; 1: findings, each naming its
file; 77 (ctest: skipped): the linter is not installed (./workbook test installs it).
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
SKIP = 77
CPP_FOLDERS = ("common", "labs", "solutions", "tests", "tools")
CPP_SUFFIXES = {".cpp", ".hpp", ".cc", ".cxx", ".hh", ".inl", ".c", ".h"}
# Never checked: code that is not ours (glad's loader is generated), and what a build or a tool leaves.
NOT_OURS = {"third_party", ".git", "node_modules", "__pycache__", "Testing"}
FINDING = re.compile(r"^(?:In (\S+) line \d+:|([^\s:][^:\n]*):\d+:)", re.M)


def is_build_folder(name):
    return name.startswith("build") or name in ("grades", "gpu-pack")


def listed_files(root):
    """Paths relative to root, sorted: git's tracked files in a checkout, every file otherwise."""
    try:
        top = subprocess.run(["git", "-C", str(root), "rev-parse", "--show-toplevel"], capture_output=True, text=True)
        in_git = top.returncode == 0 and pathlib.Path(top.stdout.strip()).resolve() == root.resolve()
    except FileNotFoundError:  # (no git on this machine)
        in_git = False
    # (root must be the checkout's top: a student edition exported into build-ci/ of a checkout is
    # inside a git tree that ignores it, and git would list none of its files)
    if in_git:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True, check=True).stdout
        names = [n for n in out.decode().split("\0") if n and (root / n).is_file()]  # (not one deleted on disk)
    else:
        names = []
        for folder, dirs, files in os.walk(root):
            here = pathlib.Path(folder)
            dirs[:] = sorted(d for d in dirs if d not in NOT_OURS and not (here == root and is_build_folder(d)))
            names += [str((here / f).relative_to(root)) for f in files]
    def ours(name):
        parts = pathlib.PurePosixPath(name).parts
        return not NOT_OURS.intersection(parts[:-1]) and not (len(parts) > 1 and is_build_folder(parts[0]))
    return sorted(n for n in names if ours(n))


def shebang(path):
    try:
        with open(path, "rb") as f:
            first = f.readline(200)
    except OSError:
        return ""
    return first.decode(errors="replace").strip() if first.startswith(b"#!") else ""


def students_files(root):
    """In the student edition (no solutions/), the files a student edits (labs/*/exercises.json's "file"):
    their code is theirs to format, and ./workbook test must not fail on it."""
    if (root / "solutions").is_dir():
        return set()
    mine = set()
    for manifest in root.glob("labs/*/exercises.json"):
        try:
            exercises = json.loads(manifest.read_text()).get("exercises", [])
        except (OSError, ValueError):
            continue
        mine |= {str(manifest.parent.relative_to(root) / e["file"]) for e in exercises if "file" in e}
    return mine


def cpp_files(root):
    leave_out = students_files(root)
    return [n for n in listed_files(root) if pathlib.PurePosixPath(n).parts[0] in CPP_FOLDERS
            and pathlib.PurePosixPath(n).suffix in CPP_SUFFIXES and n not in leave_out]


def python_files(root):
    def is_python(n):
        p = pathlib.PurePosixPath(n)
        return p.suffix == ".py" or (not p.suffix and "python" in shebang(root / n))
    return [n for n in listed_files(root) if is_python(n)]


def shell_files(root):
    def is_shell(n):
        p = pathlib.PurePosixPath(n)
        if p.suffix == ".sh":
            return True
        words = shebang(root / n).replace("/", " ").split()
        return not p.suffix and any(w in ("sh", "bash", "dash") for w in words)
    return [n for n in listed_files(root) if is_shell(n)]


def run_linter(name, command, files, root, fix):
    """Runs command + files in root; prints the linter's findings and one summary line naming the files."""
    if not files:
        print(f"lint {name}: no files to check under {root}")
        return 1
    found = subprocess.run(command + files, cwd=root, capture_output=True, text=True)
    text = (found.stdout + found.stderr).rstrip()
    if found.returncode == 0:
        print(f"lint {name}: {len(files)} files clean")
        return 0
    print(text)
    # (the file each finding starts with: "FILE:LINE:COL: ..." or shellcheck's "In FILE line LINE:")
    starts = {m.group(1) or m.group(2) for m in FINDING.finditer(text)}
    named = [f for f in files if f in starts]
    print(f"lint {name}: {len(named) or 'some'} of {len(files)} files fail: {' '.join(named)}")
    print(f"lint {name}: {fix}")
    return 1


def linter_command(name):
    """The linter's command line, to which the files are added; None where it is not installed."""
    if name == "pyflakes":
        found = subprocess.run([sys.executable, "-c", "import pyflakes"], capture_output=True).returncode == 0
        return [sys.executable, "-m", "pyflakes"] if found else None
    tool = shutil.which(name)
    # (shellcheck -x: follow `source` lines; where to find them, and the one warning this tree turns
    # off, are in .shellcheckrc)
    return None if not tool else [tool, "--dry-run", "--Werror"] if name == "clang-format" else [tool, "-x"]


LINTERS = {  # name: (the files it checks, its Debian package, what to do about a finding)
    "clang-format": (cpp_files, "clang-format",
                     "format them with `clang-format -i FILE...` (the style is .clang-format)"),
    "pyflakes": (python_files, "python3-pyflakes",
                 "remove what is unused, import what is undefined (pyflakes reads no `# noqa`)"),
    "shellcheck": (shell_files, "shellcheck",
                   "fix them, or disable a deliberate one on its line: `# shellcheck disable=SCnnnn  # (why)`"),
}


def check(name, root):
    files, package, fix = LINTERS[name]
    command = linter_command(name)
    if not command:
        where = f" for {sys.executable}" if name == "pyflakes" else ""
        print(f"lint {name}: skipped: {name} is not installed{where} (Debian: apt-get install {package}; "
              "./workbook test installs it)")
        return SKIP
    if name == "clang-format":  # (versions format differently: CI's is Debian 12's)
        version = subprocess.run([command[0], "--version"], capture_output=True, text=True).stdout.strip()
        print(f"lint clang-format: {version}")
    return run_linter(name, command, files(root), root, fix)


PLANTS = {  # path: (text, the check that must name it, or None where no check may)
    "common/base/good.cpp": ("int good() { return 1; }\n", None),
    "common/base/bad.cpp": ("int  bad( ) {return 1;}\n", "clang-format"),
    "labs/01_x/main.cpp": ("int  lab( ) {return 1;}\n", "clang-format"),
    # (a student edition, with no solutions/: a student's exercise file is theirs to format)
    "labs/01_x/exercises.json": ('{"exercises": [{"id": "01.1", "file": "exercise.cpp"}]}\n', None),
    "labs/01_x/exercise.cpp": ("int  mine( ) {return 1;}\n", None),
    "third_party/glad/src/gl.c": ("int  generated( ) {return 1;}\n", None),
    "build-ci/generated.cpp": ("int  built( ) {return 1;}\n", None),
    "tools/good.py": ("import sys\n\nprint(sys.argv)\n", None),
    "tools/bad.py": ("import os\n", "pyflakes"),
    "tools/noext_python": ("#!/usr/bin/python3\nimport os\n", "pyflakes"),
    "tools/good.sh": ('#!/usr/bin/env bash\necho "$1"\n', None),
    "tools/bad.sh": ("#!/usr/bin/env bash\necho $1\n", "shellcheck"),
    ".ci/run": ("#!/usr/bin/env bash\ncd $(dirname $0)\n", "shellcheck"),
    "workbook": ("#!/usr/bin/env bash\nls *.txt | head -1\n", "shellcheck"),
    "build/scratch.sh": ("#!/usr/bin/env bash\necho $1\n", None),
}


def self_test():
    failures, ran = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for name in (".clang-format", ".shellcheckrc"):
            shutil.copy(ROOT / name, root / name)
        for path, (text, _) in PLANTS.items():
            (root / path).parent.mkdir(parents=True, exist_ok=True)
            (root / path).write_text(text)
        for name in LINTERS:
            out = subprocess.run([sys.executable, __file__, name, str(root)], capture_output=True, text=True)
            if out.returncode == SKIP:
                print(out.stdout.strip())
                continue
            ran += 1
            summary = [line for line in out.stdout.splitlines()
                       if line.startswith(f"lint {name}: ") and " files fail: " in line]
            want = sorted(p for p, (_, who) in PLANTS.items() if who == name)
            named = summary[-1].split(" files fail: ", 1)[1].split() if summary else []
            if out.returncode != 1 or sorted(named) != want:
                failures.append(f"{name}: exit {out.returncode}, named {named}, expected exit 1 naming {want}:\n"
                                f"{out.stdout}{out.stderr}")
            else:
                print(f"lint --self-test: {name} fails naming {' '.join(want)}, and passes over the rest")
    for f in failures:
        print(f"lint --self-test: FAIL: {f}")
    if not ran:
        return SKIP
    return 1 if failures else 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    if len(argv) not in (1, 2) or argv[0] not in LINTERS:
        sys.exit(__doc__)
    root = pathlib.Path(argv[1]).resolve() if len(argv) == 2 else ROOT
    return check(argv[0], root)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
