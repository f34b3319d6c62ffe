#!/usr/bin/python3
"""Records what each known mistake looks like, for `./workbook check`: tools/authoring/make_hints.py BUILD_DIR [NN ...]

Every mutant in tests/mutants/NN_name/ is a known mistake, described by its first comment line
("# Mutant: the depths filtered, then compared once"). Its test binary (built in BUILD_DIR) runs
its exercise's tests with --signatures, which writes the value each failing test saw. Those values
and the description go to tests/hints/NN_name.json (public: values and words, no solution code),
and the descriptions to the "Common mistakes" section of labs/NN_name/README.md.
`check` then names the mistake when a student's failing test sees the same value
(common/judge/diagnosis.cpp). Run it after changing a mutant or a test, and commit the result.
Naming labs (01, 09_shadow_volumes) records those only, and leaves the others' hints as they are.
"""
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def fields_of(mutant):
    fields, hint = {}, ""
    for line in mutant.read_text().splitlines():
        if line.startswith("# Mutant:") and not hint:
            hint = line.split(":", 1)[1].strip()
        elif ":" in line and not line.startswith("#"):
            key, value = line.split(":", 1)
            fields.setdefault(key.strip(), value.strip())
    return fields, hint


def replacements(mutant):
    """Every (find, replace) pair of a mutant, in order (a mistake may change several lines)."""
    pairs, find = [], None
    for line in mutant.read_text().splitlines():
        key, _, value = line.partition(":")
        if key == "find":
            find = value.strip()
        elif key == "replace" and find is not None:
            pairs.append((find, value.strip()))
            find = None
    return pairs


def describe(mutant):
    fields, hint = fields_of(mutant)
    return fields.get("exercise", ""), hint


def mutant_command(build, mutant):
    """How to run a mutant's tests (cmake/Lab.cmake): a C++ mistake has its own test binary; a shader
    mistake is graded by the solution's tests, with the mutant's files as the submission."""
    lab = mutant.parent.name
    fields, _ = fields_of(mutant)
    if fields.get("file", "").startswith("shaders/"):
        env = dict(os.environ, WB_SUBMISSION_DIR=str(build / "mutants" / lab / mutant.stem),
                   WB_TEST_OUTPUT_DIR=str(build / "test-output" / f"lab{lab[:2]}_mutant_{mutant.stem}"))
        return build / f"lab{lab[:2]}_solution_tests", env
    return build / f"lab{lab[:2]}_mutant_{mutant.stem}_tests", None


BEGIN, END = "<!-- common mistakes: written by tools/authoring/make_hints.py -->", "<!-- end of common mistakes -->"


def handout_section(hints):
    """The handout's "Common mistakes" list: what `check` names, exercise by exercise."""
    seen, lines = set(), []
    for h in sorted(hints, key=lambda h: h["exercise"]):
        if (h["exercise"], h["hint"]) in seen:
            continue
        seen.add((h["exercise"], h["hint"]))
        lines.append(f"- **{h['exercise']}**: {h['hint']}")
    return "\n".join([BEGIN, "## Common mistakes",
                      "`./workbook check` recognises these by the values they give, and names them:", ""] + lines + [END])


def write_handout_section(lab, hints):
    """Puts handout_section() into labs/<lab>/README.md, replacing the last one, before "How to check"."""
    readme = ROOT / "labs" / lab / "README.md"
    text = readme.read_text()
    section = handout_section(hints)
    if BEGIN in text:
        text = text[:text.index(BEGIN)] + section + text[text.index(END) + len(END):]
    elif "## How to check your work" in text:
        at = text.index("## How to check your work")
        text = text[:at] + section + "\n\n" + text[at:]
    else:
        text = text.rstrip("\n") + "\n\n" + section + "\n"
    readme.write_text(text)


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: tools/authoring/make_hints.py BUILD_DIR [NN ...]")
    build = Path(sys.argv[1]).resolve()  # the tests' apps run in other folders
    only = sys.argv[2:]
    for lab_dir in sorted((ROOT / "tests/mutants").iterdir()):
        if only and not any(lab_dir.name.startswith(n) for n in only):
            continue
        hints = []
        for mutant in sorted(lab_dir.glob("*.mutant")):
            exercise, hint = describe(mutant)
            exe, env = mutant_command(build, mutant)
            if not exe.exists() or not hint:
                sys.exit(f"make_hints: {exe} is not built, or {mutant} has no '# Mutant:' line")
            with tempfile.NamedTemporaryFile("r", suffix=".jsonl") as sig:
                subprocess.run([str(exe), f"--gtest_filter=*Ex{exercise.replace('.', '_')}_*", "--signatures",
                                sig.name], capture_output=True, timeout=600, env=env)
                # A bug hunt gets no hints: its wrong fixes, and the bug as handed out, give the same
                # first failing value too often (a ramp of 7 taps has 8 values), and a hint must never be
                # wrong; its verdict names the symptom instead, with the number and the heatmap.
                for line in ([] if ".H" in exercise else Path(sig.name).read_text().splitlines()):
                    s = json.loads(line)
                    hints.append({"exercise": exercise, "mutant": mutant.stem, "test": s["test"],
                                  "value": s["value"], "hint": hint})
        out = ROOT / "tests/hints" / f"{lab_dir.name}.json"
        out.parent.mkdir(exist_ok=True)
        out.write_text(json.dumps({"about": "what known mistakes give; written by tools/authoring/make_hints.py",
                                   "hints": hints}, indent=1) + "\n")
        write_handout_section(lab_dir.name, hints)
        found = {h["mutant"] for h in hints}
        print(f"{out.relative_to(ROOT)}: {len(hints)} values of {len(found)} of "
              f"{len(list(lab_dir.glob('*.mutant')))} mutants")


if __name__ == "__main__":
    main()
