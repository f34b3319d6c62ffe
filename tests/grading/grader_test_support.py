"""What the grader's Python tests share: tools/grading/grade.py loaded as a module (without writing
__pycache__ into tools/), and a list of problems that ends the test with one line."""
import importlib.util
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in tools/
ROOT = Path(__file__).resolve().parent.parent.parent


def load(path):
    """A Python file of the grader's, loaded as a module."""
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


grade = load(ROOT / "tools/grading/grade.py")

problems = []


def check(cond, what):
    """Notes a problem when `cond` is false."""
    if not cond:
        problems.append(what)


def finish(title, ok_text="all as expected"):
    """Prints the problems and a verdict line, and exits 1 if there were any."""
    for p in problems:
        print("FAIL:", p)
    print(f"{title}: " + (ok_text if not problems else f"{len(problems)} problems"))
    sys.exit(1 if problems else 0)
