#!/usr/bin/python3
"""What the grader writes for Gradescope and for a batch (ctest -L grading; no build needed):
- results.json uses only the keys of Gradescope's autograder specification (docs/gradescope.md);
- what students see before the due date (the top-level output, the visible tests) never gives away
  the points of held-out tests, and held-out points under `hidden` are written as after_published;
- student-visible text holds no grader path, build command or absolute path (report.md keeps them);
- weaker isolation (no network namespace) is in results.json for the instructor and in report.md;
- flat uploads (exercise.cpp, exercise.glsl without folders) belong to the assignment's only lab,
  and are reported as ambiguous when it has several;
- students in a batch get unique names (erin.smith.zip and erin.jones are two students);
- PrairieLearn's result made from the same results.json (tools/grading/prairielearn/results.py): a
  score in [0, 1], the held-out tests as one test without their cases, pictures as images, no test
  for instructors only, under 1 MB."""
import base64
import csv
import json
import re
import sys
import tempfile
import zipfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from grader_test_support import ROOT, check, finish, grade, load

pl = load(ROOT / "tools/grading/prairielearn/results.py")


# Gradescope's autograder specification, "Output format" (gradescope-autograders.readthedocs.io/en/latest/specs/).
TOP_KEYS = {"score", "execution_time", "output", "output_format", "test_output_format", "test_name_format",
            "visibility", "stdout_visibility", "extra_data", "tests", "leaderboard"}
TEST_KEYS = {"score", "max_score", "status", "name", "name_format", "number", "output", "output_format", "tags",
             "visibility", "extra_data"}
FORMATS = {"text", "html", "simple_format", "md", "ansi"}


def check_spec(res, where):
    check(set(res) <= TOP_KEYS, f"{where}: keys outside the specification: {sorted(set(res) - TOP_KEYS)}")
    check(res.get("visibility", "visible") in grade.VISIBILITIES, f"{where}: visibility {res.get('visibility')}")
    check(res.get("stdout_visibility", "hidden") in grade.VISIBILITIES, f"{where}: stdout_visibility")
    check(res.get("output_format", "md") in FORMATS, f"{where}: output_format {res.get('output_format')}")
    for t in res["tests"]:
        check(set(t) <= TEST_KEYS, f"{where}: test {t.get('name')} has keys outside the specification: "
              f"{sorted(set(t) - TEST_KEYS)}")
        check(t.get("visibility", "visible") in grade.VISIBILITIES, f"{where}: test visibility {t.get('visibility')}")
        check(t.get("status", "passed") in ("passed", "failed"), f"{where}: test status {t.get('status')}")
        check(t.get("output_format", "text") in FORMATS, f"{where}: test output_format {t.get('output_format')}")


def student_sees(res):
    """Everything a student sees before the due date: the top-level output and the visible tests."""
    seen = [res["output"]]
    for t in res["tests"]:
        if t.get("visibility", res.get("visibility", "visible")) == "visible":
            seen += [t.get("name", ""), t.get("output", ""), str(t.get("score", ""))]
    return "\n".join(seen)


class Sandbox:
    def __init__(self, notes):
        self.notes, self.user = notes, "nobody"

    def protections(self):
        return "a fake sandbox (limits: none)"


lab = {"name": "01_depth_map", "nn": "01", "title": "Depth map",
       "exercises": [{"id": "01.1", "title": "Light fit", "file": "exercise.cpp", "points": 20},
                     {"id": "01.2", "title": "Spot light", "file": "exercise.cpp", "points": 17}],
       "hidden_points": {"01.1": 13}, "hidden_visibility": "after_due_date"}
where = f"{ROOT}/build-grade/w0/submission/labs/01_depth_map/exercise.cpp"
compile_error = (f"{where}:12:5: error: 'x' was not declared in this scope\n"
                 "make[2]: *** [CMakeFiles/lab01_submission_exercise.dir/build.make:76: x.o] Error 1\n"
                 f"gmake[1]: *** [CMakeFiles/Makefile2:321: all] Error 2\n"
                 f"cd {ROOT}/build-grade/w0/build && /usr/bin/c++ -O2 -c {where}\n"
                 "In file included from /usr/include/c++/12/bits/stl_vector.h:1123:5,\n"
                 "diff: /autograder/source/build-grade/w0/build/test-output/lab01_submission/Scene/diff.png\n"
                 "scratch: /tmp/grade-x1/submission-y2/labs/01_depth_map/exercise.cpp")

with tempfile.TemporaryDirectory(prefix="gradescope-results-") as tmp:
    tmp = Path(tmp)

    # 1. Held-out tests after the due date: 01.1 passes its visible 7 points and its held-out 13 (which
    # students must not learn before the due date); 01.2 fails to compile.
    out = tmp / "one"
    out.mkdir()
    r = grade.Results(out, "erin.smith", [lab], Sandbox(["network namespaces are not available here: tests run "
                                                          "with the network"]))
    e1, e2 = lab["exercises"]
    r.add(lab, e1, True, [], [], [], hidden_result=(True, [], ""), hidden=True)
    r.add(lab, e2, False, [("", compile_error)], [], ["a note about " + where])
    r.finish(1.0)
    res = json.loads((out / "results.json").read_text())
    check_spec(res, "1")
    check(res["score"] == 20, f"1: the score (the grade) is {res['score']}, expected 20 (7 + 13 held out)")
    held = [t for t in res["tests"] if "held-out" in t["name"]]
    check(len(held) == 1 and held[0]["visibility"] == "after_due_date" and held[0]["max_score"] == 13,
          f"1: the held-out test is {held}")
    seen = student_sees(res)
    check("7 of 24 points" in res["output"], f"1: the output does not give the visible points 7 of 24: {res['output']!r}")
    for leak in ("20", "13 of", "37"):
        check(not re.search(rf"(?<![\d.]){leak}(?![\d.])", res["output"]),
              f"1: the student-visible output gives away held-out points ({leak!r}): {res['output']!r}")
    doc = pl.convert(res)
    check(abs(doc["score"] - 20 / 37) < 1e-9 and doc["gradable"] and doc["message"].startswith("20 of 37 points"),
          f"1: PrairieLearn's score is {doc['score']} ({doc['message']}), expected 20 of 37")
    names = [t["name"] for t in doc["tests"]]
    check(names == ["01.1 Light fit", "01.2 Spot light", "Held-out tests"], f"1: PrairieLearn's tests are {names}")
    check(doc["tests"][-1]["points"] == 13 and doc["tests"][-1]["output"] == "",
          f"1: PrairieLearn's held-out test names exercises, or lacks its points: {doc['tests'][-1]}")
    detail = pl.convert(res, "exercises")["tests"][-1]
    check(detail["output"] == "01.1: passed", f"1: PrairieLearn's held-out test, exercises asked for: {detail}")
    salvaged = tmp / "salvaged"
    grade.salvage(salvaged, "x", [lab], Sandbox([]), "the grader could not unpack its tree", 1.0)
    doc = pl.convert(json.loads((salvaged / "results.json").read_text()))
    check(doc["gradable"] is False and doc["score"] == 0, f"1: a grader's fault costs PrairieLearn's attempt: {doc}")
    # 2. No grader path, build command or absolute path in what students see.
    for bad in (str(ROOT), "build-grade", "/autograder", "/tmp/", "/usr/", "make[2]", "gmake", "/usr/bin/c++", "cd /"):
        check(bad not in seen, f"2: students see {bad!r}")
    check(not re.search(r"(^|[\s'\"(])/\w", seen), "2: students see an absolute path: " +
          next((l for l in seen.splitlines() if re.search(r"(^|[\s'\"(])/\w", l)), ""))
    check("labs/01_depth_map/exercise.cpp:12:5: error" in seen, "2: the compiler message lost the student's file:line")
    report = (out / "report.md").read_text()
    check("build-grade/w0/submission/labs/01_depth_map/exercise.cpp" in report, "2: report.md lost the grader's path")
    # 3. Weaker isolation is reported to the instructor (a hidden test with no points) and in report.md.
    env = [t for t in res["tests"] if "grading-environment" in t.get("tags", [])]
    check(len(env) == 1 and env[0]["visibility"] == "hidden" and env[0]["max_score"] == 0
          and env[0]["status"] == "failed" and "tests run with the network" in env[0]["output"],
          f"3: the isolation note is not in a hidden instructor test: {env}")
    check("isolation: network namespaces are not available" in report, "3: report.md does not say the isolation failed")
    check("tests run with the network" not in seen, "3: students see the isolation note")

    # 4. `hidden` held-out tests carry points: Gradescope would show them in the total, so they are
    # written as after_published; a visibility that Gradescope does not know is refused.
    check(grade.gradescope_visibility("hidden", 13) == "after_published", "4: hidden with points stays hidden")
    check(grade.gradescope_visibility("hidden", 0) == "hidden", "4: hidden without points changed")
    try:
        grade.gradescope_visibility("later", 5)
        check(False, "4: an unknown visibility was accepted")
    except ValueError:
        pass

    # 5. Without held-out tests the output gives the total.
    out = tmp / "five"
    out.mkdir()
    plain = dict(lab, hidden_points={})
    r = grade.Results(out, "x", [plain], Sandbox([]))
    r.add(plain, e1, True, [], [], [])
    r.add(plain, e2, True, [], [], [])
    r.finish(1.0)
    res = json.loads((out / "results.json").read_text())
    check_spec(res, "5")
    check(res["output"].startswith("37 of 37 points"), f"5: output {res['output']!r}")
    env = [t for t in res["tests"] if "grading-environment" in t.get("tags", [])]
    check(env and env[0]["status"] == "passed", "5: the grading environment test failed with full isolation")

    # 6. Flat uploads.
    sub = tmp / "flat"
    (sub / "shaders").mkdir(parents=True)
    (sub / "exercise.cpp").write_text("int x;\n")
    (sub / "exercise.glsl").write_text("// glsl\n")
    path, note = grade.find_student_file(sub, "03_pcf", "exercise.cpp", ["03_pcf"])
    check(path == sub / "exercise.cpp" and note and "labs/03_pcf/exercise.cpp" in note,
          f"6: a flat exercise.cpp in a one-lab assignment: {path}, {note}")
    path, note = grade.find_student_file(sub, "03_pcf", "shaders/exercise.glsl", ["03_pcf"])
    check(path == sub / "exercise.glsl", f"6: a flat exercise.glsl in a one-lab assignment: {path}, {note}")
    path, note = grade.find_student_file(sub, "03_pcf", "exercise.cpp", ["03_pcf", "04_esm"])
    check(path is None and note and "cannot tell which lab" in note and "03, 04" in note,
          f"6: a flat file in a two-lab assignment is not reported as ambiguous: {path}, {note}")
    full = tmp / "repo" / "workbook-main" / "labs" / "03_pcf" / "shaders"
    full.mkdir(parents=True)
    (full / "exercise.glsl").write_text("// glsl\n")
    path, note = grade.find_student_file(tmp / "repo", "03_pcf", "shaders/exercise.glsl", ["03_pcf", "04_esm"])
    check(path == full / "exercise.glsl" and note is None, f"6: the repository layout: {path}, {note}")
    path, note = grade.find_student_file(tmp / "repo", "03_pcf", "exercise.cpp", ["03_pcf"])
    check(path is None and note is None, f"6: a missing file: {path}, {note}")
    # An upload that is one zip of flat files, left as it is in the submission folder.
    up = tmp / "upload"
    up.mkdir()
    with zipfile.ZipFile(up / "mine.zip", "w") as z:
        z.writestr("exercise.cpp", "int y;\n")
    folder = grade.unpack(up, tmp)
    path, _ = grade.find_student_file(folder, "03_pcf", "exercise.cpp", ["03_pcf"])
    check(path is not None and path.read_text() == "int y;\n", f"6: a folder holding one zip: {path}")

    # 7. Unique names in a batch.
    batch = tmp / "batch"
    batch.mkdir()
    for d in ("erin.jones", "erin", "bob"):
        (batch / d).mkdir()
    for f in ("erin.smith.zip", "erin.zip", "bob.tar.gz", "carl.TGZ", "dana.tar"):
        (batch / f).write_bytes(b"")
    names = grade.unique_names(list(batch.iterdir()))
    by_file = {p.name: n for p, n in names.items()}
    check(len(set(names.values())) == len(names), f"7: names collide: {by_file}")
    check(by_file.get("erin.smith.zip") == "erin.smith" and by_file.get("erin.jones") == "erin.jones",
          f"7: erin.smith.zip and erin.jones: {by_file}")
    check(by_file.get("carl.TGZ") == "carl" and by_file.get("dana.tar") == "dana", f"7: suffixes: {by_file}")
    check({by_file.get("erin"), by_file.get("erin.zip")} == {"erin", "erin-2"}, f"7: erin/ and erin.zip: {by_file}")
    check({by_file.get("bob"), by_file.get("bob.tar.gz")} == {"bob", "bob-2"}, f"7: bob/ and bob.tar.gz: {by_file}")
    results = [{"name": n, "score": 1, "max_score": 37, "entries": [], "seconds": 1.0,
                "timing": {"build": 0.0, "tests": 0.0}, "problems": [], "environment": ["no network namespace"]}
               for n in names.values()]
    grade.write_batch_outputs(batch, results, [lab])
    rows = [row["student"] for row in csv.DictReader(open(batch / "gradebook.csv"))]
    check(sorted(rows) == sorted(names.values()), f"7: gradebook rows {rows}")
    check("no network namespace" in (batch / "summary.md").read_text(), "7: summary.md does not report the isolation")

# 6. Pictures: a failing visible scene test shows its panels inside the student's output (a data URI);
# a held-out test's picture never does; the whole results.json stays under 1 MB with many pictures.
with tempfile.TemporaryDirectory(prefix="gradescope-pictures-") as tmp:
    out = Path(tmp)
    (out / "images").mkdir()
    png = bytes.fromhex("89504e470d0a1a0a") + bytes(60000)  # (a PNG's signature; 60 KB)
    images = []
    for k in range(30):
        (out / "images" / f"01_1_s{k}_panels.png").write_bytes(png)
        images.append((f"Lab01.Ex01_1_Scene{k}", "picture", f"01_1_s{k}_panels.png"))
    (out / "images" / "01_1_h_panels.png").write_bytes(png[:8] + bytes([7]) * 60000)  # (held out: other bytes)
    plain = dict(lab, hidden_points={})
    r = grade.Results(out, "x", [plain], Sandbox([]))
    r.add(plain, e1, False, [("Lab01.Ex01_1_Scene0", "WRONG: visibility differs")],
          [("Hidden01.Ex01_1_SceneHeldOut", "picture", "01_1_h_panels.png")] + images, [])
    r.finish(1.0)
    text = (out / "results.json").read_text()
    res = json.loads(text)
    first = res["tests"][0]["output"]
    check("![reference, yours, difference](data:image/png;base64,iVBORw0KGgo" in first,
          "6: the failing scene's panels are not in the student's output")
    check(first.count("data:image/png") < 30, "6: every picture went in, past the budget")
    check(len(text) < 1 << 20, f"6: results.json is {len(text)} bytes, over 1 MB")
    held = base64.b64encode((out / "images" / "01_1_h_panels.png").read_bytes()).decode()[100:160]
    check(held not in text, "6: a held-out test's picture is in results.json")
    check("room for no more" in first, "6: the output does not say that pictures were left out")
    doc = pl.convert(res)
    shown = doc["tests"][0]
    check(shown["images"] and all(i["url"].startswith("data:image/png;base64,iVBORw0KGgo") for i in shown["images"])
          and "data:image" not in shown["output"] and "WRONG: visibility differs" in shown["output"],
          f"6: PrairieLearn's test does not show the panels as images beside its text: {shown['output'][:300]}")
    check(len(json.dumps(doc)) < 1_000_000 and held not in json.dumps(doc), "6: PrairieLearn's result is too big or "
          "shows a held-out picture")
    check(len(json.dumps(pl.fit(dict(doc, tests=[dict(shown, images=shown["images"] * 20)])))) < 1_000_000,
          "6: PrairieLearn's result is not cut to 1 MB")

# 7. An extension's bonus points are said apart, never as a score above the maximum ("925 of 915").
with tempfile.TemporaryDirectory(prefix="gradescope-bonus-") as tmp:
    ext = {"id": "01.x", "title": "Extension", "file": "exercise.cpp", "points": 10, "extension": True}
    bonus_lab = dict(lab, hidden_points={}, exercises=lab["exercises"] + [ext])
    r = grade.Results(Path(tmp), "x", [bonus_lab], Sandbox([]))
    for e in bonus_lab["exercises"]:
        r.add(bonus_lab, e, True, [], [], [])
    r.finish(1.0)
    out = json.loads((Path(tmp) / "results.json").read_text())["output"]
    check(out.startswith("37 of 37 points and 10 bonus points from extensions."), f"7: the bonus is not said apart: {out!r}")
    doc = pl.convert(json.loads((Path(tmp) / "results.json").read_text()))
    check(doc["score"] == 1.0 and doc["message"].startswith("37 of 37 points and 10 bonus points"),
          f"7: PrairieLearn's score is {doc['score']} ({doc['message']}), expected 1.0 with the bonus said apart")

# gtest prints the floats it is given with 17 digits; students read 6.
short = grade.student_visible("WRONG: cosTheta 0.89999997615814209, tolerance 1.0000000000000001e-05.")
check(short == "WRONG: cosTheta 0.9, tolerance 1e-05.", f"numbers are not shortened for students: {short}")

# An __has_include that probes the hidden solutions' exercise.cpp: what the student sees neither names
# it like their own file nor says that it exists ("Permission denied").
probe = grade.student_visible("/autograder/source/solutions/09_shadow_volumes/exercise.cpp: Permission denied")
check("exercise.cpp" not in probe and "Permission denied" not in probe,
      f"a probe of the solutions reads as the student's own file, or tells that it exists: {probe}")
# The stubs as handed out, which an earlier edition's file is told to copy a new exercise from, are
# named as they are (every student's edition has them); a path that climbs out of them is not.
line = "labs/01_depth_map/exercise.cpp predates exercise 01.H1: copy its chunk from tests/stubs/01_depth_map/exercise.cpp"
check(grade.student_visible(line) == line, f"the stub's place is hidden from the student: {grade.student_visible(line)}")
climb = grade.student_visible("tests/stubs/../../solutions/01_depth_map/exercise.cpp: No such file or directory")
check("solutions" not in climb and "exercise.cpp" not in climb, f"a path out of the stubs is shown as it is: {climb}")
finish("gradescope results", "all as expected")
