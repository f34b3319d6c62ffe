#!/usr/bin/env python3
"""gpu_check pack: one folder (about 30 MB) with which a machine that has a GPU and python3, and none
of the workbook's tools (no apt, CMake, ctest or compiler), runs the verdict suite of this build
(docs/gpu-check.md).

  gpu_pack.py [BUILD_DIR] [OUT_DIR] [--framework] [--keep-debug REGEX] [--no-showcase]

BUILD_DIR defaults to build/, OUT_DIR to gpu-pack/ (both at the repository root). It reads the build
and writes only OUT_DIR:
  tests.json     `ctest --show-only=json-v1` of the build (which lists, and builds nothing), only
                 the verdict tests (ctest_rules.VERDICT_LABELS; --framework: the framework's too)
  tree.tar.xz    root/: the source files the tests read at run time (SOURCES); build/: every
                 executable the tests run, stripped, and the mutants' generated sources; lib/: the
                 shared libraries they link that a bare machine may lack; compat/: libstdc++ and
                 libgcc_s, which the runner uses only where the machine's own are too old
  manifest.json  the paths the binaries were built at, the commit, the archive's checksum, the list
                 of executables (the runner rewrites their paths), the glibc they need
  gpu_check.sh, gpu_check.py, ctest_rules.py, gpu_unpack.py: the runner (gpu_check.sh run, on the target), and
                 with the showcase, tools/showcase/table.py (its tables at 1920x1080: run --timings)
Needs ctest, strip, ldd and xz (XZ_OPT is honoured: XZ_OPT=-T0 packs on every core).
Python 3.7 or newer, standard library only.
"""
import argparse
import datetime
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile

import ctest_rules
from gpu_unpack import sha256  # (one checksum: the pack writes it, the target checks it)

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
# What the tests read from the source tree at run time (through the variant's kSourceDir, kLabDir,
# kSolutionDir and kShaderPath: common/base/variant.hpp), and why.
SOURCES = [
    ("labs", "exercises.json, the labs' shaders, and the exercise files whose markers the manifest tests read"),
    ("solutions", "the reference's shaders (isolated GLSL exercises) and exercise files"),
    ("shaders", "the shared GLSL includes"),
    ("scenes", "the scenes the tests and the labs render"),
    ("tests", "golden/, hidden/ and their calls, hints/, mutants/, and "
              "framework/'s scripts of the mutants.* tests"),
    ("tools", "truth/ (truth.py, its scenes and techniques), authoring/mutant_matrix.py (mutants.upstream_mistakes_blame_one_exercise, labelled mutants), and "
              "showcase/, the showcase's own folder (its kLabDir)"),
]
# Not read by any test: the handouts' pictures, and Python's caches.
SKIP_SOURCE = re.compile(r"^labs/[^/]+/images/|(^|/)__pycache__/|\.pyc$")
# Never packed with --framework either: builds, the pack itself, git's store.
SKIP_TOP = re.compile(r"^(\.git|build.*|gpu-pack.*|Testing|node_modules)$")
# Libraries the target's own system and GPU driver must provide: the C library's, and OpenGL/EGL
# through glvnd (a packed copy would not find the driver).
SYSTEM_LIB = re.compile(r"^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libresolv|"
                        r"libutil\.so|libGL|libEGL|libOpenGL|libGLX|libGLdispatch|libGLES|libgbm|libdrm|libnvidia|"
                        r"libcuda|libvulkan)")
COMPAT_LIB = re.compile(r"^(libstdc\+\+|libgcc_s)\.so")


def read_cache(build):
    """The build's CMakeCache.txt entries, NAME -> value."""
    entries = {}
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            for line in f:
                m = re.match(r"^([A-Za-z_][\w.-]*):\w+=(.*)$", line.rstrip("\n"))
                if m:
                    entries[m.group(1)] = m.group(2)
    except OSError:
        sys.exit("gpu_check pack: %s is not a CMake build folder (no CMakeCache.txt)" % build)
    return entries


def listing(build, framework):
    """ctest's own list of the build's tests (json-v1), narrowed to the verdict tests."""
    done = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True)
    if done.returncode != 0:
        sys.exit("gpu_check pack: ctest --show-only=json-v1 failed in %s:\n%s" % (build, done.stderr))
    data = json.loads(done.stdout)
    keep = set(ctest_rules.VERDICT_LABELS) | ({"framework"} if framework else set())
    tests = [e for e in data["tests"] if keep & set(ctest_rules.Test(e).labels)]
    for e in tests:
        e.pop("backtrace", None)  # (points into the backtrace graph, which is left out)
    return {"kind": data.get("kind"), "version": data.get("version"), "tests": tests}


def snapshot(build, names):
    """Size and time of each file: a build that is being rebuilt must not be packed half-linked."""
    return {n: (os.stat(os.path.join(build, n)).st_size, os.stat(os.path.join(build, n)).st_mtime_ns) for n in names}


def is_elf(path):
    try:
        with open(path, "rb") as f:
            return f.read(4) == b"\x7fELF"
    except OSError:
        return False


def _under(path, folder):
    return os.path.abspath(path).startswith(folder.rstrip("/") + "/")


def executables(tests, build, showcase):
    """Every file of the build the tests run or name (relative to it): each command and each
    argument that is a file of the build; for a test binary (a command, or check's --tests), its
    lab (kLabExe: scene tests and check's runner run it);
    every lab's solution (kSolutionExe: every lab's tests draw with it); for truth.py --mutant, the
    mutant's own build where it has one."""
    need = set()

    def add(path):
        if _under(path, build) and os.path.isfile(path):
            need.add(os.path.relpath(path, build))

    for e in tests:
        cmd = e.get("command") or []
        for arg in cmd:
            path = arg.split("=", 1)[-1] if arg.startswith("--") else arg
            add(path)
            if path.endswith("_tests"):  # (a test binary as the command, or as wb_check's --tests)
                add(path[: -len("_tests")])
        if "--mutant" in cmd[:-1]:
            lab, _, name = cmd[cmd.index("--mutant") + 1].partition("/")
            add(os.path.join(build, "lab%s_mutant_%s" % (lab[:2], name)))
    for name in os.listdir(build):
        if re.match(r"^lab\d\d_solution$", name) or (showcase and name == "showcase"):
            add(os.path.join(build, name))
    return sorted(need)


class Archive:
    """tree.tar.xz, written as a stream into xz: members in a fixed order with fixed owners and
    times, so the same build packs to the same bytes (and similar binaries sit side by side in
    xz's window, which is what makes 200 of them about 20 MB)."""

    def __init__(self, path):
        self.out = open(path, "wb")
        self.xz = subprocess.Popen(["xz", "-9", "-c"], stdin=subprocess.PIPE, stdout=self.out)
        self.tar = tarfile.open(fileobj=self.xz.stdin, mode="w|", format=tarfile.PAX_FORMAT)
        self.bytes = 0

    def add(self, name, path):
        info = tarfile.TarInfo(name)
        info.size = os.path.getsize(path)
        info.mode = 0o755 if os.access(path, os.X_OK) else 0o644
        with open(path, "rb") as f:
            self.tar.addfile(info, f)
        self.bytes += info.size

    def add_bytes(self, name, data):
        info = tarfile.TarInfo(name)
        info.size, info.mode = len(data), 0o644
        self.tar.addfile(info, io.BytesIO(data))

    def close(self):
        self.tar.close()
        self.xz.stdin.close()
        if self.xz.wait() != 0:
            sys.exit("gpu_check pack: xz failed")
        self.out.close()


def stage_executables(build, names, staging, keep_debug):
    """Each executable stripped (strip --strip-all: no symbols, no debug information) into
    `staging`, except those --keep-debug names (a crash report's file:line needs their DWARF).
    Quick, so that a build being relinked meanwhile is noticed (snapshot) before the slow part."""
    for name in names:
        src, dst = os.path.join(build, name), os.path.join(staging, name)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        if is_elf(src) and not (keep_debug and re.search(keep_debug, name)):
            subprocess.run(["strip", "--strip-all", "-o", dst, src], check=True)
            shutil.copymode(src, dst)
        else:
            shutil.copy2(src, dst)


def add_tree(archive, top, prefix, folder, skip):
    """Every file under top/folder, as prefix/folder/..., in sorted order; returns the count."""
    count = 0
    for dirpath, dirnames, filenames in os.walk(os.path.join(top, folder)):
        dirnames.sort()
        for f in sorted(filenames):
            path = os.path.join(dirpath, f)
            rel = os.path.relpath(path, top)
            if not skip.search(rel) and os.path.isfile(path) and not os.path.islink(path):
                archive.add(prefix + "/" + rel, path)
                count += 1
    return count


def shared_libraries(build, names):
    """{soname: path} of what the executables link, from ldd, less the system's and the driver's."""
    libs = {}
    for name in names:
        path = os.path.join(build, name)
        if not is_elf(path):
            continue
        done = subprocess.run(["ldd", path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        for line in done.stdout.splitlines():
            m = re.match(r"^\s*(\S+)\s+=>\s+(\S+)\s+\(", line)
            if m and not SYSTEM_LIB.match(m.group(1)):
                libs[m.group(1)] = os.path.realpath(m.group(2))
            elif "not found" in line:
                sys.exit("gpu_check pack: %s links a library this machine lacks: %s" % (name, line.strip()))
    return libs


def glibc_needed(paths):
    """The newest GLIBC_2.N symbol version any of the files asks for."""
    newest = 0
    for path in paths:
        with open(path, "rb") as f:
            for m in re.finditer(rb"GLIBC_2\.(\d+)", f.read()):
                newest = max(newest, int(m.group(1)))
    return "2.%d" % newest


def commit_of(root):
    done = subprocess.run(["git", "--no-optional-locks", "-C", root, "describe", "--always", "--dirty", "--abbrev=12"],
                          stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, universal_newlines=True)
    return done.stdout.strip() or "unknown"


def os_name():
    """This machine's system, as /etc/os-release names it ("Debian GNU/Linux 12 (bookworm)")."""
    try:
        with open("/etc/os-release") as f:
            return next((line.split("=", 1)[1].strip().strip('"') for line in f if line.startswith("PRETTY_NAME=")),
                        "unknown")
    except OSError:
        return "unknown"


def costs_of(build):
    """ctest's costs of the last run (Testing/Temporary/CTestCostData.txt): seconds per test."""
    costs = {}
    try:
        with open(os.path.join(build, "Testing/Temporary/CTestCostData.txt")) as f:
            for line in f:
                parts = line.split()
                if line.startswith("---"):
                    break
                if len(parts) == 3:
                    costs[parts[0]] = float(parts[2])
    except (OSError, ValueError):
        pass
    return costs


def prepare_out(out):
    """OUT_DIR, emptied if it is an earlier pack, refused if it holds anything else."""
    if os.path.isdir(out) and os.listdir(out):
        if not os.path.isfile(os.path.join(out, "manifest.json")):
            sys.exit("gpu_check pack: %s is not empty and not a pack; name another folder" % out)
        shutil.rmtree(out)
    os.makedirs(out, exist_ok=True)


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="gpu_check.sh pack", description=__doc__.split("\n")[0])
    ap.add_argument("build", nargs="?", default=os.path.join(REPO, "build"))
    ap.add_argument("out", nargs="?", default=os.path.join(REPO, "gpu-pack"))
    ap.add_argument("--framework", action="store_true",
                    help="also the framework's tests, and so the whole source tree (many need tools a bare machine "
                         "lacks: git, apt, CMake, Xvfb)")
    ap.add_argument("--keep-debug", metavar="REGEX", help="do not strip the executables whose name matches")
    ap.add_argument("--no-showcase", action="store_true", help="leave the showcase out (no --timings of its tables)")
    return ap.parse_args(argv)


def main(argv):
    args = parse_args(argv)
    build, out = os.path.abspath(args.build), os.path.abspath(args.out)
    cache = read_cache(build)
    root = cache.get("CMAKE_HOME_DIRECTORY", REPO)
    tests = listing(build, args.framework)
    names = executables(tests["tests"], build, not args.no_showcase)
    missing = sorted({e["command"][0] for e in tests["tests"]
                      if e.get("command") and not os.path.exists(e["command"][0])})
    if missing:
        sys.exit("gpu_check pack: the build lacks what some tests run (build it first): %s" % ", ".join(missing[:5]))
    libs = shared_libraries(build, names)
    prepare_out(out)
    archive_path = os.path.join(out, "tree.tar.xz")
    print("gpu_check pack: %d tests, %d executables, %d libraries; packing %s" % (
        len(tests["tests"]), len(names), len(libs), archive_path), flush=True)
    with tempfile.TemporaryDirectory() as staging:
        before = snapshot(build, names)
        stage_executables(build, names, staging, args.keep_debug)
        changed = [n for n, st in snapshot(build, names).items() if st != before[n]]
        if changed:
            sys.exit("gpu_check pack: the build changed while it was read (%s%s): pack again once it is finished"
                     % (", ".join(changed[:3]), "..." if len(changed) > 3 else ""))
        staged = [os.path.join(staging, n) for n in names]
        glibc = glibc_needed([p for p in staged if is_elf(p)] + list(libs.values()))
        write_archive(archive_path, staging, names, build, root, args.framework, libs)
    write_pack_files(out, build, root, cache, tests, names, libs, glibc, args)


def write_archive(path, staging, names, build, root, framework, libs):
    """tree.tar.xz: the staged executables, the mutants' sources, the source files, the libraries."""
    archive = Archive(path)
    for name in names:
        archive.add("build/" + name, os.path.join(staging, name))
    # The mutants' generated sources: their tests' WB_SUBMISSION_DIR, check cases' --submission,
    # truth.py's shader overlays.
    add_tree(archive, build, "build", "mutants", SKIP_SOURCE)
    folders = [f for f, _ in SOURCES] if not framework else sorted(
        f for f in os.listdir(root) if not SKIP_TOP.match(f))
    for folder in folders:
        if os.path.isdir(os.path.join(root, folder)):
            add_tree(archive, root, "root", folder, SKIP_SOURCE)
        elif os.path.isfile(os.path.join(root, folder)):
            archive.add("root/" + folder, os.path.join(root, folder))
    for soname, lib in sorted(libs.items()):
        archive.add(("compat/" if COMPAT_LIB.match(soname) else "lib/") + soname, lib)
    archive.close()


def write_pack_files(out, build, root, cache, tests, names, libs, glibc, args):
    """tests.json, manifest.json and the runner beside the archive; then the sizes."""
    archive = os.path.join(out, "tree.tar.xz")
    with open(os.path.join(out, "tests.json"), "w") as f:
        json.dump(tests, f, indent=1)
    manifest = {
        "format": 1, "root": root, "build": build, "commit": commit_of(root),
        "made": datetime.datetime.now().isoformat(timespec="seconds"), "made_on": os_name(),
        "build_type": cache.get("CMAKE_BUILD_TYPE"),
        "expect_stubs": cache.get("WB_EXPECT_STUBS", "OFF").upper() in ("ON", "1", "TRUE", "YES"),
        "framework": args.framework, "archive": "tree.tar.xz", "sha256": sha256(archive),
        "executables": names, "libraries": sorted(libs), "tests": len(tests["tests"]),
        "glibc": glibc,
        "probe": next((n for n in names if re.match(r"^lab\d\d_solution$", n)), names[0]),
        "costs": costs_of(build),
    }
    with open(os.path.join(out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    for script in ("gpu_check.sh", "gpu_check.py", "ctest_rules.py", "gpu_unpack.py"):
        shutil.copy2(os.path.join(HERE, script), os.path.join(out, script))
    # The showcase's table maker as this runner knows it (--size), for --timings.
    table = os.path.join(REPO, "tools/showcase/table.py")
    if "showcase" in names and os.path.isfile(table):
        shutil.copy2(table, os.path.join(out, "table.py"))
    total = sum(os.path.getsize(os.path.join(out, f)) for f in os.listdir(out))
    print("gpu_check pack: %s: %.1f MB (the archive %.1f MB); built at %s, commit %s, glibc %s or newer" % (
        out, total / 1e6, os.path.getsize(archive) / 1e6, root, manifest["commit"], manifest["glibc"]))
    if not manifest["expect_stubs"]:
        print("gpu_check pack: note: this build is not configured with WB_EXPECT_STUBS=ON (the 'ci' preset): its "
              "student tests fail on the stubs by design, and it has no hunt tests")
    print("gpu_check pack: on the GPU machine: %s/gpu_check.sh run" % os.path.basename(out))


if __name__ == "__main__":
    if sys.version_info < (3, 7):
        sys.exit("gpu_check pack: python 3.7 or newer is needed")
    main(sys.argv[1:])
