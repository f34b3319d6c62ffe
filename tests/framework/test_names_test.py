#!/usr/bin/python3
"""The grader's convention on test names (tools/grading/outcomes.py test_runs_app, and check's
tests/harness/main.cpp drawsScene): a test that draws a scene is named Ex<NN>_<K>_Scene... or
Ex<NN>_<K>_Measured..., and no other test has Scene or Measured anywhere in its name (09.4's
"...CountsFacesInFrontOfTheScene", a kernel test, was counted as a scene, and a hunt that waits on
its scenes would have been told it has no test of its own). Usage: test_names_test.py [ROOT]"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
TEST = re.compile(r"\bTEST(?:_F)?\(\s*\w+\s*,\s*(Ex\d\d_(?:\d+|x|H\d+)_(\w+))\s*\)")
problems, names = [], 0
for source in sorted(ROOT.glob("tests/**/*.cpp")):
    for m in TEST.finditer(source.read_text(errors="replace")):
        names += 1
        name, rest = m.group(1), m.group(2)
        says = "Scene" in name or "Measured" in name
        if says and not rest.startswith(("Scene", "Measured")):
            problems.append(f"{source.relative_to(ROOT)}: {name}: 'Scene' or 'Measured' only as the name's first word "
                            "after the exercise (the grader and check take any such name for a test that draws a scene)")
for p in problems:
    print("FAIL:", p)
print(f"{names} exercise tests: " + ("the scene convention holds" if not problems else f"{len(problems)} problems"))
sys.exit(1 if problems or not names else 0)
