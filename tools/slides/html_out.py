#!/usr/bin/env python3
"""pandoc to self-contained reveal.js HTML: fonts, MathML, the check that nothing is fetched, PDF and the index (tools/slides/build.py)."""
from __future__ import annotations

import base64
import datetime
import html
import html.parser
import json
import os
import re
import shlex
import struct
import subprocess
import zlib
from pathlib import Path

from decks import ROOT, BuildError, Deck, rel, tail

HEAD_INCLUDE = r"""<style>
.reveal .slides section > ul, .reveal .slides section > ol { display: block; margin-left: 1.2em; }
.reveal figure { margin: 0.2em auto 0; text-align: center; }
.reveal .slides section > p:has(> .numbers:only-child) { margin: 0.15em 0; }
.reveal .slides section > figure + ul, .reveal .slides section > figure + p { margin-top: 0.3em; }
.reveal figure img { display: block; margin: 0 auto; max-width: 100%; max-height: 500px;
  width: auto; height: auto; object-fit: contain; }
.reveal figure.clip video { display: block; margin: 0 auto; max-width: 100%; max-height: 480px; }
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


