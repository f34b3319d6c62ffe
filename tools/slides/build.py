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
import base64
import datetime
import glob
import hashlib
import html
import html.parser
import json
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RENDER_SIZE = "1280x720"
DEFAULT_RENDERER = "{build_dir}/lab{lab}_solution"
MIN_PANDOC = (2, 10)  # the first pandoc whose revealjs template is written for reveal.js 4

# The measured numbers a {{numbers:K}} line shows, in this order, when present and not null.
NUMBER_LABELS = [
    ("acne_percent", "acne", "%"),
    ("leak_percent", "leak", "%"),
    ("contact_gap_texels", "contact gap", "texels"),
    ("area_mean_abs_percent", "area-light error", "%"),
    ("pcf_diff_percent", "vs PCF", "%"),
]

FIGURE_RE = re.compile(r"^step:(\d+)$")
# ![caption](target "title"){attrs}: a caption may hold one level of brackets (links, spans).
IMAGE_RE = re.compile(r"!\[((?:[^\[\]\\]|\\.|\[[^\]]*\])*)\]\(\s*(<[^>]*>|[^)\s]*)((?:\s+\"[^\"]*\")?)\s*\)")
REF_IMAGE_RE = re.compile(r"!\[(?:[^\[\]\\]|\\.)*\]\[[^\]]*\]")
NUMBERS_RE = re.compile(r"\{\{\s*numbers\s*:\s*(\d+)\s*\}\}")
NUMBERS_LOOSE_RE = re.compile(r"\{\{\s*num[^}]*\}\}")
RAW_MEDIA_RE = re.compile(r"<\s*(img|picture|source|video|audio|iframe|embed|object|svg\s[^>]*\bhref)\b", re.I)
FENCE_RE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
INLINE_CODE_RE = re.compile(r"(`+)(?:(?!\1).)+?\1")

# Put into every deck's <head>: figure layout, and a script that sizes each slide's figures so the
# slide fits the slide height (reveal.js scales the slide as a whole; a slide's content that is
# taller than the slide is cut off). It marks <html data-figures-fitted="1"> when done.
HEAD_INCLUDE = r"""<style>
.reveal .slides section > ul, .reveal .slides section > ol { display: block; margin-left: 1.2em; }
.reveal figure { margin: 0.2em auto 0; text-align: center; }
.reveal .slides section > p:has(> .numbers:only-child) { margin: 0.15em 0; }
.reveal .slides section > figure + ul, .reveal .slides section > figure + p { margin-top: 0.3em; }
.reveal figure img { display: block; margin: 0 auto; max-width: 100%; max-height: 500px;
  width: auto; height: auto; object-fit: contain; }
.reveal figcaption { font-size: 0.5em; line-height: 1.3; margin-top: 0.3em; color: #444; }
.reveal .numbers { font-size: 0.55em; font-variant-numeric: tabular-nums; color: #1a5e8a; }
.reveal math[display="block"] { margin: 0.4em auto; }
.reveal mtd[columnalign="left"] { text-align: left; }
.reveal mtd[columnalign="right"] { text-align: right; }
</style>
<script>
(function () {
  "use strict";
  // Makes every slide's content fit the slide (reveal.js scales a slide as a whole, so content
  // taller or wider than the slide is cut off): a display equation wider than its line gets a
  // smaller font; then, starting from the slide's own text size and shrinking it in steps down to
  // 70 %, the figures get the largest height (at most 500 px, at least 280 px while the text may
  // still shrink) at which the slide fits. A slide whose text had to shrink is marked
  // data-fit-scale="0.85" (tools/slides/check_decks.mjs reports it). On screen this runs once
  // reveal.js is ready and the images are decoded, then lays out again; printing (?print-pdf)
  // runs it at "load", before reveal.js lays the slides out on pages (its "load" listener is
  // added after this one).
  var FIG_MAX = 500, FIG_MIN_WHILE_TEXT_SHRINKS = 280, FIG_MIN = 60;
  var BOTTOM = 52;  // px kept free under a figure slide's content, clear of reveal.js's controls
  var TEXT_SCALES = [1, 0.95, 0.9, 0.85, 0.8, 0.75, 0.7];
  function fitSlide(slide, width, height) {
    var imgs = Array.prototype.slice.call(slide.querySelectorAll("figure img, p > img"));
    var shown = [];
    for (var el = slide; el && el.tagName === "SECTION"; el = el.parentElement) {
      shown.push([el, el.style.display, el.hasAttribute("hidden")]);
      el.style.display = "block";
      el.removeAttribute("hidden");
    }
    var room = imgs.length ? height - BOTTOM : height;
    var fits = function () { return slide.scrollHeight <= room && slide.scrollWidth <= width; };
    var figures = function (h) { imgs.forEach(function (img) { img.style.maxHeight = h + "px"; }); };
    var largest = function (lo, hi) {  // the largest figure height in [lo, hi] that fits, or 0
      figures(hi);
      if (fits()) return hi;
      figures(lo);
      if (!fits()) return 0;
      while (hi - lo > 1) { var mid = (lo + hi) >> 1; figures(mid); if (fits()) lo = mid; else hi = mid; }
      figures(lo);
      return lo;
    };
    Array.prototype.slice.call(slide.querySelectorAll('math[display="block"]')).forEach(function (m) {
      var line = m.parentElement.getBoundingClientRect().width, w = m.getBoundingClientRect().width;
      if (w > line && line > 0) m.style.fontSize = Math.max(0.6, Math.floor(100 * line / w) / 100) + "em";
    });
    var done = false;
    for (var i = 0; i < TEXT_SCALES.length && !done; i++) {
      slide.style.fontSize = TEXT_SCALES[i] === 1 ? "" : TEXT_SCALES[i] + "em";
      if (TEXT_SCALES[i] !== 1) slide.setAttribute("data-fit-scale", String(TEXT_SCALES[i]));
      done = imgs.length ? largest(FIG_MIN_WHILE_TEXT_SHRINKS, FIG_MAX) > 0 : fits();
    }
    if (!done && imgs.length) largest(FIG_MIN, FIG_MAX);  // best effort; the check reports what is left
    shown.forEach(function (s) {
      s[0].style.display = s[1];
      if (s[2]) s[0].setAttribute("hidden", "");
    });
  }
  function fitAll(relayout) {
    var R = window.Reveal, width = R.getConfig().width, height = R.getConfig().height;
    var slides = Array.prototype.slice.call(document.querySelectorAll(".reveal .slides section"))
      .filter(function (s) { return !s.querySelector("section"); });
    slides.forEach(function (slide) { fitSlide(slide, width, height); });
    if (relayout) R.layout();
    document.documentElement.setAttribute("data-figures-fitted", "1");
  }
  if (/print-pdf/i.test(window.location.search)) {
    window.addEventListener("load", function () { if (window.Reveal) fitAll(false); });
    return;
  }
  function whenReady() {
    var imgs = Array.prototype.slice.call(document.querySelectorAll(".reveal img"));
    var decoded = imgs.map(function (img) { return img.decode ? img.decode().catch(function () {}) : null; });
    var fonts = document.fonts ? document.fonts.ready : null;
    Promise.all(decoded.concat([fonts])).then(function () { fitAll(true); });
  }
  document.addEventListener("DOMContentLoaded", function () {
    var R = window.Reveal;
    if (!R) return;
    if (R.isReady()) whenReady(); else R.on("ready", whenReady);
  });
})();
</script>
"""


class BuildError(Exception):
    """A deck, a lab or a render is wrong: the message says which and where."""


class SetupError(Exception):
    """A tool is missing: the message says what to install or run."""


@dataclass
class Use:
    kind: str  # "figure" or "numbers"
    step: int
    line: int  # 1-based line in the deck
    caption: str = ""


@dataclass
class Deck:
    name: str  # 02_bias
    lab: str  # 02
    source: Path
    demo: Path
    lines: list = field(default_factory=list)
    steps: list = field(default_factory=list)  # demo.json steps
    uses: list = field(default_factory=list)
    renders: dict = field(default_factory=dict)  # step -> {"png": Path, "json": Path, "record": dict}


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
# Reading the decks


def rel(path: Path) -> str:
    try:
        return str(Path(path).resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def find_decks(slides_dir: Path, labs: list | None) -> list:
    decks = sorted(Path(p) for p in glob.glob(str(slides_dir / "[0-9][0-9]_*.md")))
    if labs:
        by_lab = {}
        for d in decks:
            by_lab.setdefault(d.name[:2], []).append(d)
        missing = [lab for lab in labs if lab not in by_lab]
        if missing:
            raise BuildError(f"no deck for lab {', '.join(missing)} in {rel(slides_dir)} "
                             f"(decks are slides/NN_name.md; found: {', '.join(d.name for d in decks) or 'none'})")
        decks = [d for lab in labs for d in by_lab[lab]]
    if not decks:
        raise BuildError(f"no decks (slides/NN_name.md) in {rel(slides_dir)}")
    return decks


def load_demo(deck: Deck) -> None:
    if not deck.demo.is_file():
        raise BuildError(f"{rel(deck.source)}: the lab's presenter steps {rel(deck.demo)} do not exist")
    try:
        demo = json.loads(deck.demo.read_text(encoding="utf-8"))
    except ValueError as e:
        raise BuildError(f"{rel(deck.demo)}: not valid JSON: {e}") from e
    steps = demo.get("steps") if isinstance(demo, dict) else None
    if not isinstance(steps, list) or not all(isinstance(s, dict) for s in steps):
        raise BuildError(f"{rel(deck.demo)}: has no \"steps\" list of objects")
    deck.steps = steps


def scannable_lines(lines: list):
    """Yields (line number, text with inline code blanked) for lines outside the YAML title block
    and fenced code blocks."""
    in_yaml = bool(lines) and lines[0].rstrip() == "---"
    fence = None
    for i, line in enumerate(lines, 1):
        if in_yaml:
            if i > 1 and line.rstrip() in ("---", "..."):
                in_yaml = False
            continue
        m = FENCE_RE.match(line)
        if fence:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) and not line.strip().strip(fence[0]):
                fence = None
            continue
        if m:
            fence = m.group(1)
            continue
        yield i, INLINE_CODE_RE.sub(lambda mm: " " * len(mm.group(0)), line)


def scan_deck(deck: Deck) -> list:
    """Finds the figures and numbers of a deck; returns the problems found (deck:line: message)."""
    deck.lines = deck.source.read_text(encoding="utf-8").split("\n")
    problems = []
    where = rel(deck.source)
    nsteps = len(deck.steps)

    def check_step(k: int, line: int, what: str) -> bool:
        if 1 <= k <= nsteps:
            return True
        problems.append(f"{where}:{line}: {what} refers to demo step {k}, but {rel(deck.demo)} has "
                        f"{nsteps} step{'s' if nsteps != 1 else ''} (steps are numbered from 1)")
        return False

    for no, text in scannable_lines(deck.lines):
        for m in IMAGE_RE.finditer(text):
            target = m.group(2).strip("<>")
            fm = FIGURE_RE.match(target)
            if not fm:
                problems.append(f"{where}:{no}: image '{target}': a deck's only images are demo steps, "
                                f"written ![caption](step:K) (K = a step of {rel(deck.demo)})")
                continue
            k = int(fm.group(1))
            if check_step(k, no, f"figure ![...](step:{k})"):
                deck.uses.append(Use("figure", k, no, m.group(1)))
        for m in REF_IMAGE_RE.finditer(text):
            problems.append(f"{where}:{no}: reference-style image '{m.group(0)}': write figures as "
                            "![caption](step:K)")
        for m in RAW_MEDIA_RE.finditer(text):
            problems.append(f"{where}:{no}: raw HTML <{m.group(1).split()[0]}>: a deck's only images are demo "
                            "steps, written ![caption](step:K)")
        found = {m.start() for m in NUMBERS_RE.finditer(text)}
        for m in NUMBERS_LOOSE_RE.finditer(text):
            if m.start() not in found:
                problems.append(f"{where}:{no}: '{m.group(0)}' is not a placeholder this build knows: "
                                "write {{numbers:K}} (K = a step with \"measure\": true)")
        for m in NUMBERS_RE.finditer(text):
            k = int(m.group(1))
            if not check_step(k, no, f"{{{{numbers:{k}}}}}"):
                continue
            if deck.steps[k - 1].get("measure") is not True:
                problems.append(f"{where}:{no}: {{{{numbers:{k}}}}}: step {k} of {rel(deck.demo)} has no "
                                "\"measure\": true, so it has no numbers")
                continue
            deck.uses.append(Use("numbers", k, no))
    if not any(u.kind == "figure" for u in deck.uses) and not problems:
        print(f"slides: note: {where} has no figures")
    return problems


# ----------------------------------------------------------------------------------------------
# Rendering


def png_size(path: Path) -> tuple:
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def sha256(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def tail(text: str, lines: int = 25) -> str:
    text = (text or "").rstrip()
    return "\n".join("    " + ln for ln in text.splitlines()[-lines:]) if text else "    (nothing)"


def render_command(prefix: str, deck: Deck, build_dir: Path, step: int, png: Path, rec: Path, measure: bool) -> list:
    words = []
    for w in shlex.split(prefix):
        words.append(w.replace("{lab}", deck.lab).replace("{name}", deck.name).replace("{build_dir}", str(build_dir)))
    words += ["--headless", "--size", RENDER_SIZE, "--demo-step", str(step), "--screenshot", str(png),
              "--record", str(rec), "--quiet"]
    if measure:
        words.append("--metrics")
    return words


def render_steps(deck: Deck, prefix: str, build_dir: Path, out: Path, timeout: float, reuse: bool) -> None:
    rdir = out / "renders" / deck.name
    rdir.mkdir(parents=True, exist_ok=True)
    wanted = sorted({u.step for u in deck.uses})
    for k in wanted:
        step = deck.steps[k - 1]
        measure = step.get("measure") is True
        png, rec = rdir / f"step{k:02d}.png", rdir / f"step{k:02d}.json"
        cmd = render_command(prefix, deck, build_dir, k, png, rec, measure)
        shown = " ".join(shlex.quote(c) for c in cmd)
        exe = cmd[0] if os.sep in cmd[0] else shutil.which(cmd[0])
        if not exe or not os.path.isfile(exe):
            hint = ("build the labs first: ./workbook build" if prefix == DEFAULT_RENDERER
                    else "check --render-cmd / $SLIDES_RENDER_CMD")
            raise BuildError(f"lab {deck.lab} step {k}: the renderer {cmd[0]} does not exist ({hint})")
        # The stamp names everything the render depends on that this script can see; with
        # --reuse-renders an unchanged stamp skips the render (shaders read at run time are not in it).
        st = os.stat(exe)
        stamp = hashlib.sha256(json.dumps([cmd, step, json.loads(deck.demo.read_text()).get("settings"),
                                           st.st_mtime_ns, st.st_size]).encode()).hexdigest()
        stamp_file = rdir / f"step{k:02d}.stamp"
        if reuse and png.is_file() and rec.is_file() and stamp_file.is_file() and stamp_file.read_text() == stamp:
            print(f"slides: lab {deck.lab} step {k}: reusing {rel(png)}")
        else:
            for p in (png, rec, stamp_file):
                p.unlink(missing_ok=True)
            print(f"slides: lab {deck.lab} step {k}: rendering ({step.get('title', '')!s})", flush=True)
            t0 = time.monotonic()
            try:
                proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout)
            except subprocess.TimeoutExpired as e:
                err = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
                raise BuildError(f"lab {deck.lab} step {k} ({rel(deck.source)}): the render took more than "
                                 f"{timeout:g} s and was stopped\n  command: {shown}\n  its stderr (last lines):\n"
                                 f"{tail(err)}") from e
            except OSError as e:
                raise BuildError(f"lab {deck.lab} step {k}: could not run the renderer: {e}\n  command: {shown}") from e
            if proc.returncode != 0:
                raise BuildError(f"lab {deck.lab} step {k} ({rel(deck.source)}): the render failed with exit "
                                 f"status {proc.returncode}\n  command: {shown}\n  its stderr (last lines):\n"
                                 f"{tail(proc.stderr or proc.stdout)}")
            problem = None
            size = png_size(png) if png.is_file() else None
            if not png.is_file():
                problem = f"it wrote no screenshot {rel(png)}"
            elif not size:
                problem = f"its screenshot {rel(png)} is not a PNG"
            elif "x".join(map(str, size)) != RENDER_SIZE:
                problem = f"its screenshot is {size[0]}x{size[1]}, not the {RENDER_SIZE} asked for"
            elif not rec.is_file():
                problem = f"it wrote no record {rel(rec)}"
            if problem:
                raise BuildError(f"lab {deck.lab} step {k} ({rel(deck.source)}): the renderer exited 0 but "
                                 f"{problem}\n  command: {shown}\n  its stderr (last lines):\n{tail(proc.stderr)}")
            stamp_file.write_text(stamp)
            print(f"slides: lab {deck.lab} step {k}: rendered in {time.monotonic() - t0:.1f} s")
        try:
            record = json.loads(rec.read_text(encoding="utf-8"))
        except ValueError as e:
            raise BuildError(f"lab {deck.lab} step {k}: the record {rel(rec)} is not valid JSON: {e}\n"
                             f"  command: {shown}") from e
        if isinstance(record, dict) and record.get("status") not in (None, "ok"):
            print(f"slides: warning: lab {deck.lab} step {k}: the record says status "
                  f"{record.get('status')!r}: {record.get('warnings') or ''}")
        deck.renders[k] = {"png": png, "json": rec, "record": record, "command": shown}


def format_number(value: float) -> str:
    v = abs(value)
    if v != 0 and v < 1:
        return f"{value:.2f}"
    if v < 100:
        return f"{value:.1f}"
    return f"{value:.0f}"


def numbers_line(deck: Deck, k: int, line: int) -> str:
    record = deck.renders[k]["record"]
    m = record.get("measurement") if isinstance(record, dict) else None
    where = f"{rel(deck.source)}:{line}: {{{{numbers:{k}}}}}"
    if not isinstance(m, dict):
        raise BuildError(f"{where}: the record of lab {deck.lab} step {k} ({rel(deck.renders[k]['json'])}) "
                         "has no \"measurement\" (was it rendered with --metrics?)\n"
                         f"  command: {deck.renders[k]['command']}")
    step = record.get("demo_step") or {}
    said = step.get("numbers", "") if isinstance(step, dict) else ""
    if " | " in said:  # a split screen: the presenter's own line, which measures each half on its own
        halves = said.removeprefix("measured: ").split(" | ")
        return "[" + " · ".join(h.strip().replace("%", "\u00a0%") for h in halves) + "]{.numbers}"
    parts = []
    for key, label, unit in NUMBER_LABELS:
        v = m.get(key)
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            parts.append(f"{label} {format_number(v)}\u00a0{unit}")
    if not parts:
        raise BuildError(f"{where}: the measurement of lab {deck.lab} step {k} has none of "
                         f"{', '.join(k_ for k_, _, _ in NUMBER_LABELS)}")
    return "[" + " · ".join(parts) + "]{.numbers}"


def substituted_markdown(deck: Deck) -> str:
    lines = list(deck.lines)
    by_line = {}
    for no, text in scannable_lines(deck.lines):
        by_line[no] = text
    for no, text in by_line.items():
        line = lines[no - 1]
        # Replace from the right so earlier offsets stay valid; `text` has inline code blanked.
        spans = []
        for m in IMAGE_RE.finditer(text):
            fm = FIGURE_RE.match(m.group(2).strip("<>"))
            if fm:
                k = int(fm.group(1))
                png = deck.renders[k]["png"]
                target = f"renders/{deck.name}/{png.name}"
                spans.append((m.start(2), m.end(2), target))
        for m in NUMBERS_RE.finditer(text):
            spans.append((m.start(), m.end(), numbers_line(deck, int(m.group(1)), no)))
        for a, b, new in sorted(spans, reverse=True):
            line = line[:a] + new + line[b:]
        lines[no - 1] = line
    return "\n".join(lines)


# ----------------------------------------------------------------------------------------------
# pandoc, and what the browser test needs to know


def pandoc_ast(pandoc: str, md: Path, cwd: Path) -> dict:
    proc = subprocess.run([pandoc, "-f", "markdown", "-t", "json", str(md)], cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise BuildError(f"pandoc could not read {md}:\n{tail(proc.stderr)}")
    return json.loads(proc.stdout)


def walk(node, visit):
    if isinstance(node, dict):
        visit(node)
        for v in node.values():
            walk(v, visit)
    elif isinstance(node, list):
        for v in node:
            walk(v, visit)


def deck_structure(ast: dict) -> dict:
    """The slides pandoc makes with --slide-level=2: the title slide (when the deck has a title),
    one per level-1 or level-2 heading, one per horizontal rule; and, per slide, its images and
    math."""
    has_title = "title" in ast.get("meta", {})
    slides = []

    def counter(slide):
        def visit(n):
            if n.get("t") == "Image":
                slide["images"].append(n["c"][2][0])
            elif n.get("t") == "Math":
                slide["math"] += 1
        return visit

    if has_title:
        slides.append({"images": [], "math": 0})
        walk({k: v for k, v in ast["meta"].items() if k in ("title", "subtitle", "author", "date", "institute")},
             counter(slides[0]))
    started = False  # content before the first heading makes a slide of its own
    for block in ast["blocks"]:
        t = block.get("t")
        if (t == "Header" and block["c"][0] <= 2) or t == "HorizontalRule" or not started:
            slides.append({"images": [], "math": 0})
            started = True
        walk(block, counter(slides[-1]))
    return {"has_title": has_title, "slides": slides}


class ExternalRefs(html.parser.HTMLParser):
    """Collects every reference in an HTML file that a browser would fetch from the network."""

    FETCHING = {"script": ["src"], "link": ["href"], "img": ["src", "srcset"], "source": ["src", "srcset"],
                "video": ["src", "poster"], "audio": ["src"], "iframe": ["src"], "embed": ["src"],
                "object": ["data"], "track": ["src"], "input": ["src"], "image": ["href", "xlink:href"],
                "use": ["href", "xlink:href"]}
    URL_IN_CSS = re.compile(r"(?:url\(\s*['\"]?|@import\s+['\"])\s*((?:https?:)?//[^'\")\s]+)", re.I)

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.found = []
        self._in_style = False

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if name in self.FETCHING.get(tag, []) and re.match(r"\s*(https?:)?//", value, re.I):
                self.found.append(f"<{tag} {name}=\"{value[:100]}\">")
            if name == "style":
                self.found += [f"style url {u[:100]}" for u in self.URL_IN_CSS.findall(value)]
        self._in_style = tag == "style"

    def handle_endtag(self, tag):
        if tag == "style":
            self._in_style = False

    def handle_data(self, data):
        if self._in_style:
            self.found += [f"<style> {u[:100]}" for u in self.URL_IN_CSS.findall(data)]


FONT_FACE_RE = re.compile(r"@font-face\s*\{([^{}]*)\}")
SRC_DECL_RE = re.compile(r"src\s*:\s*(?:url\([^)]*\)\s*(?:format\([^)]*\))?\s*,?\s*)+;?")
WOFF_RE = re.compile(r"url\(\s*['\"]?(data:(?:application|font)/(?:font-)?woff2?;base64,[A-Za-z0-9+/=]+)['\"]?\s*\)")


def slim_fonts(text: str) -> str:
    """The theme's fonts come as EOT (twice), WOFF and TTF, and --self-contained inlines all four:
    2.5 MB of a deck. Every browser since 2012 reads WOFF, so a @font-face that has a WOFF keeps
    only that one."""
    def one(m):
        body = m.group(1)
        woff = WOFF_RE.search(body)
        if not woff:
            return m.group(0)
        rest = SRC_DECL_RE.sub("", body).strip()
        fmt = "woff2" if "woff2" in woff.group(1)[:40] else "woff"
        return "@font-face {\n" + rest + f"\nsrc: url({woff.group(1)}) format('{fmt}');\n}}"
    return FONT_FACE_RE.sub(one, text)


# OpenType math fonts from Debian packages, best first: MathML needs one (for stretchy braces, big
# operators, radicals), and a reader's machine may have none, so a deck with math carries its own.
MATH_FONTS = [
    ("Latin Modern Math", "/usr/share/texmf/fonts/opentype/public/lm-math/latinmodern-math.otf", "fonts-lmodern"),
    ("DejaVu Math TeX Gyre", "/usr/share/fonts/truetype/dejavu/DejaVuMathTeXGyre.ttf", "fonts-dejavu-extra"),
]


def find_math_font():
    for name, path, package in MATH_FONTS:
        if os.path.isfile(path):
            return name, Path(path)
    return None


def sfnt_to_woff(data: bytes) -> bytes:
    """WOFF 1.0 (W3C): the font's tables, each zlib-compressed where that is smaller."""
    flavor, num = struct.unpack(">IH", data[:6])
    tables = []
    for i in range(num):
        tag, checksum, offset, length = struct.unpack(">4sIII", data[12 + 16 * i:28 + 16 * i])
        raw = data[offset:offset + length]
        comp = zlib.compress(raw, 9)
        tables.append((tag, checksum, raw, comp if len(comp) < len(raw) else raw))
    tables.sort(key=lambda t: t[0])
    offset = 44 + 20 * num
    directory, body = b"", b""
    total_sfnt = 12 + 16 * num
    for tag, checksum, raw, stored in tables:
        directory += struct.pack(">4sIIII", tag, offset + len(body), len(stored), len(raw), checksum)
        body += stored + b"\0" * (-len(stored) % 4)
        total_sfnt += len(raw) + (-len(raw) % 4)
    length = offset + len(body)
    header = struct.pack(">4sIIHHIHHIIIII", b"wOFF", flavor, length, num, 0, total_sfnt, 1, 0, 0, 0, 0, 0, 0)
    return header + directory + body


def head_include(math_font) -> str:
    """The <head> additions of a deck: HEAD_INCLUDE, and with math, the math font inlined."""
    if not math_font:
        return HEAD_INCLUDE
    name, path = math_font
    woff = base64.b64encode(sfnt_to_woff(path.read_bytes())).decode("ascii")
    return (f"<style>\n@font-face {{ font-family: 'Slides Math'; src: url(data:font/woff;base64,{woff}) "
            f"format('woff'); }}\n/* {name}, from {path} */\n"
            ".reveal math { font-family: 'Slides Math', math; }\n</style>\n" + HEAD_INCLUDE)


MATH_RE = re.compile(r"<math\b.*?</math>", re.S)
MATH_TAG_RE = re.compile(r"<(/?)([a-z]+)\b[^>]*?(/?)>")
TALL_MATHML = {"mfrac", "mtable", "munder", "munderover", "msqrt", "mroot"}  # not mover: accents
STRETCHY_FENCE = re.compile(r'<mo stretchy="true" form="(prefix|postfix)">')


def unstretch_fences(text: str) -> str:
    """pandoc 2.17's texmath marks every bracket stretchy, \\left( or plain (, and Chromium sets a
    stretchy bracket apart from its content: d(x) reads "d ( x )". A bracket pair around nothing
    taller than a line (no fraction, matrix, root or underscript; an accent is not taller) is made
    not stretchy."""
    def one_math(m):
        src = m.group(0)
        edits = []  # (start, end) of "true" in a fence to make "false"
        stack = []  # per open <mrow>: [fences, tall]
        for t in MATH_TAG_RE.finditer(src):
            closing, name, selfclosing = t.group(1), t.group(2), t.group(3)
            if name == "mrow" and not closing and not selfclosing:
                stack.append([[], False])
            elif name == "mrow" and closing and stack:
                fences, tall = stack.pop()
                if len(fences) == 2 and not tall:
                    edits += fences
                if stack:
                    stack[-1][1] = stack[-1][1] or tall
            elif name == "mo" and not closing and stack:
                f = STRETCHY_FENCE.match(src, t.start())
                if f:
                    i = src.index('"true"', t.start()) + 1
                    stack[-1][0].append((i, i + 4))
            elif name in TALL_MATHML and not closing and stack:
                stack[-1][1] = True
        for a, b in sorted(edits, reverse=True):
            src = src[:a] + "false" + src[b:]
        return FUNCTION_NAME_RE.sub(function_name, src)
    return MATH_RE.sub(one_math, text)


# texmath writes \ln, \max, \operatorname{f} as <mo>ln</mo>, which Chromium spaces like an
# unknown operator, a thick space each side: "ln (x)". TeX puts a thin space before a function
# name, and after it unless a bracket or another name follows.
FUNCTION_NAME_RE = re.compile(r"<mo>([A-Za-z]{2,})</mo>(?=(<mrow>)?(<mo[^>]*>)?)")


def function_name(m) -> str:
    nxt = m.group(3) or ""
    tight = 'form="prefix"' in nxt or re.match(r"<mo>[A-Za-z(\[{|]", m.string[m.end():m.end() + 6] or "")
    return f'<mo lspace="0.1667em" rspace="{"0" if tight else "0.1667em"}">{m.group(1)}</mo>'


def run_pandoc(pandoc: str, deck: Deck, md: Path, out: Path, reveal_dir: Path, head: Path, theme: str) -> Path:
    html_path = out / f"{deck.name}.html"
    cmd = [pandoc, "-f", "markdown", "-t", "revealjs", "--self-contained", "--slide-level=2", "--mathml",
           "-V", f"revealjs-url={reveal_dir}", "-V", f"theme={theme}", "-V", "width=1280", "-V", "height=720",
           "-V", "margin=0.04", "-V", "center=false", "-V", "hash=true", "-V", "slideNumber='c/t'", "-V", "transition=fade",
           "-H", str(head), "-o", str(html_path), str(md)]
    proc = subprocess.run(cmd, cwd=out, capture_output=True, text=True)
    errors = [ln for ln in proc.stderr.splitlines() if "Could not fetch" in ln or "Could not convert TeX" in ln]
    if proc.returncode != 0 or errors:
        raise BuildError(f"{rel(deck.source)}: pandoc failed (exit status {proc.returncode})\n"
                         f"  command: {' '.join(shlex.quote(c) for c in cmd)}\n{tail(proc.stderr)}")
    for ln in proc.stderr.splitlines():
        print(f"slides: pandoc: {deck.name}: {ln}")
    text = slim_fonts(html_path.read_text(encoding="utf-8"))
    # pandoc writes figures as <img data-src=...> for reveal.js to load lazily, only within three
    # slides of the current one; inlined images gain nothing from that, and the figure fitting needs
    # every image loaded to measure it.
    text = text.replace('<img data-src="data:', '<img src="data:')
    text = unstretch_fences(text)
    # Slides are top-aligned (center=false: a heading stays put from slide to slide, and a figure
    # slide's content ends above the controls); the deck's and the sections' title slides are
    # centred.
    text = text.replace('<section id="title-slide"', '<section id="title-slide" class="center"', 1)
    text = re.sub(r'(<section id="[^"]*" class="title-slide slide level1)"', r'\1 center"', text)
    html_path.write_text(text, encoding="utf-8")
    parser = ExternalRefs()
    parser.feed(text)
    if parser.found:
        raise BuildError(f"{rel(html_path)} is not self-contained: it refers to the network:\n"
                         + "\n".join("    " + f for f in parser.found[:10]))
    return html_path


def print_pdf(node: str, html_path: Path, timeout: float) -> Path:
    """Prints a deck as reveal.js lays it out for printing (?print-pdf), one page per slide, with
    chromium driven by tools/slides/check_decks.mjs --print-pdf (it waits until the figures are
    fitted and the pages laid out, which chromium --print-to-pdf alone does not)."""
    pdf = html_path.with_suffix(".pdf")
    pdf.unlink(missing_ok=True)
    cmd = [node, str(ROOT / "tools" / "slides" / "check_decks.mjs"), "--print-pdf", str(html_path), str(pdf)]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        raise BuildError(f"printing {rel(html_path)} took more than {timeout:g} s") from e
    if proc.returncode != 0 or not pdf.is_file() or pdf.stat().st_size == 0:
        raise BuildError(f"could not print {rel(html_path)} to PDF (exit status {proc.returncode})\n"
                         f"  command: {' '.join(shlex.quote(c) for c in cmd)}\n{tail(proc.stderr or proc.stdout)}")
    for ln in proc.stdout.splitlines():
        print(f"slides: {ln}")
    return pdf


def html_title(html_path: Path, fallback: str) -> str:
    m = re.search(r"<title>(.*?)</title>", html_path.read_text(encoding="utf-8")[:20000], re.S)
    return html.unescape(m.group(1)).strip() if m and m.group(1).strip() else fallback


def write_index(out: Path, entries: list) -> None:
    rows = []
    for e in entries:
        pdf = f' · <a href="{html.escape(e["pdf"])}">PDF</a>' if e.get("pdf") else ""
        title = html.escape(e["title"])
        if not re.match(rf"lab\s*0?{int(e['lab'])}\b", e["title"], re.I):  # the title may name the lab already
            title = f'<span class="lab">Lab {e["lab"]}</span> {title}'
        rows.append(f'<li><a href="{html.escape(e["html"])}">{title}</a>{pdf} <span class="meta">{e["expected_slides"]} slides, '
                    f'{len(e["figures"])} figures</span></li>')
    stamp = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    (out / "index.html").write_text(f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Shadow Lab Workbook — lecture slides</title>
<style>
body {{ font-family: "Source Sans Pro", Helvetica, Arial, sans-serif; max-width: 46em; margin: 3em auto;
  padding: 0 1em; color: #222; }}
li {{ margin: 0.5em 0; }} a {{ color: #1a5e8a; }} .lab {{ font-weight: bold; }}
.meta {{ color: #777; font-size: 0.9em; }}
</style></head><body>
<h1>Shadow Lab Workbook — lecture slides</h1>
<p>One self-contained file per lab: it opens offline, and can be emailed as it is. Keys in a deck:
arrows to move, <kbd>F</kbd> full screen, <kbd>S</kbd> speaker notes, <kbd>Esc</kbd> overview.</p>
<ul>
{chr(10).join(rows)}
</ul>
<p class="meta">Built {stamp} by tools/slides/build.py; figures rendered by the reference solution.</p>
</body></html>
""", encoding="utf-8")


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
                     "figure_slides": sorted({f["slide"] for f in figures}), "figures": figures, "numbers": numbers}
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
