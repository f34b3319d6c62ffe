#!/usr/bin/env python3
"""The one judge path: who starts the runner and the judge, in check and in the grader, drawn from the
code. Every edge of the picture names the place in the code that makes that call (a file, the function
it is in, and the code itself, found by a pattern); the check fails when an edge's code is gone, and
when a product file starts wb_check, a runner or a judge at a place no edge names.

  judge_path.py [ROOT]               check; exit 1 naming each edge without code and each unnamed start
  judge_path.py --self-test          prove the check fails on an edge whose code is gone and on a start
                                     the picture does not show
  judge_path.py --svg F [ROOT]       draw it (docs/images/judge_path.svg)
  judge_path.py --check-svg F [ROOT] exit 1 when F is not what --svg would draw now
"""
import pathlib
import re
import shutil
import sys
import tempfile

import drawn_from_code

# The programs and entry points, by column (left to right) and row.
NODES = {
    "workbook": (0, 0, "./workbook check NN", "Linux, macOS: builds, then runs wb_check"),
    "cmake": (0, 1, "check_NN target", "cmake --build build --target check_NN (Windows too); the check cases"),
    "grader": (0, 2, "the grader", "grade.py, Gradescope's run_autograder, PrairieLearn's run_job: grader.py"),
    "check": (1, 0, "wb_check NN", "common/judge/check_main.cpp: one lab's whole check"),
    "runner_sup": (1, 1, "wb_check --runner", "supervisor.cpp: one exercise, its time limit and cap on output"),
    "judge_sup": (1, 2, "wb_check --judge", "supervisor.cpp: each judge test's limit; a stuck test left out"),
    "fill": (1, 3, "wb_check --fill-missing", "an earlier edition's file: the exercises it lacks, from the stubs"),
    "runner": (2, 1, "labNN_tests --runner", "the student's build: records on the tape, decides nothing"),
    "judge": (2, 2, "labNN_solution_tests --judge", "replays the tape, draws every scene, words the verdict"),
}

# (from, to, label, file, the function the call is in, a pattern of the code that makes it)
EDGES = [
    ("workbook", "check", "runs", "workbook", "check_lab", r'build/wb_check "\$1"'),
    ("workbook", "fill", "student edition", "tools/workbook/build.sh", "fill_from_stubs",
     r'build/wb_check --fill-missing'),
    ("cmake", "check", "runs", "cmake/Lab.cmake", "_wb_check_target", r"COMMAND wb_check \$\{nn\} --root"),
    ("cmake", "check", "runs", "cmake/Lab.cmake", "_wb_check_case", r"COMMAND wb_check \$\{nn\} --root"),
    ("cmake", "fill", "student edition", "cmake/FillFromStubs.cmake", "", r"COMMAND \$\{WB_CHECK\} --fill-missing"),
    ("check", "runner_sup", "each exercise", "common/judge/check_main.cpp", "checkLab",
     r"runExerciseRunner\(tests, id, tape, limits, shaders\)"),
    ("check", "judge_sup", "then", "common/judge/check_main.cpp", "checkLab",
     r"runJudge\(nn, judge, tape, submission, limits\)"),
    ("grader", "runner_sup", "in the sandbox", "tools/grading/grader.py", "run_tests",
     r'"wb_check"\), "--runner"'),
    ("grader", "judge_sup", "outside it", "tools/grading/grader.py", "judge_tape", r'"wb_check"\), "--judge"'),
    ("grader", "judge", "held-out plan", "tools/grading/heldout.py", "plan_requests", r'str\(judge\), f"--gtest_filter=\{gfilter\}", "--judge"'),
    ("grader", "fill", "", "tools/grading/submission.py", "fill_missing", r'str\(tool\), "--fill-missing"'),
    ("runner_sup", "runner", "", "common/judge/supervisor.cpp", "runExerciseRunner",
     r'spec\.argv = \{tests\.string\(\), "--runner"'),
    ("judge_sup", "judge", "", "common/judge/supervisor.cpp", "judgeOnce", r'spec\.argv = \{judge\.string\(\), "--judge"'),
]

# Where a product file starts wb_check, a runner or a judge: these files, and a line that passes one of
# these as a program or an argument (a quoted mode, or wb_check at the head of a command).
SCANNED = ("workbook", "tools/workbook/*.sh", "cmake/*.cmake", "tools/grading/*.py", "tools/grading/*/*",
           "common/judge/*.cpp", "common/platform/*.cpp")
QUOTED = re.compile(r'"--runner"|"--judge"|"--fill-missing"')
COMMAND = re.compile(r'^\s*(?:COMMAND\s+|execute_process\(COMMAND\s+)?(?:build/)?(?:wb_check|\$\{WB_CHECK\})\s')
# (a program reading its own command line, not starting one: wb_check's and the test binaries' modes)
DISPATCH = re.compile(r'== "--|strcmp\(|opt\.count\("--|opt\["--')


def enclosing(lines, index, suffix):
    """The function a line is in: the nearest def, shell function, CMake function or C++ definition above."""
    pattern = {".py": r"\s*def (\w+)", ".cmake": r"^function\((\w+)", ".cpp": r"^[\w:<>&*, ]+?[ *&](\w+)\([^;]*\{?$"}
    for line in reversed(lines[:index + 1]):
        m = re.match(pattern.get(suffix, r"^(\w+)\(\) \{"), line)
        if m:
            return m.group(1)
    return ""


def scanned_files(root):
    out = []
    for pattern in SCANNED:
        out += [p for p in sorted(root.glob(pattern)) if p.is_file() and p.suffix not in (".md", ".json")]
    return out


def problems(root):
    """One line per edge whose code is gone, and per start of wb_check, a runner or a judge no edge names."""
    found, covered = [], set()
    for a, b, _, rel, func, pattern in EDGES:
        path = root / rel
        lines = path.read_text(errors="replace").splitlines() if path.is_file() else []
        hits = [k for k, line in enumerate(lines) if re.search(pattern, line)
                and (not func or enclosing(lines, k, path.suffix) == func)]
        if not hits:
            found.append(f"{rel}: no call from {a} to {b} in {func or 'the file'} (/{pattern}/): the code moved? "
                         "update EDGES in tools/authoring/judge_path.py and redraw")
        covered |= {(rel, k) for k in hits}
    for path in scanned_files(root):
        rel = path.relative_to(root).as_posix()
        lines = path.read_text(errors="replace").splitlines()
        for k, line in enumerate(lines):
            code = line.split("#", 1)[0] if path.suffix in (".py", ".sh", ".cmake", "") else line.split("//", 1)[0]
            shell = path.suffix in (".sh", ".cmake", "")
            start = QUOTED.search(code) or (shell and COMMAND.search(code))
            if start and not DISPATCH.search(code) and (rel, k) not in covered:
                found.append(f"{rel}:{k + 1}: starts wb_check, a runner or a judge where the judge path's picture "
                             f"shows no call: {line.strip()[:90]}")
    return found


def check(root):
    found = problems(root)
    for p in found:
        print(p)
    print(f"judge path: {len(EDGES)} calls checked, {len(found)} problems")
    return 1 if found else 0


def self_test(root):
    """Copies the scanned files, removes one edge's code and adds an unnamed start; expects both found."""
    cases = {
        "an edge whose code is gone": ("common/judge/supervisor.cpp", lambda t: t.replace('"--runner"', '"--record"'),
                                       "no call from runner_sup"),
        "a start no edge names": ("tools/grading/batch.py", lambda t: t + '\nrun(["wb_check", "--judge", "01"])\n',
                                  "shows no call"),
    }
    ok = True
    for name, (rel, change, want) in cases.items():
        with tempfile.TemporaryDirectory() as tmp:
            copy = pathlib.Path(tmp)
            for path in scanned_files(root) + [root / e[3] for e in EDGES]:
                dest = copy / path.relative_to(root)
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(path, dest)
            (copy / rel).write_text(change((copy / rel).read_text()))
            hit = any(want in p for p in problems(copy))
            print(f"self-test: {name}: {'found' if hit else 'NOT FOUND'}")
            ok &= hit
    clean = problems(root)
    print(f"self-test: this tree: {len(clean)} problems")
    return 0 if ok and not clean else 1


def wrapped(text, width):
    lines, line = [], ""
    for w in text.split():
        if line and len(line) + len(w) + 1 > width:
            lines.append(line)
            line = w
        else:
            line = f"{line} {w}".strip()
    return lines + [line]


def calls():
    """The edges with one arrow per pair of programs: (from, to, label, [file:function, ...])."""
    out = {}
    for a, b, label, rel, func, _ in EDGES:
        place = f"{rel.split('/')[-1]}:{func}" if func else rel.split("/")[-1]
        if (a, b) in out:
            out[(a, b)][3].append(place)
        else:
            out[(a, b)] = (a, b, label, [place])
    return list(out.values())


def svg(root):
    """Three columns (entry points, wb_check's modes, the test binaries), an arrow per call with a
    number, and under them each number's label and the files and functions that make the call."""
    esc = lambda s: s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    col_x, col_w, top, row_h, box_h = (20, 440, 860), 280, 60, 100, 64
    edges = calls()
    legend_y = top + row_h * 4 + 10
    width, height = 1160, legend_y + 18 * len(edges) + 40
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="DejaVu Sans, sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           '<defs><marker id="a" markerWidth="8" markerHeight="8" refX="7" refY="4" orient="auto">'
           '<path d="M0,0 L8,4 L0,8 z" fill="#4a6fa5"/></marker></defs>',
           '<text x="20" y="24" font-weight="bold" font-size="15">The one judge path: check and the grader start '
           'the same supervisor, runner and judge</text>',
           f'<text x="{col_x[0]}" y="48" fill="#777">entry points</text>',
           f'<text x="{col_x[1]}" y="48" fill="#777">wb_check (common/judge/check_main.cpp)</text>',
           f'<text x="{col_x[2]}" y="48" fill="#777">the lab\'s test binaries (common/judge/main.cpp)</text>']
    box = {}
    for key, (col, row, title, text) in NODES.items():
        x, y = col_x[col], top + row * row_h
        box[key] = (x, y)
        fill = "#fdf3e7" if key == "grader" else "#eef3fa"
        out.append(f'<rect x="{x}" y="{y}" width="{col_w}" height="{box_h}" rx="6" fill="{fill}" stroke="#4a6fa5"/>')
        out.append(f'<text x="{x + 10}" y="{y + 20}" font-weight="bold" font-family="DejaVu Sans Mono, monospace">'
                   f'{esc(title)}</text>')
        for k, line in enumerate(wrapped(text, 44)):
            out.append(f'<text x="{x + 10}" y="{y + 38 + 13 * k}" fill="#444" font-size="11">{esc(line)}</text>')
    leaving = {k: [e for e in edges if e[0] == k] for k in NODES}
    arriving = {k: [e for e in edges if e[1] == k] for k in NODES}
    for n, e in enumerate(edges, 1):
        a, b = e[0], e[1]
        (ax, ay), (bx, by) = box[a], box[b]
        y1 = ay + box_h * (leaving[a].index(e) + 1) / (len(leaving[a]) + 1)
        y2 = by + box_h * (arriving[b].index(e) + 1) / (len(arriving[b]) + 1)
        if NODES[a][0] == NODES[b][0]:  # the same column: out and back on the right
            side = ax + col_w + 18 + 10 * leaving[a].index(e)
            points = [(ax + col_w, y1), (side, y1), (side, y2), (bx + col_w + 2, y2)]
        elif NODES[b][0] - NODES[a][0] == 2:  # past the middle column: below its boxes
            low = top + row_h * 4 - 20
            points = [(ax + col_w / 2, ay + box_h), (ax + col_w / 2, low), (bx + col_w / 2, low),
                      (bx + col_w / 2, by + box_h + 2)]
        else:  # each its own lane between the columns
            lanes = [f for f in edges if NODES[f[1]][0] - NODES[f[0]][0] == 1 and NODES[f[0]][0] == NODES[a][0]]
            mid = ax + col_w + 24 + (bx - ax - col_w - 48) * lanes.index(e) / max(len(lanes) - 1, 1)
            points = [(ax + col_w, y1), (mid, y1), (mid, y2), (bx - 2, y2)]
        path = " ".join(f"{x:.0f},{y:.0f}" for x, y in points)
        out.append(f'<polyline points="{path}" fill="none" stroke="#4a6fa5" stroke-width="1.5" marker-end="url(#a)"/>')
        lx, ly = (points[1][0] + points[2][0]) / 2, (points[1][1] + points[2][1]) / 2
        if points[1][0] == points[2][0]:  # (on the lane, a quarter of the way: clear of the other arrows)
            lx, ly = points[1][0], points[1][1] + (points[2][1] - points[1][1]) / 4
        out.append(f'<circle cx="{lx:.0f}" cy="{ly:.0f}" r="8" fill="white" stroke="#4a6fa5"/>')
        out.append(f'<text x="{lx:.0f}" y="{ly + 4:.0f}" text-anchor="middle" font-size="10" fill="#4a6fa5">{n}</text>')
        label = f"{NODES[a][2]} \u2192 {NODES[b][2]}" + (f" ({e[2]})" if e[2] else "")
        out.append(f'<text x="20" y="{legend_y + 18 * n}" font-size="11"><tspan fill="#4a6fa5" font-weight="bold">'
                   f'{n}</tspan>  {esc(label)}: <tspan font-family="DejaVu Sans Mono, monospace">'
                   f'{esc(", ".join(e[3]))}</tspan></text>')
    out.append(f'<text x="20" y="{height - 12}" fill="#777" font-size="11">Drawn from the code by '
               'tools/authoring/judge_path.py --svg: each call is found in the file and function it names; a start '
               'of wb_check, a runner or a judge anywhere else fails ctest.</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    return drawn_from_code.main(argv, "judge path", __doc__, check, self_test, svg)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
