"""What ctest does with a test, for a machine without ctest (gpu_check.py run): the tests of
`ctest --show-only=json-v1`, their verdicts by ctest's rules (CMake 3.25), run N at a time, and the
reports (results.tsv, failures.txt, a table per label, the closing line).
Python 3.7 or newer, standard library only.
"""
import concurrent.futures
import os
import re
import signal
import subprocess
import time

# The labels whose tests give the workbook's verdicts (the rest, "framework", test the tooling).
VERDICT_LABELS = ("solution", "student", "mutant", "mutants", "hunts", "perturbation", "truth", "checkcase")
DEFAULT_TIMEOUT = 1500.0  # ctest's own limit (DART_TESTING_TIMEOUT) for a test that sets none


def _as_list(value):
    """A property value as a list: json-v1 writes one-element lists as plain strings in places."""
    if value is None:
        return []
    return list(value) if isinstance(value, list) else [value]


def _regexes(value):
    """ctest's regexes, compiled. CMake's dialect is a subset of Python's; its `.` also matches a
    newline, hence DOTALL."""
    return [(r, re.compile(r, re.DOTALL)) for r in _as_list(value)]


class Test:
    """One test of `ctest --show-only=json-v1`, with the properties that decide its verdict."""

    def __init__(self, entry):
        props = {p["name"]: p["value"] for p in entry.get("properties", [])}
        self.name = entry["name"]
        self.command = list(entry.get("command") or [])
        self.labels = sorted(_as_list(props.get("LABELS")))
        self.cwd = props.get("WORKING_DIRECTORY") or os.getcwd()
        self.env = _as_list(props.get("ENVIRONMENT"))
        self.timeout = float(props.get("TIMEOUT") or 0) or DEFAULT_TIMEOUT
        self.pass_re = _regexes(props.get("PASS_REGULAR_EXPRESSION"))
        self.fail_re = _regexes(props.get("FAIL_REGULAR_EXPRESSION"))
        self.skip_re = _regexes(props.get("SKIP_REGULAR_EXPRESSION"))
        code = props.get("SKIP_RETURN_CODE")
        self.skip_code = int(code) if code not in (None, "") else None
        self.will_fail = _truthy(props.get("WILL_FAIL"))
        self.disabled = _truthy(props.get("DISABLED"))
        self.serial = _truthy(props.get("RUN_SERIAL"))
        self.locks = set(_as_list(props.get("RESOURCE_LOCK")))
        self.processors = max(1, int(props.get("PROCESSORS") or 1))


def _truthy(value):
    return value is True or str(value).upper() in ("1", "ON", "YES", "TRUE", "Y")


class Outcome:
    """How a test's process ended: kind is exited, signal, timeout or notrun."""

    def __init__(self, kind, code, output, seconds):
        self.kind, self.code, self.output, self.seconds = kind, code, output, seconds


def judge(test, outcome):
    """ctest's verdict (CMake 3.25, cmCTestRunTest::EndTest): (passed|failed|skipped, reason).
    A PASS regex makes the exit code irrelevant; a FAIL regex match fails; WILL_FAIL inverts that;
    then SKIP_RETURN_CODE or a SKIP regex turns the result into a skip. A timeout or a signal fails
    whatever WILL_FAIL or the skip rules say, and a command that cannot start is not run (failed)."""
    if outcome.kind == "notrun":
        return "failed", "Not Run: " + outcome.output.strip()
    if outcome.kind == "timeout":
        return "failed", "Timeout after %g s" % test.timeout
    if outcome.kind == "signal":
        return "failed", "Exception: %s" % _signal_name(outcome.code)
    out, reason, forced = outcome.output, "exit code %d" % outcome.code, False
    if test.pass_re and not any(rx.search(out) for _, rx in test.pass_re):
        reason, forced = "Required regular expression not found: %s" % [r for r, _ in test.pass_re], True
    for text, rx in test.fail_re:
        if rx.search(out):
            reason, forced = "Error regular expression found in output: [%s]" % text, True
            break
    success = not forced and (outcome.code == 0 or bool(test.pass_re))
    verdict = "passed" if success != test.will_fail else "failed"
    if test.will_fail and verdict == "failed":
        reason = "WILL_FAIL, and it passed (%s)" % reason
    if test.skip_code is not None and outcome.code == test.skip_code:
        return "skipped", "SKIP_RETURN_CODE=%d" % test.skip_code
    for text, rx in test.skip_re:
        if rx.search(out):
            return "skipped", "SKIP_REGULAR_EXPRESSION matched: [%s]" % text
    return verdict, reason


def _signal_name(number):
    try:
        return signal.Signals(number).name
    except ValueError:
        return "signal %d" % number


def run_one(test, base_env):
    """Runs one test as ctest does: its own process group (a timeout kills the whole of it), stdout
    and stderr in one stream, its ENVIRONMENT on top of ours."""
    env = dict(base_env)
    for assignment in test.env:
        key, _, value = assignment.partition("=")
        env[key] = value
    start = time.monotonic()
    if not test.command:
        return Outcome("notrun", None, "the test has no command (its executable was not built)", 0.0)
    try:
        os.makedirs(test.cwd, exist_ok=True)  # (the pack holds no empty folders of the build)
        proc = subprocess.Popen(test.command, cwd=test.cwd, env=env, stdin=subprocess.DEVNULL,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
    except OSError as e:
        return Outcome("notrun", None, "could not start %s: %s" % (test.command[0], e), 0.0)
    kind = None
    try:
        raw, _ = proc.communicate(timeout=test.timeout)
    except subprocess.TimeoutExpired:
        kind = "timeout"
        _kill_group(proc.pid)
        try:
            raw, _ = proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:  # (a grandchild in a session of its own holds the pipe)
            proc.kill()
            proc.wait()
            raw = b"gpu_check: the output could not be read after the timeout\n"
    seconds = time.monotonic() - start
    output = raw.decode("utf-8", "replace")
    if kind is None:
        kind = "exited" if proc.returncode >= 0 else "signal"
    code = proc.returncode if kind == "exited" else -proc.returncode if kind == "signal" else None
    return Outcome(kind, code, output, seconds)


def _kill_group(pid):
    try:
        os.killpg(pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _order(tests, costs):
    """Longest first, as ctest does with the costs of the last run, so the slow ones (truth, check
    cases) do not start last; without costs, the list's order."""
    return sorted(tests, key=lambda t: -float(costs.get(t.name, 0.0)))


def _fits(test, free, jobs, running, locks):
    if test.serial:
        return not running
    if any(t.serial for t in running):
        return False
    return min(test.processors, jobs) <= free and not (test.locks & locks)


def run_all(tests, jobs, base_env, costs=None, report=None):
    """Every test, `jobs` slots at a time; {test: (verdict, reason, outcome)}, by test and not by
    name: names repeat (each lab's test binary has its own student.Manifest.* tests). `report` is
    called as each ends (from this thread)."""
    pending, results = _order(tests, costs or {}), {}
    running, free, locks = {}, jobs, set()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        while pending or running:
            for test in list(pending):
                if _fits(test, free, jobs, running.values(), locks):
                    pending.remove(test)
                    free -= min(test.processors, jobs)
                    locks |= test.locks
                    if test.disabled:
                        future = pool.submit(lambda: Outcome("disabled", None, "", 0.0))
                    else:
                        future = pool.submit(run_one, test, base_env)
                    running[future] = test
            done, _ = concurrent.futures.wait(list(running), return_when=concurrent.futures.FIRST_COMPLETED)
            for future in done:
                test = running.pop(future)
                free += min(test.processors, jobs)
                locks -= test.locks
                outcome = future.result()
                verdict, reason = ("skipped", "DISABLED") if outcome.kind == "disabled" else judge(test, outcome)
                results[test] = (verdict, reason, outcome)
                if report:
                    report(test, verdict, reason, outcome, len(results))
    return results


# ----------------------------------------------------------------------------------------------------
# Reports: results.tsv and failures.txt as in the NVIDIA run's (shared/gpu/), a table per label, and
# the closing line.

def write_reports(tests, results, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "results.tsv"), "w") as f:
        for t in tests:
            verdict, _, outcome = results[t]
            f.write("%s\t%s\t%s\t%.2f\n" % (t.name, ",".join(t.labels), verdict, outcome.seconds))
    # The verdict tests' failures first, then the framework's (as shared/gpu/failures.txt).
    failing = [t for t in tests if results[t][0] == "failed"]
    failing.sort(key=lambda t: "framework" in t.labels)
    with open(os.path.join(out_dir, "failures.txt"), "w") as f:
        for t in failing:
            verdict, reason, outcome = results[t]
            f.write("==== %s [%s] %s %.1fs\n" % (t.name, ",".join(t.labels), verdict, outcome.seconds))
            f.write(outcome.output.rstrip("\n") + "\n")
            f.write("gpu_check: %s\n\n" % reason)


def is_verdict_test(test):
    """A verdict label, even beside "framework" (the mutants.* tests of check's attribution are both,
    and the NVIDIA run counted them among the verdict tests)."""
    return any(label in VERDICT_LABELS for label in test.labels)


def label_table(tests, results, every_label=False):
    """Lines of a table: label, passed, failed, skipped. The per-exercise labels (lab03.2) only
    with every_label: there are dozens."""
    counts = {}
    for t in tests:
        for label in t.labels:
            if every_label or not re.match(r"^lab\d+\.", label):
                row = counts.setdefault(label, {"passed": 0, "failed": 0, "skipped": 0})
                row[results[t][0]] += 1
    width = max([len("label")] + [len(k) for k in counts])
    lines = ["%-*s %7s %7s %8s" % (width, "label", "passed", "failed", "skipped")]
    for label in sorted(counts, key=lambda k: (k.startswith("lab"), k)):
        c = counts[label]
        lines.append("%-*s %7d %7d %8d" % (width, label, c["passed"], c["failed"], c["skipped"]))
    return lines


def closing_line(results):
    """`N passed, N failed` (`, N skipped` when some were): the line a caller greps for."""
    n = {"passed": 0, "failed": 0, "skipped": 0}
    for verdict, _, _ in results.values():
        n[verdict] += 1
    line = "%d passed, %d failed" % (n["passed"], n["failed"])
    return line + (", %d skipped" % n["skipped"] if n["skipped"] else "")


def select(tests, only, exclude, labels):
    """ctest's -R, -E and -L (every --label must match one of a test's labels, as repeated -L do)."""
    chosen = []
    for t in tests:
        if only and not re.search(only, t.name):
            continue
        if exclude and re.search(exclude, t.name):
            continue
        if all(any(re.search(rx, label) for label in t.labels) for rx in labels):
            chosen.append(t)
    return chosen
