#!/usr/bin/env python3
"""Builds the lecture decks: slides/NN_name.md -> self-contained reveal.js HTML.

    python3 tools/slides/build.py --build-dir build --out build/slides [--labs 02,05]
                                  [--render-cmd CMD] [--pdf] [--reuse-renders]

For every deck slides/NN_name.md (all of them by default, or those of --labs):

  * reads labs/NN_name/demo.json, the presenter's steps of that lab;
  * checks the deck: a figure is written ![caption](step:K) (demo step K, 1-based), a line
    {{numbers:K}} stands for the measured numbers of step K (which must have "measure": true);
    any other image, or a step the lab does not have, stops the build with the deck and line;
  * renders every step the deck uses from the solution build, one process per step:
        build/labNN_solution --headless --size 1280x720 --demo-step K --screenshot P.png
                             --record P.json --quiet [--metrics]
    (--render-cmd, or $SLIDES_RENDER_CMD, replaces the program: a command line in which {lab},
    {name} and {build_dir} are substituted, followed by the same arguments);
  * replaces step:K with the rendered PNG and {{numbers:K}} with the step's measurement;
  * runs pandoc to one self-contained HTML file per deck (reveal.js from slides/node_modules, math
    as MathML, every image and font inlined) and checks that it refers to nothing on the network;
  * optionally prints each deck to PDF with chromium (--pdf; through check_decks.mjs --print-pdf);
  * writes index.html (every deck) and manifest.json (per deck: the slide count a browser must
    find, and per figure the PNG, its sha256 and its slide), which tools/slides/check_decks.mjs
    checks in a real browser.

Python 3 standard library only. Exit status: 0 built, 1 a deck or a render failed, 2 a tool is
missing or the command line is wrong.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
# (the decks read and checked; pandoc, fonts, MathML, PDF and the index; the demo steps' figures and numbers)
from decks import (DEFAULT_RENDERER, FIGURE_RE, MIN_PANDOC, RENDER_SIZE, ROOT, BuildError, Deck, SetupError,
                   find_decks, load_demo, rel, scan_deck, scannable_lines)
from html_out import (deck_structure, find_math_font, head_include, html_title, pandoc_ast, print_pdf, run_pandoc,
                      write_index)
from render import numbers_line, png_size, render_clips, render_steps, sha256, substituted_markdown

# ----------------------------------------------------------------------------------------------
# Tools


def need_pandoc() -> tuple:
    exe = shutil.which("pandoc")
    if not exe:
        raise SetupError("pandoc is not installed: apt-get install -y pandoc (Debian 12 has pandoc 2.17)")
    out = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout
    m = re.search(r"pandoc(?:\.exe)? (\d+)\.(\d+)", out)
    version = (int(m.group(1)), int(m.group(2))) if m else (0, 0)
    if version < MIN_PANDOC:
        raise SetupError(f"pandoc {out.split()[1] if out else '?'} is too old: its reveal.js template predates "
                         f"reveal.js 4; pandoc >= {MIN_PANDOC[0]}.{MIN_PANDOC[1]} is needed (Debian 12's 2.17 is fine)")
    return exe, out.splitlines()[0].split()[-1]


def need_reveal(reveal_dir: Path, slides_dir: Path) -> str:
    pinned = None
    try:
        pinned = json.loads((slides_dir / "package.json").read_text())["dependencies"]["reveal.js"]
    except (OSError, ValueError, KeyError):
        pass
    if not shutil.which("npm") and not (reveal_dir / "dist" / "reveal.js").is_file():
        raise SetupError("npm is not installed: apt-get install -y nodejs npm, then: npm ci --prefix slides")
    if not (reveal_dir / "dist" / "reveal.js").is_file():
        raise SetupError(f"reveal.js is not installed in {reveal_dir}: run npm ci --prefix slides")
    try:
        have = json.loads((reveal_dir / "package.json").read_text())["version"]
    except (OSError, ValueError, KeyError):
        have = "?"
    if pinned and have != pinned:
        raise SetupError(f"{reveal_dir} is reveal.js {have} but slides/package.json pins {pinned}: "
                         "run npm ci --prefix slides")
    return have


def need_pdf_tools() -> str:
    """--pdf prints with chromium through puppeteer-core (slides/node_modules): node, chromium and
    npm ci --prefix slides are needed."""
    node = shutil.which("node") or shutil.which("nodejs")
    if not node:
        raise SetupError("node is not installed (needed for --pdf): apt-get install -y nodejs npm")
    if not any(os.access(c, os.X_OK) for c in filter(None, (os.environ.get("CHROMIUM"), "/usr/lib/chromium/chromium",
                                                            shutil.which("chromium")))):
        raise SetupError("chromium is not installed (needed for --pdf): apt-get install -y chromium")
    if not (ROOT / "slides" / "node_modules" / "puppeteer-core").is_dir():
        raise SetupError("puppeteer-core is not installed (needed for --pdf): npm ci --prefix slides")
    return node



# ----------------------------------------------------------------------------------------------


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build-dir", default="build", help="the CMake build folder with labNN_solution (default: build)")
    ap.add_argument("--out", help="where the decks go (default: BUILD_DIR/slides)")
    ap.add_argument("--labs", help="only these labs, e.g. 02,05 (default: every deck)")
    ap.add_argument("--render-cmd", default=os.environ.get("SLIDES_RENDER_CMD"),
                    help="the renderer instead of BUILD_DIR/labNN_solution: a command line in which {lab}, "
                         "{name} and {build_dir} are replaced; the render options follow it "
                         "(default: $SLIDES_RENDER_CMD, else " + DEFAULT_RENDERER + ")")
    ap.add_argument("--slides-dir", default=str(ROOT / "slides"), help="the decks (default: slides/)")
    ap.add_argument("--labs-dir", default=str(ROOT / "labs"), help="the labs with demo.json (default: labs/)")
    ap.add_argument("--reveal-dir", help="reveal.js (default: slides/node_modules/reveal.js)")
    ap.add_argument("--theme", default="white", help="reveal.js theme (default: white)")
    ap.add_argument("--pdf", action="store_true",
                    help="also print every deck to PDF (BUILD_DIR/slides/NN_name.pdf) with chromium")
    ap.add_argument("--reuse-renders", action="store_true",
                    help="keep a step's earlier render when its command, step, lab settings and renderer "
                         "binary are unchanged (shader edits are not seen: do not use for a release)")
    ap.add_argument("--render-timeout", type=float, default=300, help="seconds per render (default: 300)")
    ap.add_argument("--check", action="store_true",
                    help="only check the decks against the labs' demo.json (no renders, no pandoc): the test suite's check")
    args = ap.parse_args(argv)

    build_dir = Path(args.build_dir).resolve()  # (pandoc runs in the output folder: every path absolute)
    out = (Path(args.out) if args.out else build_dir / "slides").resolve()
    slides_dir, labs_dir = Path(args.slides_dir), Path(args.labs_dir)
    reveal_dir = Path(args.reveal_dir) if args.reveal_dir else ROOT / "slides" / "node_modules" / "reveal.js"
    prefix = args.render_cmd or DEFAULT_RENDERER
    labs = None
    if args.labs:
        labs = [x.strip() for x in args.labs.split(",") if x.strip()]
        bad = [x for x in labs if not re.fullmatch(r"\d\d", x)]
        if bad:
            ap.error(f"--labs takes two-digit lab numbers, e.g. 02,05 (not {', '.join(bad)})")

    if args.check:
        problems, count = [], 0
        try:
            for src in find_decks(slides_dir, labs):
                deck = Deck(name=src.stem, lab=src.name[:2], source=src, demo=labs_dir / src.stem / "demo.json")
                load_demo(deck)
                problems += scan_deck(deck)
                count += 1
        except BuildError as e:
            problems.append(str(e))
        for p in problems:
            print(f"slides: {p}", file=sys.stderr)
        print(f"slides: {count} deck(s) checked against their demo steps: "
              f"{'OK' if not problems else str(len(problems)) + ' problem(s)'}")
        return 1 if problems or count == 0 else 0

    try:
        pandoc, pandoc_version = need_pandoc()
        reveal_version = need_reveal(reveal_dir.resolve(), ROOT / "slides")
        node = need_pdf_tools() if args.pdf else None
    except SetupError as e:
        print(f"slides: {e}", file=sys.stderr)
        return 2

    try:
        # 1. Read and check every deck before rendering anything.
        decks = []
        problems = []
        for src in find_decks(slides_dir, labs):
            deck = Deck(name=src.stem, lab=src.name[:2], source=src, demo=labs_dir / src.stem / "demo.json")
            load_demo(deck)
            problems += scan_deck(deck)
            decks.append(deck)
        if problems:
            raise BuildError("the decks have problems:\n" + "\n".join("  " + p for p in problems))

        out.mkdir(parents=True, exist_ok=True)
        srcdir = out / "src"
        srcdir.mkdir(exist_ok=True)
        math_font = find_math_font()

        entries = []
        for deck in decks:
            # 2. Render, 3. substitute, 4. pandoc.
            render_steps(deck, prefix, build_dir, out, args.render_timeout, args.reuse_renders)
            render_clips(deck, prefix, build_dir, out, args.render_timeout)
            md = srcdir / f"{deck.name}.md"
            md.write_text(substituted_markdown(deck), encoding="utf-8")
            ast = pandoc_ast(pandoc, md, out)
            structure = deck_structure(ast)
            expected_targets = {f"renders/{deck.name}/{r['png'].name}" for r in deck.renders.values()}
            for i, s in enumerate(structure["slides"]):
                for target in s["images"]:
                    if target not in expected_targets:
                        line = next((n for n, t in enumerate(deck.lines, 1) if target and target in t), "?")
                        if FIGURE_RE.match(target):
                            raise BuildError(f"{rel(deck.source)}:{line}: the figure ({target}) is not written on one "
                                             "line: write ![caption](step:K) on a single line")
                        raise BuildError(f"{rel(deck.source)}:{line}: image '{target}': a deck's only images are "
                                         "demo steps, written ![caption](step:K)")
            math = sum(s["math"] for s in structure["slides"])
            deck_font = math_font if math else None
            if math and not math_font:
                print(f"slides: warning: {rel(deck.source)} has math but no OpenType math font is installed: its "
                      "equations use the reader's fonts (apt-get install -y fonts-lmodern)")
            head = srcdir / f"{deck.name}.head.html"
            head.write_text(head_include(deck_font), encoding="utf-8")
            html_path = run_pandoc(pandoc, deck, md, out, reveal_dir.resolve(), head, args.theme)
            pdf = print_pdf(node, html_path, 180) if node else None
            if not pdf:
                html_path.with_suffix(".pdf").unlink(missing_ok=True)  # an earlier PDF would be stale

            figures = []
            fig_uses = [u for u in deck.uses if u.kind == "figure"]
            slide_of = []  # per image in document order, its slide index
            for i, s in enumerate(structure["slides"]):
                slide_of += [i] * len(s["images"])
            if len(slide_of) != len(fig_uses):
                raise BuildError(f"{rel(deck.source)}: found {len(fig_uses)} figures line by line but pandoc "
                                 f"reads {len(slide_of)} images (a figure inside a construct this script does not "
                                 "read?)")
            for u, slide in zip(fig_uses, slide_of):
                png = deck.renders[u.step]["png"]
                w, h = png_size(png)
                figures.append({"step": u.step, "line": u.line, "caption": u.caption, "slide": slide,
                                "png": png.relative_to(out).as_posix(), "sha256": sha256(png),
                                "width": w, "height": h,
                                "record": deck.renders[u.step]["json"].relative_to(out).as_posix()})
            numbers = [{"step": u.step, "line": u.line, "text": numbers_line(deck, u.step, u.line)}
                       for u in deck.uses if u.kind == "numbers"]
            entry = {"lab": deck.lab, "name": deck.name, "title": html_title(html_path, deck.name),
                     "source": rel(deck.source), "demo": rel(deck.demo), "html": html_path.name,
                     "pdf": pdf.name if pdf else None, "bytes": html_path.stat().st_size,
                     "expected_slides": len(structure["slides"]), "has_title_slide": structure["has_title"],
                     "math": math, "dollar_lines": sum(1 for _, t in scannable_lines(deck.lines) if "$" in t),
                     "math_font": deck_font[0] if deck_font else None,
                     "figure_slides": sorted({f["slide"] for f in figures}), "figures": figures, "numbers": numbers,
                     "clips": [{"step": u.step, "line": u.line, "caption": u.caption,
                                "webm": deck.clips[u.step].relative_to(out).as_posix(),
                                "bytes": deck.clips[u.step].stat().st_size} for u in deck.uses if u.kind == "clip"]}
            entries.append(entry)
            print(f"slides: {rel(html_path)}: {entry['expected_slides']} slides, {len(figures)} figures, "
                  f"{math} equations, {entry['bytes'] / 1e6:.1f} MB" + (f"; {rel(pdf)}" if pdf else ""))

        # A build of some labs (--labs) keeps the other decks an earlier build left in OUT.
        built = {e["name"] for e in entries}
        try:
            earlier = json.loads((out / "manifest.json").read_text(encoding="utf-8")).get("decks", [])
        except (OSError, ValueError):
            earlier = []
        kept = [e for e in earlier if isinstance(e, dict) and e.get("name") not in built
                and (out / str(e.get("html", ""))).is_file() and (slides_dir / f"{e.get('name')}.md").is_file()]
        if kept:
            print(f"slides: keeping the earlier build of {', '.join(e['name'] for e in kept)} in the index")
        entries = sorted(entries + kept, key=lambda e: e["name"])
        manifest = {"generator": "tools/slides/build.py", "pandoc": pandoc_version, "reveal.js": reveal_version,
                    "render_size": RENDER_SIZE, "renderer": prefix, "decks": entries}
        (out / "manifest.json").write_text(json.dumps(manifest, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
        write_index(out, entries)
        print(f"slides: built {len(built)} deck{'s' if len(built) != 1 else ''}; {rel(out)}/index.html lists "
              f"{len(entries)}; check them: node tools/slides/check_decks.mjs {rel(out / 'manifest.json')}")
        return 0
    except BuildError as e:
        print(f"slides: error: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())

