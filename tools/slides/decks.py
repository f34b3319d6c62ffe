#!/usr/bin/env python3
"""The decks: slides/NN_name.md read and checked against their lab's demo.json (tools/slides/build.py)."""
from __future__ import annotations

import glob
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RENDER_SIZE = "1280x720"
DEFAULT_RENDERER = "{build_dir}/lab{lab}_solution"
MIN_PANDOC = (2, 10)  # the first pandoc whose revealjs template is written for reveal.js 4
FIGURE_RE = re.compile(r"^step:(\d+)$")
# ![caption](clip:K): demo step K in motion, as its "clip" entry says (a setting animated over frames).
CLIP_RE = re.compile(r"^clip:(\d+)$")
CLIP_SIZE = "960x540"
CLIP_MAX_BYTES = 2_000_000
BENCH_FRAMES = 40  # a measured step's render times this many frames (--bench: 10 warm-up, 30 timed)
# ![caption](target "title"){attrs}: a caption may hold one level of brackets (links, spans).
IMAGE_RE = re.compile(r"!\[((?:[^\[\]\\]|\\.|\[[^\]]*\])*)\]\(\s*(<[^>]*>|[^)\s]*)((?:\s+\"[^\"]*\")?)\s*\)")
REF_IMAGE_RE = re.compile(r"!\[(?:[^\[\]\\]|\\.)*\]\[[^\]]*\]")
NUMBERS_RE = re.compile(r"\{\{\s*numbers\s*:\s*(\d+|\d\d\.H\d+)\s*\}\}")
# ![caption](hunt:NN.Hk): bug hunt NN.Hk's scene, the bug beside the fix (tools/slides/hunts.py).
HUNT_RE = re.compile(r"^hunt:(\d\d\.H\d+)$")
NUMBERS_LOOSE_RE = re.compile(r"\{\{\s*num[^}]*\}\}")
RAW_MEDIA_RE = re.compile(r"<\s*(img|picture|source|video|audio|iframe|embed|object|svg\s[^>]*\bhref)\b", re.I)
FENCE_RE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
INLINE_CODE_RE = re.compile(r"(`+)(?:(?!\1).)+?\1")

# Put into every deck's <head>: figure layout, and a script that sizes each slide's figures so the
# slide fits the slide height (reveal.js scales the slide as a whole; a slide's content that is
# taller than the slide is cut off). It marks <html data-figures-fitted="1"> when done.

class BuildError(Exception):
    """A deck, a lab or a render is wrong: the message says which and where."""


class SetupError(Exception):
    """A tool is missing: the message says what to install or run."""


@dataclass
class Use:
    kind: str  # "figure", "clip" or "numbers"
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
    clips: dict = field(default_factory=dict)  # step -> the rendered clip (a WebM file)
    hunts: dict = field(default_factory=dict)  # "02.H1" -> its exercises.json entry (with "show")



# ----------------------------------------------------------------------------------------------
# Reading the decks


def tail(text: str, lines: int = 25) -> str:
    """The last lines of a tool's output, indented, for an error message."""
    text = (text or "").rstrip()
    return "\n".join("    " + ln for ln in text.splitlines()[-lines:]) if text else "    (nothing)"


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


def find_hunt(deck: Deck, hid: str) -> bool:
    """Records bug hunt `hid` of the deck's lab (labs/NN_name/exercises.json) in deck.hunts; False when
    the lab has no such hunt, or it has no "show" arguments."""
    if hid in deck.hunts:
        return True
    try:
        manifest = json.loads((deck.demo.parent / "exercises.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    for e in manifest.get("exercises", []):
        if e.get("id") == hid and e.get("kind") == "hunt" and isinstance(e.get("show"), list):
            deck.hunts[hid] = e
            return True
    return False


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
            cm = CLIP_RE.match(target)
            if cm:
                k = int(cm.group(1))
                if not check_step(k, no, f"clip ![...](clip:{k})"):
                    continue
                clip = deck.steps[k - 1].get("clip")
                if not isinstance(clip, dict) or not isinstance(clip.get("animate"), str):
                    problems.append(f"{where}:{no}: clip:{k}: step {k} of {rel(deck.demo)} has no \"clip\": "
                                    "{\"animate\": \"key=from:to\", \"frames\": N, \"flips\": true|false}")
                    continue
                deck.uses.append(Use("clip", k, no, m.group(1)))
                continue
            hm = HUNT_RE.match(target)
            if hm:
                if find_hunt(deck, hm.group(1)):
                    deck.uses.append(Use("figure", hm.group(1), no, m.group(1)))
                else:
                    problems.append(f"{where}:{no}: hunt:{hm.group(1)}: {rel(deck.demo.parent)}/exercises.json has "
                                    "no such hunt with a \"show\" (the arguments that show its symptom)")
                continue
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
            if ".H" in m.group(1):  # a hunt's numbers: the bug's and the fix's
                if find_hunt(deck, m.group(1)):
                    deck.uses.append(Use("numbers", m.group(1), no))
                else:
                    problems.append(f"{where}:{no}: {{{{numbers:{m.group(1)}}}}}: no such hunt with a \"show\"")
                continue
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


