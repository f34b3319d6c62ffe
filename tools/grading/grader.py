"""One submission graded: the runner records in the sandbox, the judge decides
(docs/grading-trust.md)."""
import concurrent.futures
import os
import secrets
import shutil
import tarfile
import tempfile
import threading
import time
import traceback
import zipfile

from .chunks import BUILD_TIMED_OUT, DEFAULT_BUILD_TIMEOUT, build_failure, chunk, keep_only_chunks
from .common import MAX_FILE_BYTES, ROOT, log
from .outcomes import (CUT_SHORT, copy_images, explanation, grader_failed, gtest_failures, hung_by_itself,
                       left_as_stub, named_limit, runs_app, stopped_itself, supervised_run, tag_id)
from .report import Results, first_line
from .sandbox import minimal_env, run_killable, sweep_leftovers
from .heldout import plan_requests
from .submission import fill_missing, find_student_file, student_files, unpack
from .workspace import copy_tape


class Grader:
    def __init__(self, ws, labs, sandbox, timeout, jobs, build_timeout=DEFAULT_BUILD_TIMEOUT, deadline=None):
        self.ws, self.labs, self.sandbox, self.timeout = ws, labs, sandbox, timeout
        self.build_timeout = build_timeout  # seconds for one build of the submission's code
        # A grading service's limit on the whole job (time.time() at which to stop), or None: no run
        # may go past it, so the results are written before the service kills the job.
        self.deadline, self.deadline_reached = deadline, False
        self.build_jobs = max(1, jobs)  # cores for this submission
        # Exercises graded at once: twice the cores, since a runner or a judge is a short process that
        # waits for its start-up and files for a good part of its time (on 2 cores, 6 submissions of
        # labs 01 and 02 took 31 s with 4 at once, against 34-36 s with 2).
        # Without a PID namespace (the weakest mode: Gradescope's container) a student's run could read
        # the command line of a judge drawing a held-out scene beside it: one exercise at a time there.
        self.test_jobs = 2 * self.build_jobs if sandbox.mode != "session" else 1
        self.build_timeouts = 0  # how many builds of this submission were stopped
        self.printed = {}  # exercise tag ("01_1") -> MB its runner printed, where the grader cut its output
        self.explained = {}  # (lab nn, exercise id) -> check's lines for its visible run (run_tests)
        # A fresh variation of every scene per submission, unless the instructor fixes one to reproduce a grade.
        self.vary_seed = int(os.environ.get("WB_GRADE_SEED") or secrets.randbelow(1 << 32))
        # Where the time goes, summed over exercises graded at once: every build (compile and link),
        # the runners, and the judge (its planning passes and renders).
        self.spent, self.spent_lock = {"compile": 0.0, "runner": 0.0, "judge": 0.0}, threading.Lock()

    def limit(self, seconds):
        """`seconds` for a run, cut to what is left before the deadline (1 s at least)."""
        if self.deadline is None or self.deadline - time.time() >= seconds:
            return seconds
        self.deadline_reached = True
        return max(1, int(self.deadline - time.time()))

    def count(self, what, since):
        with self.spent_lock:
            self.spent[what] += time.time() - since

    def build(self, labs):
        """Builds the submission app and tests of `labs`: (ok, compiler output). A build that runs past
        the build time limit (compile-time work that takes too long: template or constexpr recursion,
        a huge file) is killed with its compilers and fails with a message that starts with
        BUILD_TIMED_OUT."""
        # The builder user compiles, in the sandbox: no network, no view of the solutions.
        t0, seconds = time.time(), self.limit(self.build_timeout)
        code, out, timed_out = self.sandbox.run(
            self.ws.build_command(self.build_jobs, labs), seconds, env=minimal_env(HOME="/tmp"),
            uid=self.ws.builder, **self.ws.builder_binds())
        self.count("compile", t0)
        if timed_out:
            self.ws.after_killed_build(labs)
            if seconds < self.build_timeout:
                return False, f"{BUILD_TIMED_OUT} at the time limit of the whole job ({CUT_SHORT})"
            self.build_timeouts += 1
            return False, (f"{BUILD_TIMED_OUT} after {seconds} s and was stopped (compile-time work "
                           "that takes too long, such as deep template or constexpr recursion, or a huge file?)")
        return code == 0, out

    def build_lab(self, lab):
        return self.build([lab])

    def compile_lab(self, lab, files, failed_build=None):
        """Builds the lab from the student's files. When exercise.cpp does not compile (or its build
        runs past the time limit), each C++ exercise is tried alone in the stub's file, so an error
        costs only the exercises it is in. Returns {exercise id: compiler message} for the exercises
        that cannot be graded. The student's `files` are already in place. `failed_build`: the output
        of a failed build of this lab alone with these files, which need not run again."""
        ok, out = (False, failed_build) if failed_build is not None else self.build_lab(lab)
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

    def list_tests(self, lab, built=True):
        exe = self.ws.build / f"lab{lab['nn']}_tests"
        if built and not exe.exists():  # the lab could not be built at all (every exercise is then marked broken)
            return []
        # The list comes from the judge (the same test sources, built with the solution): a submission
        # cannot hide a test by printing another list.
        judge = self.ws.judge_bin / f"lab{lab['nn']}_solution_tests"
        code, out, _ = run_killable([str(judge), "--gtest_list_tests"], 60, cwd=self.ws.judge)
        tests, suite = [], ""
        for line in out.splitlines():
            if line and not line.startswith(" "):
                suite = line.split()[0]
            elif line.strip():
                tests.append(suite + line.split()[0])
        return tests

    def run_tests(self, lab, gfilter, tag, held_out=False, replay_uses=(), explain=None):
        """Grades one exercise's tests: (passed, failures [(test, message)], runner output). The
        student's test binary runs as the *runner* in the sandbox and records what its C++ exercises
        produce on a tape; the solution's test binary, the *judge*, replays that tape, draws every
        scene itself (with the student's recorded C++ results, or the student's GLSL chunk) and
        decides. The runner's exit code, output and files claim nothing (common/judge/tape.hpp).
        Held-out tests are in the judge only: a planning pass of the judge says which lab runs the
        runner must record (`held_out`). `explain`: the exercise whose lines of check's table the
        student is shown (self.explained), for a visible run."""
        runner = self.ws.build / f"lab{lab['nn']}_tests"
        judge = self.ws.judge_bin / f"lab{lab['nn']}_solution_tests"
        uid = self.ws.heldout_uid if held_out else self.ws.uid  # (held-out inputs: not for a visible run)
        tape = self.ws.fresh_tape(tag, uid)
        judged = self.ws.judge / "runs" / tag
        shutil.rmtree(judged, ignore_errors=True)
        judged.mkdir(parents=True)
        # WB_VARY_SEED: scene tests turn the scene a little and compare with the solution's render of
        # the same variation, not with the published golden (common/judge/harness.cpp). Each
        # process has a home of its own: nothing in a shared /tmp (a Mesa .drirc) reaches it.
        # (minimal_env: nothing else of the grader's environment reaches the student's code)
        env = minimal_env(HOME=str(tape), TMPDIR=str(tape), WB_STRICT_GL="1", WB_VARY_SEED=str(self.vary_seed),
                          WB_RECORD_SHADERS=str(self.ws.stubs / lab["name"] / "shaders"))
        # WB_REPLAY_USES: the used exercises (manifest "uses") that failed their own tests, the only
        # ones whose recorded results the judge replays beside the graded one; WB_HELD_OUT: quote
        # nothing the runner wrote (it could carry held-out inputs).
        jenv = dict(env, HOME=str(judged), TMPDIR=str(judged), WB_SUBMISSION_DIR=str(self.ws.lab_dir(lab["name"])),
                    WB_REPLAY_USES=",".join(replay_uses), WB_HELD_OUT="1" if held_out else "")
        what = ["--requests", str(self.plan(lab, judge, gfilter, judged, jenv, tape, uid))] if held_out \
            else [f"--gtest_filter={gfilter}"]
        binds = self.ws.runner_binds(tape, held_out)
        t0, seconds, outer = time.time(), self.limit(self.timeout), self.limit(self.timeout + 10)
        # The runner runs under wb_check, check's own supervisor (common/judge/supervisor.hpp): the
        # same limit, cap on output and words for a run that was stopped, in check and here. The
        # sandbox's own time limit, a little longer (within the job's), only catches wb_check itself.
        # A lab run a test starts may take the exercise's whole time, as before (WB_RUN_TIMEOUT).
        check = [str(self.ws.framework / "wb_check"), "--runner", str(runner), tag_id(tag), str(tape)]
        limits = {"WB_CHECK_TIMEOUT": str(seconds), "WB_CHECK_IN_SANDBOX": "1", "WB_RUN_TIMEOUT": str(seconds)}
        code, out, timed_out = self.sandbox.run(check + what, outer, env=dict(env, **limits), cwd=tape, uid=uid,
                                                **binds)
        self.count("runner", t0)
        ran = supervised_run(tape, tag_id(tag), code, out, timed_out, seconds, self.sandbox.cpu_seconds, held_out)
        if held_out:  # the held-out inputs go as soon as they are used, and nothing of them is quoted
            shutil.rmtree(tape / "inputs", ignore_errors=True)
            (tape / "requests.jsonl").unlink(missing_ok=True)
        stopped = ran.stopped  # (shown first)
        if stopped and seconds < self.timeout and ran.timed_out:  # (not this exercise's time limit: the job's)
            stopped = [(test, f"ERROR: not finished at the time limit of the whole job ({CUT_SHORT})")
                       for test, _ in stopped]
        if ran.printed_mb is not None:  # (a flood below the cap is graded as it ended; the student is told)
            self.printed[tag.rsplit("_", 1)[0]] = ran.printed_mb
        out = ran.output
        copy_tape(tape / "all", judged / "all")
        ok, failures = self.judge_tape(lab, judge, gfilter, judged, jenv, stopped, explain if not held_out else None)
        return ok, failures, out

    def judge_tape(self, lab, judge, gfilter, judged, env, stopped, explain):
        """The judge's run over the runner's copied tape (`judged`/all): (passed, failures), the runner's
        `stopped` first. It runs under wb_check --judge, as in check (common/judge/supervisor.hpp): a
        test that makes no progress for half the exercise's limit is stopped, written down for its
        exercise, and the rest judged without it. With `explain` (an exercise id, for a visible run) the
        judge also words the verdict as check does (--check, WB_CHECK_JSON: the lines under its row),
        which the student is shown (self.explained); a stopped runner goes into its stopped.txt so that
        the table says so too (common/judge/tape.cpp)."""
        tape = judged / "all"
        if stopped and explain:
            (tape / "stopped.txt").write_text(f"Ex{explain.replace('.', '_')}\t{stopped[0][1].removeprefix('ERROR: ')}\n")
        before = (tape / "stopped.txt").read_text() if (tape / "stopped.txt").exists() else ""
        report, verdicts = judged / "report.json", judged / "verdicts.json"
        t0, seconds = time.time(), self.limit(self.timeout)
        args = [f"--gtest_filter={gfilter}", f"--gtest_output=json:{report}"] + (["--check"] if explain else [])
        limits = {"WB_CHECK_TIMEOUT": str(self.timeout), "WB_CHECK_JUDGE_TIMEOUT": str(max(self.timeout // 2, 10))}
        jcode, jout, jtimed = run_killable([str(self.ws.judge_bin / "wb_check"), "--judge", lab["nn"], str(judge),
                                            str(judged), env["WB_SUBMISSION_DIR"]] + args, seconds,
                                           env=dict(env, WB_CHECK_JSON=str(verdicts), **limits), cwd=judged)
        if explain:
            self.explained[(lab["nn"], explain)] = explanation(verdicts, explain)
        self.count("judge", t0)
        after = (tape / "stopped.txt").read_text() if (tape / "stopped.txt").exists() else ""
        stopped = stopped + [("", f"ERROR: {line.partition(chr(9))[2]}") for line in after[len(before):].splitlines()]
        if jtimed and seconds < self.timeout:
            return False, stopped + [("", f"ERROR: the judge had not finished at the time limit of the whole job "
                                      f"({CUT_SHORT})")]
        if jtimed:
            return False, stopped + [("", f"ERROR: timed out after {seconds} s while the judge drew this "
                                      "exercise with your shaders (an endless loop in a shader?)")]
        if not report.exists():
            return False, stopped + [("", "ERROR: the judge could not finish (a fault of the grader, not of the "
                                      f"submission: tell the instructor):\n{jout[-2000:]}")]
        count, failures = gtest_failures(report)
        if count == 0:
            return False, stopped + [("", "ERROR: no tests ran")]
        failures = stopped + [(test, named_limit(msg)) for test, msg in failures]
        return not failures, failures

    def plan(self, lab, judge, gfilter, judged, env, tape, uid):
        """The held-out tests' requests for the runner (heldout.plan_requests), timed as the judge's."""
        t0 = time.time()
        try:
            return plan_requests(lab, judge, gfilter, judged, env, tape, uid, self.limit(self.timeout))
        finally:
            self.count("judge", t0)

    def grade_exercise(self, lab, e, tests, broken, replay_uses=()):
        """(ok, failures, images, hidden result, has hidden tests) of one exercise with the current build."""
        ex_id, tag = e["id"], e["id"].replace(".", "_")
        mine = [t for t in tests if f".Ex{tag}_" in t]
        has_hidden = any(t.startswith("Hidden") for t in mine)
        if ex_id in broken:
            msg = broken[ex_id]
            msg = msg if msg.startswith("ERROR") else f"ERROR: does not compile: {first_line(msg)}\n{msg}"
            return False, [("", msg)], [], None, has_hidden
        ok, failures, _ = self.run_tests(lab, f"*.Ex{tag}_*-Hidden*.*", f"{tag}_visible", replay_uses=replay_uses,
                                         explain=ex_id)
        hidden_result = None
        if has_hidden and any("timed out after" in m for _, m in failures):  # another wait would tell nothing new
            hidden_result = (False, [("", "ERROR: not run: the exercise's other tests timed out")], "")
        elif has_hidden:
            hidden_result = self.run_tests(lab, f"Hidden*.Ex{tag}_*", f"{tag}_hidden", held_out=True,
                                           replay_uses=replay_uses)
        kept = copy_images(failures + (hidden_result[1] if hidden_result else []), self.images, tag,
                           self.ws.judge_bin / "test-output")
        return ok, failures, kept, hidden_result, has_hidden

    def grade_alone(self, lab, e, mine, tests, replay_uses=(), stopped=()):
        """Grades C++ exercise `e` with only its own chunk from `mine`, and those of the exercises it
        takes its inputs from ("uses" in the manifest: the judge replays those too), the stubs for the
        others, and for a used exercise that stops whatever runs it (`stopped`: a crash or a loop in its
        own tests): the judge replays its stub's "not implemented" in both renders, which a lab that
        draws without it (lab 11) judges `e` on."""
        stub = ROOT / "labs" / lab["name"] / "exercise.cpp"
        keep = {e["id"], *(u for u in e.get("uses", []) if u not in stopped)}
        hybrid = keep_only_chunks(mine, stub.read_text(), keep, self.ws.lab_dir(lab["name"]) / "exercise.cpp") \
            if stub.exists() and chunk(mine, e["id"]) else None
        if hybrid is None:
            return None
        self.ws.place(lab["name"], "exercise.cpp", hybrid.encode())
        ok, _ = self.build_lab(lab)
        if not ok:
            return None
        return self.grade_exercise(lab, e, tests, {}, replay_uses)

    def untouched(self, lab, files):
        """True when every exercise file of `lab` in the submission is byte for byte the stub (or
        missing, and so the stub): each stub fails its tests by design (the ci preset checks that it
        reports NOT IMPLEMENTED), so nothing needs to run. A class has many such labs."""
        stubs = ROOT / "labs" / lab["name"]
        return all(files.get(rel, b"") in (b"", (stubs / rel).read_bytes()) for rel in student_files(lab))

    def add_untouched(self, results, lab, tests, notes):
        for e in lab["exercises"]:
            tag = e["id"].replace(".", "_")
            hidden = any(t.startswith("Hidden") and f".Ex{tag}_" in t for t in tests)
            results.add(lab, e, False, [("", UNTOUCHED)], [], notes, hidden=hidden)

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
        if self.deadline_reached:
            results.problems.append("grading reached the time limit of the whole job before it ended: the runs "
                                    "after that were cut short, and the exercises they decided scored 0")
        sweep_leftovers(self.ws.uids())
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
            found_files = {lab["name"]: self.take_files(lab, folder) for lab in self.labs}
            # Only the labs the submission touched are built and run (an untouched lab scores 0 unrun).
            touched = [lab for lab in self.labs if not self.untouched(lab, found_files[lab["name"]][0])]
            all_built, first_out = self.build(touched) if touched else (True, "")  # one build when all compile
            results.timing["build"] = time.time() - t_build
            t_tests = time.time()
            for lab in self.labs:
                files, notes = found_files[lab["name"]]
                if lab not in touched:
                    self.add_untouched(results, lab, self.list_tests(lab, built=False), notes)
                    continue
                broken = {}
                if not all_built:  # (the first build was of this lab alone: it need not run twice)
                    broken = self.compile_lab(lab, files, first_out if touched == [lab] else None)
                self.grade_lab(results, lab, files, notes, broken)
            results.timing["tests"] = time.time() - t_tests
            results.timing.update(self.spent)

    def take_files(self, lab, folder):
        """(files, notes): the submission's exercise files of `lab`, placed in the runner's tree (every
        lab's first: one parallel build for all when they compile), and what the student is told of them."""
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
                files[rel], added = fill_missing(self.ws.judge_bin / "wb_check", lab, rel, found.read_bytes())
                notes += added
        for rel, content in files.items():
            self.ws.place(lab["name"], rel, content)
        return files, notes

    def grade_lab(self, results, lab, files, notes, broken):
        """Every exercise of a built lab, in "uses" order (an exercise after those whose results it
        takes), a process each at once; then, where several C++ exercises failed, those that may be
        failing because of another graded again alone."""
        tests = self.list_tests(lab)
        with concurrent.futures.ThreadPoolExecutor(self.test_jobs) as pool:
            outcome, failed_uses = {}, {}
            pending = list(lab["exercises"])
            while pending:
                wave = [e for e in pending if all(u in outcome for u in e.get("uses", []))] or pending
                for e in wave:
                    failed_uses[e["id"]] = [u for u in e.get("uses", []) if u in outcome and not outcome[u][0]]
                futures = {e["id"]: pool.submit(self.grade_exercise, lab, e, tests, broken,
                                                failed_uses[e["id"]]) for e in wave}
                outcome.update({i: f.result() for i, f in futures.items()})
                pending = [e for e in pending if e["id"] not in outcome]
        self.regrade_alone(lab, files, tests, broken, outcome, failed_uses)
        for e in lab["exercises"]:
            ok, failures, kept, hidden_result, has_hidden = outcome[e["id"]]
            mb = self.printed.get(e["id"].replace(".", "_"))
            printed = [f"your tests printed {mb} MB while they ran: the grader kept the first and last "
                       "512 KB of it and left the rest out (a print in a loop?)"] if mb is not None else []
            results.add(lab, e, ok, failures, kept, notes + printed, hidden_result=hidden_result,
                        hidden=has_hidden, explained=self.explained.pop((lab["nn"], e["id"]), None))

    def regrade_alone(self, lab, files, tests, broken, outcome, failed_uses):
        """A C++ exercise runs in the app with the student's other C++ exercises: when several fail, one
        may be failing because of another (a crash, a loop, a wrong light fit). Each is then graded
        again in the stub's file with only its own chunk (`outcome` is updated)."""
        cpp_ids = [e["id"] for e in lab["exercises"] if e["file"] == "exercise.cpp"]
        failing = [i for i in cpp_ids if i in broken or not outcome[i][0]]
        stub_cpp = (ROOT / "labs" / lab["name"] / "exercise.cpp").read_text() if cpp_ids else ""
        mine_cpp = files.get("exercise.cpp", b"").decode(errors="replace")
        failed = [e for e in lab["exercises"] if e["id"] in failing and e["id"] not in broken
                  and runs_app(outcome[e["id"]]) and not hung_by_itself(outcome[e["id"]])
                  and not left_as_stub(outcome[e["id"]], mine_cpp, stub_cpp, e["id"])]
        if not failed or len(failing) < 2 or "exercise.cpp" not in files:
            return
        stopped = {i for i in cpp_ids if i in broken or stopped_itself(outcome[i])}
        for e in failed:
            alone = self.grade_alone(lab, e, mine_cpp, tests, failed_uses[e["id"]], stopped)
            if alone is not None:
                outcome[e["id"]] = alone


UNTOUCHED = "NOT IMPLEMENTED: the lab's exercise files are the stubs as handed out"

