#!/usr/bin/env python3
"""The floors of common/: every #include "common/..." must point at the including file's own floor or
one below it (common/floors.txt lists them, bottom first). The labs stand above every floor: a lab's
files (labs/*/, solutions/*/) include the framework's floors and the lab's own files, nothing else
(not tests/ or tools/, not another lab's); its main.cpp includes common/shell/lab.hpp, and beside it
only headers it uses (one of the names a header declares appears in main.cpp).

  floors.py [ROOT]               check; exit 1 naming each include that runs up
  floors.py --self-test          prove the check fails on an include that runs up, a forwarding header
                                 used inside common/, and a file outside every floor
  floors.py --svg F [ROOT]       draw the floors and the includes between them (docs/images/floors.svg)
  floors.py --check-svg F [ROOT] exit 1 when F is not what --svg would draw now
"""
import pathlib
import re
import shutil
import sys
import tempfile

import drawn_from_code

INCLUDE = re.compile(r'^\s*#\s*include\s+"common/([^"]+)"', re.M)
SYSTEM = re.compile(r'^\s*#\s*include\s+<([^>]+)>', re.M)
# Libraries a floor must not reach (its README says why): base knows nothing of rendering, and only
# the truth floor casts rays.
# GoogleTest is the judge floor's alone: nothing a lab's app is built from may use it.
TESTING = ("gtest/", "gmock/")
FORBIDDEN = {
    "base": ("glad/", "GLFW/", "EGL/", "imgui", "embree") + TESTING,
    "platform": ("embree",) + TESTING,
    "scene": ("imgui", "embree") + TESTING,
    "shadows": ("imgui", "embree") + TESTING,
    "truth": TESTING,
    "exercise": TESTING,
    "shell": TESTING,
}
# The floor every lab's tests, check and the grader's judge are built on: a lab's app never includes it.
TESTS_ONLY = "judge"
SOURCES = (".hpp", ".cpp", ".h")


def read_floors(root):
    """[(name, description)] bottom first, from common/floors.txt."""
    floors = []
    for line in (root / "common" / "floors.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            name, _, text = line.partition(" ")
            floors.append((name, text.strip()))
    return floors


def includes(root):
    """Every (file, line, included path under common/) of the framework's sources."""
    out = []
    for f in sorted((root / "common").rglob("*")):
        if f.suffix in SOURCES and f.is_file():
            text = f.read_text(errors="replace")
            for m in INCLUDE.finditer(text):
                out.append((f.relative_to(root), text.count("\n", 0, m.start()) + 1, m.group(1)))
    return out


def floor_of(rel, levels):
    """The floor of a path under common/ ("base/error.hpp"), or None when it is in none."""
    parts = pathlib.PurePosixPath(rel).parts
    return parts[0] if len(parts) == 2 and parts[0] in levels else None


def problems(root):
    """One line per include that runs up a floor, or reaches outside the floors."""
    levels = {name: i for i, (name, _) in enumerate(read_floors(root))}
    found = []
    for f in sorted((root / "common").rglob("*")):
        rel = f.relative_to(root / "common").as_posix()
        if f.suffix in SOURCES and f.is_file() and floor_of(rel, levels) is None and "/" in rel:
            found.append(f"common/{rel}: a source file outside every floor (common/floors.txt lists them)")
    for f in sorted((root / "common").rglob("*")):
        mine = floor_of(f.relative_to(root / "common").as_posix(), levels)
        if f.suffix in SOURCES and f.is_file() and mine in FORBIDDEN:
            text = f.read_text(errors="replace")
            for m in SYSTEM.finditer(text):
                if m.group(1).startswith(FORBIDDEN[mine]):
                    line = text.count("\n", 0, m.start()) + 1
                    found.append(f"common/{f.relative_to(root / 'common').as_posix()}:{line}: includes <{m.group(1)}>, "
                                 f"which the {mine} floor must not use (common/{mine}/README.md)")
    for f, line, target in includes(root):
        mine = floor_of(f.relative_to("common").as_posix(), levels)
        if mine is None:
            continue  # a forwarding header at the top of common/ (README.md says why it is there)
        theirs = floor_of(target, levels)
        where = f"{f.as_posix()}:{line}"
        if theirs is None:
            found.append(f'{where}: includes "common/{target}", which is in no floor (include it from its floor)')
        elif levels[theirs] > levels[mine]:
            found.append(f'{where}: includes "common/{target}": {mine} may not include {theirs}, a floor above it')
    return found


DECLARED = re.compile(r"^(?:struct|class|enum(?: class)?|using)\s+(\w+)|^[\w:<>,*& ]+?[\s*&](\w+)\s*\(", re.M)


def declared_names(header):
    """The names a header declares at its outer level (types, aliases, functions): lines that start
    in column 0 (a namespace's contents are not indented in this code base)."""
    text = re.sub(r"//[^\n]*", "", header.read_text(errors="replace"))
    return {a or b for a, b in DECLARED.findall(text)} - {"namespace", "return", "operator"}


def lab_problems(root):
    """One line per include of a lab's files that reaches outside the framework and the lab, and per
    main.cpp that misses common/shell/lab.hpp or includes a header it does not use."""
    levels = {name: i for i, (name, _) in enumerate(read_floors(root))}
    found = []
    for folder in sorted([*(root / "labs").glob("[0-9][0-9]_*"), *(root / "solutions").glob("[0-9][0-9]_*")]):
        own = {p.name for d in (root / "labs" / folder.name, folder) if d.is_dir() for p in d.iterdir()}
        for f in sorted(p for p in folder.iterdir() if p.suffix in SOURCES and p.is_file()):
            text, rel = f.read_text(errors="replace"), f.relative_to(root).as_posix()
            for m in re.finditer(r'^\s*#\s*include\s+"([^"]+)"', text, re.M):
                target, line = m.group(1), text.count("\n", 0, m.start()) + 1
                framework = target.startswith("common/") and floor_of(target[7:], levels) is not None
                if framework and floor_of(target[7:], levels) == TESTS_ONLY:
                    found.append(f'{rel}:{line}: includes "{target}": common/{TESTS_ONLY}/ is its tests\' floor '
                                 "(check and the grader's judge), never part of a lab's app")
                elif not framework and target not in own:
                    found.append(f'{rel}:{line}: includes "{target}": a lab includes the framework\'s floors '
                                 "(common/<floor>/...) and its own files only")
                elif framework and f.name == "main.cpp" and target != "common/shell/lab.hpp" and \
                        (root / target).is_file():
                    names = declared_names(root / target)
                    if not any(re.search(rf"\b{re.escape(n)}\b", text) for n in names):
                        found.append(f'{rel}:{line}: includes "{target}" but uses nothing it declares')
            if f.name == "main.cpp" and '#include "common/shell/lab.hpp"' not in text:
                found.append(f"{rel}: a lab's main.cpp includes common/shell/lab.hpp (the lab API)")
    return found


def check(root):
    found = problems(root) + lab_problems(root)
    for p in found:
        print(p)
    n = len(includes(root))
    print(f"floors: {n} includes checked, {len(found)} running up or outside the floors")
    return 1 if found else 0


def self_test(root):
    """Copies common/ to a temporary tree, breaks it three ways, and expects each to be found."""
    ok = True
    cases = {
        "an include running up": ("base/strf.hpp", '#include "common/shell/lab.hpp"\n', "base may not include shell"),
        "a forwarder used inside a floor": ("scene/camera.hpp", '#include "common/error.hpp"\n', "in no floor"),
        "a file outside the floors": ("extra/stray.cpp", "int x;\n", "outside every floor"),
        "a library a floor must not use": ("base/strf.hpp", "#include <imgui.h>\n", "must not use"),
        "a lab reaching into tests/": ("../labs/01_depth_map/main.cpp", '#include "tests/framework/label.hpp"\n',
                                       "its own files only"),
        "a lab reaching into the judge": ("../labs/01_depth_map/main.cpp", '#include "common/judge/harness.hpp"\n',
                                          "its tests' floor"),
        "GoogleTest below the judge": ("shell/lab.hpp", "#include <gtest/gtest.h>\n", "must not use"),
        "a lab reaching into another": ("../labs/01_depth_map/main.cpp", '#include "../02_bias/exercise.hpp"\n',
                                        "its own files only"),
        "a lab including what it does not use": ("../labs/01_depth_map/main.cpp",
                                                 '#include "common/truth/soft_shadows.hpp"\n', "uses nothing"),
    }
    for name, (rel, text, want) in cases.items():
        with tempfile.TemporaryDirectory() as tmp:
            copy = pathlib.Path(tmp)
            shutil.copytree(root / "common", copy / "common")
            for top in ("labs", "solutions"):
                shutil.copytree(root / top, copy / top, ignore=shutil.ignore_patterns("images", "*.png", "*.pfm"))
            target = copy / "common" / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(text + (target.read_text() if target.exists() else ""))
            found = problems(copy) + lab_problems(copy)
            hit = any(want in p for p in found)
            print(f"self-test: {name}: {'found' if hit else 'NOT FOUND'} ({len(found)} problems)")
            ok &= hit
    clean = problems(root) + lab_problems(root)
    print(f"self-test: this tree: {len(clean)} problems")
    return 0 if ok and not clean else 1


def wrap(words, width):
    """`words` joined by two spaces into lines of at most `width` characters."""
    lines, line = [], ""
    for w in words:
        if line and len(line) + 2 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = f"{line}  {w}" if line else w
    return lines + ([line] if line else [])


def svg(root):
    """The floors as stacked bands (the bottom floor at the bottom) with their files, and, beside
    each, an arrow down with how many #include lines it makes of each floor below it."""
    floors = read_floors(root)
    levels = {name: i for i, (name, _) in enumerate(floors)}
    edges = {}
    for f, _, target in includes(root):
        a, b = floor_of(f.relative_to("common").as_posix(), levels), floor_of(target, levels)
        if a and b and a != b:
            edges[(a, b)] = edges.get((a, b), 0) + 1
    width, left, box, line_h, gap = 1000, 70, 900, 15, 12
    esc = lambda s: s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    bands = []  # (name, text, file lines, includes line), top floor first
    for name, text in reversed(floors):
        files = sorted({p.stem for p in (root / "common" / name).glob("*") if p.suffix in SOURCES})
        below = sorted(((b, n) for (a, b), n in edges.items() if a == name), key=lambda e: -levels[e[0]])
        note = "includes " + (", ".join(f"{b}/ {n}" for b, n in below) if below else "no other floor")
        bands.append((name, text, wrap(files, 128), note))
    height = 40 + sum(46 + line_h * len(b[2]) + gap for b in bands) + 10
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="DejaVu Sans, sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>',
           '<defs><marker id="a" markerWidth="8" markerHeight="8" refX="4" refY="4" orient="auto">'
           '<path d="M0,0 L8,4 L0,8 z" fill="#4a6fa5"/></marker></defs>']
    y = 16
    for i, (name, text, lines, note) in enumerate(bands):
        h = 46 + line_h * len(lines)
        out.append(f'<rect x="{left}" y="{y}" width="{box}" height="{h}" rx="6" fill="#eef3fa" stroke="#4a6fa5"/>')
        out.append(f'<text x="{left + 10}" y="{y + 19}" font-weight="bold" font-size="15">{name}/</text>')
        out.append(f'<text x="{left + 110}" y="{y + 19}" fill="#333">{esc(text)}</text>')
        for k, files in enumerate(lines):
            out.append(f'<text x="{left + 10}" y="{y + 37 + k * line_h}" fill="#444" '
                       f'font-family="DejaVu Sans Mono, monospace" font-size="11">{esc(files)}</text>')
        out.append(f'<text x="{left + 10}" y="{y + h - 8}" fill="#4a6fa5" font-size="11">{esc(note)}</text>')
        if i + 1 < len(bands):  # the arrow down to the next floor
            out.append(f'<line x1="{left - 30}" y1="{y + h / 2}" x2="{left - 30}" y2="{y + h + gap + 10}" '
                       f'stroke="#4a6fa5" stroke-width="2" marker-end="url(#a)"/>')
        y += h + gap
    out.append(f'<text x="{left}" y="{height - 8}" fill="#777" font-size="11">Drawn from the code by '
               f'tools/authoring/floors.py --svg (common/floors.txt): a floor includes only the floors below '
               f'it; the counts are #include lines.</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main(argv):
    return drawn_from_code.main(argv, "floors", __doc__, check, self_test, svg)


if __name__ == "__main__":
    sys.exit(main(sys.argv))
