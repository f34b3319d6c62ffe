#!/usr/bin/env python3
"""Every call of a C++ exercise in the tests goes through the tape: WB_CALL(...) or
WB_CALL_HELD_OUT(...), or names it for the runner (WB_CALLABLE). A judge then replays what the
student's build returned and never runs the student's code itself; a direct call (09.4 and 09.5's
tests once made one) ran a student's endless loop inside the judge, without a limit.

  exercise_calls.py [ROOT]        exit 1 naming each direct call (file:line)
  exercise_calls.py --self-test   prove that a direct call is found and a taped one is not
"""
import pathlib
import re
import sys
import tempfile

DECLARATION = re.compile(r"^[\w:<>,\s\*&]*?\b(\w+)\s*\([^;{]*\)\s*;", re.M)
TAPED = ("WB_CALL(", "WB_CALL_HELD_OUT(", "WB_CALLABLE(")


def exercise_functions(header):
    """The function names declared at namespace level in a lab's exercise.hpp."""
    text = re.sub(r"//[^\n]*", "", header.read_text(errors="replace"))
    return {m.group(1) for m in DECLARATION.finditer(text)} - {"operator"}


LAMBDA = re.compile(r"auto\s+(\w+)\s*=\s*\[")


def in_taped_statement(text, at):
    """True when the statement around `at` (from the end of the last ;, { or }) calls through the tape."""
    start = max(text.rfind(c, 0, at) for c in ";{}") + 1
    return any(t in text[start:at] for t in TAPED)


def taped(text, at):
    """True when the exercise call at `at` goes through the tape: in a WB_CALL statement, or inside a
    lambda (`auto NAME = [...] {...}`, in the same test) that is only ever called in WB_CALL statements."""
    if in_taped_statement(text, at):
        return True
    test_start = text.rfind("TEST", 0, at)
    lambdas = list(LAMBDA.finditer(text, max(test_start, 0), at))
    if not lambdas:
        return False
    name, after = lambdas[-1].group(1), lambdas[-1].end()
    uses = [u.start() for u in re.finditer(r"\b" + name + r"\s*\(", text[after:])]
    next_test = text.find("\nTEST", at)
    uses = [after + u for u in uses if next_test < 0 or after + u < next_test]
    return bool(uses) and all(in_taped_statement(text, u) for u in uses)


def direct_calls(root):
    found = []
    for header in sorted((root / "labs").glob("[0-9][0-9]_*/exercise.hpp")):
        lab, nn = header.parent.name, header.parent.name[:2]
        names = exercise_functions(header)
        if not names:
            continue
        call = re.compile(r"\blab" + nn + r"::(" + "|".join(sorted(names)) + r")\s*\(")
        sources = [p for d in ("tests", "tests/hidden") for p in sorted((root / d / lab).glob("*.cpp"))]
        for f in sources:
            text = f.read_text(errors="replace")
            for m in call.finditer(text):
                if not taped(text, m.start()):
                    line = text.count("\n", 0, m.start()) + 1
                    found.append(f"{f.relative_to(root).as_posix()}:{line}: lab{nn}::{m.group(1)}(...) is called "
                                 f"directly: wrap it in WB_CALL(...), so that a judge replays it")
    return found


def main(argv):
    if argv[1:2] == ["--self-test"]:
        with tempfile.TemporaryDirectory() as tmp:
            root = pathlib.Path(tmp)
            (root / "labs/77_fake").mkdir(parents=True)
            (root / "tests/77_fake").mkdir(parents=True)
            (root / "labs/77_fake/exercise.hpp").write_text("namespace lab77 {\n/// EXERCISE 77.1\nint f(int x);\n}\n")
            (root / "tests/77_fake/t.cpp").write_text(
                "int a = WB_CALL(lab77::f(1));\nWB_TRY_EXERCISE(s = g(WB_CALL(h(lab77::f(2)))));\n"
                "WB_TRY_EXERCISE(s = lab77::f(3));\n"
                "TEST(L, A) {\n  auto after = [] { lab77::f(4); return 1; };\n  int v = WB_CALL(after());\n}\n"
                "TEST(L, B) {\n  auto leaky = [] { return lab77::f(5); };\n  int v = WB_CALL(leaky());\n"
                "  int w = leaky();\n}\n")
            found = direct_calls(root)
        ok = [f.split(":")[1] for f in found] == ["3", "9"]
        print(f"exercise_calls --self-test: {'the direct calls alone are found' if ok else 'FAILED: ' + str(found)}")
        return 0 if ok else 1
    root = pathlib.Path(argv[1]) if len(argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    found = direct_calls(root)
    for f in found:
        print(f)
    print(f"exercise_calls: {len(found)} direct calls of a C++ exercise in the tests")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
