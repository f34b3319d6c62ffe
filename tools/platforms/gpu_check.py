#!/usr/bin/env python3
"""gpu_check run: the workbook's verdict suite from a pack, on a machine with a GPU and python3 but no
CMake, ctest, compiler or package manager (docs/gpu-check.md; the pack is made by gpu_pack.py).

  gpu_check.py run [PACK_DIR] [-j N] [--only REGEX] [--exclude REGEX] [--label REGEX]...
                   [--nvidia | --no-nvidia] [--uncapped] [--at DIR] [--fresh] [--out DIR]
                   [--timings [--timings-size WxH] [--timings-frames N]]
  gpu_check.py --self-test      ctest's rules on tiny fake commands (sh -c 'echo ok'), in seconds

It unpacks the tree where the binaries look for their files (gpu_unpack.py), runs every listed test
as ctest would (ctest_rules.py: command, working directory, ENVIRONMENT, TIMEOUT,
PASS/FAIL/SKIP_REGULAR_EXPRESSION, SKIP_RETURN_CODE, WILL_FAIL, RUN_SERIAL, RESOURCE_LOCK,
PROCESSORS), N at a time, and writes results.tsv (name, labels, verdict, seconds) and failures.txt
(each failing test's output).
Python 3.7 or newer, standard library only.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import gpu_unpack
from ctest_rules import Test, closing_line, is_verdict_test, label_table, run_all, select, write_reports

HERE = os.path.dirname(os.path.abspath(__file__))
NVIDIA_VENDOR_FILES = ("/usr/share/glvnd/egl_vendor.d/10_nvidia.json", "/etc/glvnd/egl_vendor.d/10_nvidia.json")


# ----------------------------------------------------------------------------------------------------
# The run on the target.

def nvidia_vendor_file(mode):
    """NVIDIA's glvnd EGL vendor file when asked (--nvidia) or, by default, when it is installed:
    glvnd would otherwise also try Mesa's, which may answer first with llvmpipe."""
    if mode == "off":
        return None
    found = next((f for f in NVIDIA_VENDOR_FILES if os.path.isfile(f)), None)
    if mode == "on" and not found:
        sys.exit("gpu_check: --nvidia, but there is no %s (is NVIDIA's driver installed?)" % NVIDIA_VENDOR_FILES[0])
    return found


def environment(args, lib_dirs):
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = ":".join(lib_dirs + [p for p in env.get("LD_LIBRARY_PATH", "").split(":") if p])
    # As ./workbook test runs the suite: Mesa capped at OpenGL 4.1 core, forward-compatible, GLSL 4.10
    # (NVIDIA's driver ignores both; --uncapped or WB_GL_UNCAPPED=1: Mesa's own).
    if not args.uncapped and env.get("WB_GL_UNCAPPED", "0") != "1":
        env["MESA_GL_VERSION_OVERRIDE"], env["MESA_GLSL_VERSION_OVERRIDE"] = "4.1FC", "410"
    vendor = nvidia_vendor_file(args.nvidia)
    if vendor and (args.nvidia == "on" or "__EGL_VENDOR_LIBRARY_FILENAMES" not in env):
        env["__EGL_VENDOR_LIBRARY_FILENAMES"] = vendor
    return env


def probe(tree, manifest, env):
    """The GL renderer, from one headless frame of a lab's solution (also proves the binaries load).
    Returns (renderer or None, output)."""
    exe = os.path.join(tree.build, manifest["probe"])
    with tempfile.TemporaryDirectory() as tmp:
        record = os.path.join(tmp, "probe.json")
        cmd = [exe, "--headless", "--quiet", "--size", "64x64", "--frames", "1", "--record", record]
        try:
            done = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
        except (OSError, subprocess.TimeoutExpired) as e:
            return None, str(e)
        try:
            with open(record) as f:
                return json.load(f).get("renderer"), done.stdout.decode("utf-8", "replace")
        except (OSError, ValueError):
            return None, done.stdout.decode("utf-8", "replace")


def _version(text):
    return tuple(int(x) for x in re.findall(r"\d+", text)[:2])


def glibc_warning(manifest):
    """A line when this machine's C library is older than the binaries need (they would not load)."""
    try:
        here = os.confstr("CS_GNU_LIBC_VERSION").split()[-1]  # "glibc 2.36"
    except (ValueError, OSError, AttributeError, IndexError):
        return "gpu_check: warning: this is not a glibc system; the binaries need glibc %s" % manifest.get("glibc")
    if _version(here) < _version(manifest.get("glibc", "0.0")):
        return ("gpu_check: warning: this machine has glibc %s and the binaries need %s or newer (built on %s)"
                % (here, manifest["glibc"], manifest.get("made_on", "Debian 12")))
    return None


def libraries(tree, manifest, args):
    """The library folders for LD_LIBRARY_PATH: the pack's libraries, and its libstdc++/libgcc_s
    only where this machine's cannot load the binaries (an older GCC's), since a newer one may be
    what the GL driver itself needs."""
    lib_dirs = [tree.lib]
    env = environment(args, lib_dirs)
    renderer, output = probe(tree, manifest, env)
    if renderer is None and re.search(r"error while loading shared libraries|version `\S+' not found", output):
        lib_dirs.append(tree.compat)
        renderer, output = probe(tree, manifest, environment(args, lib_dirs))
        print("gpu_check: this machine's libstdc++/libgcc_s could not load the binaries: the pack's are used")
    return lib_dirs, renderer, output


def progress(test, verdict, reason, outcome, n, total):
    mark = {"passed": "ok  ", "failed": "FAIL", "skipped": "skip"}[verdict]
    extra = "" if verdict == "passed" else "  (%s)" % reason.splitlines()[0][:120]
    print("[%*d/%d] %s %6.2fs %s%s" % (len(str(total)), n, total, mark, outcome.seconds, test.name, extra), flush=True)


def timings(pack, tree, manifest, env, out_dir, size, frames):
    """The showcase's tables (tools/showcase/table.py) and each lab's --bench at `size`, one at a
    time after the tests: nothing else shares the GPU while they are timed."""
    # (the pack's own copy, made beside the runner that calls it with --size; else the tree's)
    table = next((t for t in (os.path.join(pack, "table.py"), os.path.join(tree.root, "tools/showcase/table.py"))
                  if os.path.isfile(t)), "")
    showcase = os.path.join(tree.build, "showcase")
    if os.path.isfile(showcase) and os.path.isfile(table):
        print("gpu_check: timing the showcase's tables at %s" % size, flush=True)
        subprocess.run([sys.executable, "-B", table, "--exe", showcase, "--csv-dir",
                        os.path.join(out_dir, "showcase-table"), "--size", size, "--frames", str(frames)],
                       env=env, check=False)
    else:
        print("gpu_check: --timings: the pack has no showcase (pack it from an instructor build)")
    for exe in sorted(e for e in manifest["executables"] if re.match(r"^lab\d\d_solution$", e)):
        out = os.path.join(out_dir, "bench%s.csv" % exe[3:5])
        print("gpu_check: %s --bench at %s" % (exe, size), flush=True)
        subprocess.run([os.path.join(tree.build, exe), "--headless", "--quiet", "--size", size, "--frames", "60",
                        "--bench", out], env=env, check=False, stdout=subprocess.DEVNULL)


# ----------------------------------------------------------------------------------------------------
# --self-test: the rules above on tiny fake commands, in about a second.

def _fake(name, script, **props):
    """A json-v1 entry that runs `sh -c script` with these properties."""
    return {"name": name, "command": ["/bin/sh", "-c", script],
            "properties": [{"name": k, "value": v} for k, v in props.items()]}


def _self_cases(tmp):
    lock, serial = os.path.join(tmp, "lock"), os.path.join(tmp, "serial")
    # (two at once would find the folder made: mkdir fails, and the test with it)
    alone = 'mkdir "%s" && sleep 0.3 && rmdir "%s"'
    # (the serial test's folder must never be seen by a test beside it)
    watch = 'for i in 1 2 3 4 5 6; do test -d "%s" && exit 1; sleep 0.1; done; exit 0' % serial
    return [  # (the serial and locked ones first: they need free slots to show the order they start in)
        (_fake("serial_first", alone % (serial, serial), RUN_SERIAL=True), "passed"),
        (_fake("beside_serial_a", watch), "passed"),
        (_fake("beside_serial_b", watch), "passed"),
        (_fake("lock_a", alone % (lock, lock), RESOURCE_LOCK=["l"]), "passed"),
        (_fake("lock_b", alone % (lock, lock), RESOURCE_LOCK=["l"]), "passed"),
        (_fake("plain", "echo ok"), "passed"),
        (_fake("plain", "exit 1"), "failed"),  # (names repeat in the workbook's list: each is its own test)
        (_fake("exit_code", "echo ok; exit 1"), "failed"),
        (_fake("pass_re_ignores_exit_code", "echo 'NOT IMPLEMENTED'; exit 1",
               PASS_REGULAR_EXPRESSION=["NOT IMPLEMENTED"]), "passed"),
        (_fake("pass_re_reads_stderr", "echo 'NOT IMPLEMENTED' >&2; exit 1",
               PASS_REGULAR_EXPRESSION="NOT IMPLEMENTED"), "passed"),
        (_fake("pass_re_missing", "echo ok", PASS_REGULAR_EXPRESSION=["WRONG", "  PASSED  . 1 test"]), "failed"),
        (_fake("pass_re_any_of", "echo '[  PASSED  ] 1 test.'",
               PASS_REGULAR_EXPRESSION=["WRONG", "  PASSED  . 1 test"]), "passed"),
        (_fake("fail_re", "echo 'ERROR: it broke'", FAIL_REGULAR_EXPRESSION=["ERROR|NOT IMPLEMENTED"]), "failed"),
        (_fake("fail_re_beats_pass_re", "echo WRONG; echo ERROR", PASS_REGULAR_EXPRESSION=["WRONG"],
               FAIL_REGULAR_EXPRESSION=["ERROR"]), "failed"),
        (_fake("will_fail_inverts_failure", "exit 3", WILL_FAIL=True), "passed"),
        (_fake("will_fail_inverts_success", "echo ok", WILL_FAIL=True), "failed"),
        (_fake("will_fail_inverts_fail_re", "echo ERROR", FAIL_REGULAR_EXPRESSION=["ERROR"], WILL_FAIL=True),
         "passed"),
        (_fake("skip_return_code", "exit 77", SKIP_RETURN_CODE=77), "skipped"),
        (_fake("skip_return_code_other_code", "exit 0", SKIP_RETURN_CODE=77), "passed"),
        (_fake("skip_return_code_over_fail", "echo ERROR; exit 77", SKIP_RETURN_CODE=77,
               FAIL_REGULAR_EXPRESSION=["ERROR"]), "skipped"),
        (_fake("skip_re", "echo 'SKIPPED: no display'; exit 1", SKIP_REGULAR_EXPRESSION=["SKIPPED"]), "skipped"),
        (_fake("timeout", "sleep 30", TIMEOUT=0.5), "failed"),
        (_fake("timeout_kills_the_group", "sleep 30 & sleep 30", TIMEOUT=0.5), "failed"),
        (_fake("timeout_beats_will_fail", "sleep 30", TIMEOUT=0.5, WILL_FAIL=True), "failed"),
        (_fake("timeout_beats_skip", "echo SKIPPED; sleep 30", TIMEOUT=0.5, SKIP_REGULAR_EXPRESSION=["SKIPPED"]),
         "failed"),
        (_fake("signal_beats_will_fail", "kill -SEGV $$", WILL_FAIL=True), "failed"),
        (_fake("environment", 'test "$GPU_CHECK_X" = "a=b"', ENVIRONMENT=["GPU_CHECK_X=a=b"]), "passed"),
        (_fake("working_directory", 'test "$(pwd -P)" = "%s"' % os.path.realpath(tmp), WORKING_DIRECTORY=tmp),
         "passed"),
        ({"name": "no_command", "properties": []}, "failed"),
        ({"name": "missing_executable", "command": [os.path.join(tmp, "nothing")]}, "failed"),
        (_fake("disabled", "exit 1", DISABLED=True), "skipped"),
        (_fake("serial_last", alone % (serial, serial), RUN_SERIAL=True), "passed"),
    ]


def _self_check_reports(tests, results, tmp, failed):
    write_reports(tests, results, tmp)
    with open(os.path.join(tmp, "results.tsv")) as f:
        rows = [line.rstrip("\n").split("\t") for line in f]
    if len(rows) != len(tests) or any(len(r) != 4 for r in rows):
        failed.append("results.tsv: %d rows of 4 columns wanted, got %s" % (len(tests), rows[:2]))
    with open(os.path.join(tmp, "failures.txt")) as f:
        heads = [line for line in f if line.startswith("==== ")]
    if len(heads) != sum(1 for v, _, _ in results.values() if v == "failed"):
        failed.append("failures.txt: one section per failed test wanted, got %d" % len(heads))
    if not re.match(r"^\d+ passed, \d+ failed(, \d+ skipped)?$", closing_line(results)):
        failed.append("the closing line: %r" % closing_line(results))


def _self_check_helpers(tmp, failed):
    tests = [Test({"name": "a.x", "properties": [{"name": "LABELS", "value": ["lab03", "mutant"]}]}),
             Test({"name": "a.y", "properties": [{"name": "LABELS", "value": ["lab04", "mutant"]}]})]
    if [t.name for t in select(tests, None, None, ["mutant", "^lab03$"])] != ["a.x"]:
        failed.append("--label twice must ask for both labels")
    if [t.name for t in select(tests, "y$", None, [])] != ["a.y"] or select(tests, None, "^a", []):
        failed.append("--only / --exclude")
    old, new = "/work/main-tree", gpu_unpack._pad("/tmp/wbx", len("/work/main-tree"))
    if len(new) != len(old) or os.path.normpath(new) != "/tmp/wbx":
        failed.append("padding a shorter path: %r" % new)
    binary = os.path.join(tmp, "fake.bin")
    with open(binary, "wb") as f:
        f.write(b"\x7fELF\0" + old.encode() + b"/labs\0" + old.encode() + b"/build/lab01\0")
    gpu_unpack._patch([binary], [(old, new)])
    with open(binary, "rb") as f:
        data = f.read()
    if data != b"\x7fELF\0" + new.encode() + b"/labs\0" + new.encode() + b"/build/lab01\0":
        failed.append("patching a binary's paths: %r" % data)
    if gpu_unpack.relocate({"c": [old + "/x", 3]}, [(old, new)]) != {"c": [new + "/x", 3]}:
        failed.append("relocating the test list")


def self_test():
    """Each fake test's verdict is ctest's; everything runs at once, so this takes about a second."""
    failed = []
    with tempfile.TemporaryDirectory() as tmp:
        cases = _self_cases(tmp)
        tests = [Test(entry) for entry, _ in cases]
        start = time.monotonic()
        results = run_all(tests, 8, dict(os.environ))
        took = time.monotonic() - start
        for (entry, want), t in zip(cases, tests):
            verdict, reason, outcome = results[t]
            if verdict != want:
                failed.append("%s: %s (%s), ctest says %s; output: %s" % (t.name, verdict, reason, want,
                                                                        outcome.output[-200:]))
        for t in tests:
            if t.name in ("timeout", "timeout_kills_the_group") and results[t][2].seconds > 3:
                failed.append("%s took %.1f s: the timeout did not end it" % (t.name, results[t][2].seconds))
        if took > 4:
            failed.append("the fake tests took %.1f s: they did not run side by side" % took)
        _self_check_reports(tests, results, tmp, failed)
        _self_check_helpers(tmp, failed)
    for f in failed:
        print("FAIL: " + f)
    print("gpu_check --self-test: %s" % ("%d fake tests judged as ctest does" % len(cases) if not failed
                                         else "%d checks failed" % len(failed)))
    return 1 if failed else 0


def default_pack():
    """Beside this script when it was copied into a pack, else gpu-pack/ at the repository root."""
    if os.path.isfile(os.path.join(HERE, "manifest.json")):
        return HERE
    return os.path.join(os.path.dirname(os.path.dirname(HERE)), "gpu-pack")


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="gpu_check.sh run",
                                 description="Run a pack's verdict suite with ctest's rules (docs/gpu-check.md).")
    ap.add_argument("pack", nargs="?", default=default_pack(), help="the pack folder (default: %(default)s)")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1, help="tests at a time (default: nproc)")
    ap.add_argument("--only", help="only the tests whose name matches this regex (ctest -R)")
    ap.add_argument("--exclude", help="not the tests whose name matches this regex (ctest -E)")
    ap.add_argument("--label", action="append", default=[],
                    help="only tests with a label matching this regex; repeated, a label for each (ctest -L)")
    ap.add_argument("--framework", action="store_true", help="also the framework's tests, if the pack has them")
    nv = ap.add_mutually_exclusive_group()
    nv.add_argument("--nvidia", dest="nvidia", action="store_const", const="on", default="auto",
                    help="use NVIDIA's EGL (default: when /usr/share/glvnd/egl_vendor.d/10_nvidia.json exists)")
    nv.add_argument("--no-nvidia", dest="nvidia", action="store_const", const="off", help="let glvnd choose")
    ap.add_argument("--uncapped", action="store_true", help="do not cap Mesa at OpenGL 4.1 (MESA_GL_VERSION_OVERRIDE)")
    ap.add_argument("--at", help="unpack the tree here (no longer than the path it was built at; default: that path "
                                 "if it can be made, else a /tmp path of the same length)")
    ap.add_argument("--fresh", action="store_true", help="unpack again even if this pack was unpacked there before")
    ap.add_argument("--out", help="where results.tsv and failures.txt go (default: PACK/results)")
    ap.add_argument("--all-labels", action="store_true", help="the table also has each exercise's label (lab03.2)")
    ap.add_argument("--timings", action="store_true", help="then time the showcase's tables and each lab's --bench")
    ap.add_argument("--timings-size", default="1920x1080")
    ap.add_argument("--timings-frames", type=int, default=30, help="timed frames per row and round (default 30)")
    return ap.parse_args(argv)


def main_run(argv):
    args = parse_args(argv)
    pack = os.path.abspath(args.pack)
    manifest = gpu_unpack.read_manifest(pack)
    out_dir = os.path.abspath(args.out or os.path.join(pack, "results"))
    nvidia_vendor_file(args.nvidia)  # (--nvidia without NVIDIA's driver: said before unpacking)
    with open(os.path.join(pack, "tests.json")) as f:
        entries = json.load(f)["tests"]
    listed = [Test(e) for e in entries]  # (chosen by name and label first: the paths change with the place)
    picked = select(listed if args.framework else [t for t in listed if is_verdict_test(t)], args.only, args.exclude,
                    args.label)
    if not picked:
        sys.exit("gpu_check: no test matches (%d in the pack)" % len(entries))
    tree = gpu_unpack.unpack(pack, manifest, args.at, args.fresh)
    index = {id(t): i for i, t in enumerate(listed)}
    tests = [Test(gpu_unpack.relocate(entries[index[id(t)]], tree.mapping)) for t in picked]
    lib_dirs, renderer, output = libraries(tree, manifest, args)
    env = environment(args, lib_dirs)
    print("gpu_check: renderer: %s" % (renderer or "none: the probe failed:\n" + output[-3000:]))
    print("gpu_check: EGL vendor file: %s" % env.get("__EGL_VENDOR_LIBRARY_FILENAMES", "(glvnd's choice)"))
    if not manifest.get("expect_stubs"):
        print("gpu_check: note: packed from a build without WB_EXPECT_STUBS (not the 'ci' preset): the student "
              "tests fail on the stubs there, by design, and the hunts' tests are absent")
    jobs = max(1, args.jobs)
    print("gpu_check: %d test%s, %d at a time, from %s (commit %s)" % (
        len(tests), "" if len(tests) == 1 else "s", jobs, tree.root, manifest.get("commit", "?")), flush=True)
    start = time.monotonic()
    results = run_all(tests, jobs, env, manifest.get("costs"),
                      lambda t, v, r, o, n: progress(t, v, r, o, n, len(tests)))
    write_reports(tests, results, out_dir)
    print("\n".join(label_table(tests, results, args.all_labels)))
    print("gpu_check: %.0f s; results.tsv and failures.txt in %s" % (time.monotonic() - start, out_dir))
    if args.timings:
        timings(pack, tree, manifest, env, out_dir, args.timings_size, args.timings_frames)
    print(closing_line(results))
    return 1 if any(verdict == "failed" for verdict, _, _ in results.values()) else 0


if __name__ == "__main__":
    if sys.version_info < (3, 7):
        sys.exit("gpu_check: python 3.7 or newer is needed")
    if sys.argv[1:2] == ["--self-test"]:
        sys.exit(self_test())
    if sys.argv[1:2] != ["run"]:
        sys.exit(__doc__)
    sys.exit(main_run(sys.argv[2:]))
