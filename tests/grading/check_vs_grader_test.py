#!/usr/bin/env python3
"""`check` and the grader on the same submissions: their verdicts must agree exercise by exercise.

    check_vs_grader_test.py BUILD OUT [NAME,...]   (only these cases, by name)

Each case is a lab folder that the build already holds (BUILD/mutants/NN_name/NAME: the solution's
exercise files with one mistake): the check cases of labs 01 and 03 (a wrong C++ result, a crash, an
endless loop; a GLSL compile error, an endless shader loop, a wrong filter), one C++ and one GLSL
mutant of labs 01 and 02, and a wrong fix of each of their bug hunts. `check` runs as a student's does
(wb_check: the runner one exercise at a time, then the judge); the grader grades the same files as an
upload (grade.py --batch, in its sandbox, with the same time limits). An exercise passes in check when
its row says "passes its tests", in the grader when its test has status "passed". Every difference
is printed and fails the test; "waiting" and "blocked" rows of the student edition do not occur here
(the instructor's check judges with the solution's shaders), and the test says so if one does."""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CASES = [
    "01_depth_map/case_cpp_wrong", "01_depth_map/case_cpp_crash", "01_depth_map/case_cpp_endless",
    "03_pcf/case_glsl_compile_error", "03_pcf/case_glsl_endless", "03_pcf/case_glsl_wrong",
    "01_depth_map/spot_degrees", "01_depth_map/flipped_compare", "01_depth_map/hunt_half_way",
    "02_bias/culling_never_enabled", "02_bias/bias_sign_flipped", "02_bias/hunt_texel_divided",
]
LIMIT = "8"  # seconds an exercise may run, in both (the endless cases run into it)
ROW = re.compile(r"^  (\d\d\.(?:\d+|x|H\d+))\s+(passes its tests|wrong|error|not implemented|waiting[^ ]*|blocked[^ ]*)",
                 re.M)


def check_verdicts(build, out, case):
    lab, name = case.split("/")
    nn = lab[:2]
    tests = build / f"lab{nn}_mutant_{name}_tests"
    if not tests.exists():  # a GLSL mistake: the solution's C++, the case's shaders
        tests = build / f"lab{nn}_solution_tests"
    env = dict(os.environ, WB_TEST_OUTPUT_DIR=str(out / "check-output" / name), WB_CHECK_TIMEOUT=LIMIT)
    proc = subprocess.run([str(build / "wb_check"), nn, "--root", str(ROOT), "--tests", str(tests), "--judge",
                           str(build / f"lab{nn}_solution_tests"), "--submission", str(build / "mutants" / case),
                           "--tape", str(out / "check-tape" / name)], env=env, capture_output=True, text=True,
                          timeout=600)
    (out / f"check_{name}.log").write_text(proc.stdout + proc.stderr)
    return {m.group(1): m.group(2) for m in ROW.finditer(proc.stdout + proc.stderr)}


def main():
    build, out = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    if len(sys.argv) > 3:
        CASES[:] = [c for c in CASES if c.split("/")[1] in sys.argv[3].split(",")]
    shutil.rmtree(out, ignore_errors=True)
    subs = out / "submissions"
    labs = sorted({c.split("/")[0] for c in CASES})
    for case in CASES:  # an upload of the case's lab, the other labs as handed out
        lab, name = case.split("/")
        shutil.copytree(build / "mutants" / case, subs / name / "labs" / lab)
    nns = ",".join(l[:2] for l in labs)
    grade = subprocess.run([sys.executable, "-B", str(ROOT / "tools/grading/grade.py"), "--batch", str(subs), "--out",
                            str(out / "grades"), "--labs", nns, "--jobs", "1", "--timeout", LIMIT, "--build-timeout",
                            "60", "--judge-build", str(build)], capture_output=True, text=True,
                           env=dict(os.environ, WB_GRADE_SEED="14"))
    (out / "grade.log").write_text(grade.stdout + grade.stderr)
    if grade.returncode != 0:
        sys.exit(f"FAIL: the grader failed:\n{(grade.stdout + grade.stderr)[-3000:]}")
    differences, rows = [], []
    for case in CASES:
        lab, name = case.split("/")
        checked = check_verdicts(build, out, case)
        tests = json.loads((out / "grades" / name / "results.json").read_text())["tests"]
        graded = {}  # (an exercise's held-out tests are a second entry with its number: both must pass)
        for t in tests:
            if t.get("number", "").startswith(lab[:2] + "."):
                graded[t["number"]] = graded.get(t["number"], True) and t["status"] == "passed"
        if not checked:
            differences.append(f"{case}: check printed no verdict table (log: {out / f'check_{name}.log'})")
            continue
        for ex, status in sorted(checked.items()):
            if status.startswith(("waiting", "blocked")):
                differences.append(f"{case}: {ex} is '{status}' in check, which the instructor's check never says")
            elif (status == "passes its tests") != graded.get(ex, False):
                differences.append(f"{case}: {ex}: check says '{status}', the grader "
                                   f"{'passed' if graded.get(ex) else 'failed'} it")
        lost = sorted(ex for ex, ok in graded.items() if not ok)
        rows.append(f"{case:34s} lost in both: {', '.join(lost) or '-'}")
        missing = sorted(set(graded) - set(checked))
        if missing:
            differences.append(f"{case}: check has no row for {', '.join(missing)}")
    print("\n".join(rows))
    for d in differences:
        print("DIFFERS:", d)
    print(f"{len(CASES)} submissions, check and the grader " +
          ("agree on every exercise" if not differences else f"differ {len(differences)} times"))
    sys.exit(1 if differences else 0)


if __name__ == "__main__":
    main()
