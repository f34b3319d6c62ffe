#!/usr/bin/env python3
"""Rendering a deck's demo steps from the solution build, and the Markdown they go into (tools/slides/build.py)."""
from __future__ import annotations

import hashlib
import html
import html.parser
import json
import os
import shlex
import shutil
import struct
import subprocess
import time
from pathlib import Path

from decks import (BENCH_FRAMES, CLIP_MAX_BYTES, CLIP_RE, CLIP_SIZE, DEFAULT_RENDERER, FIGURE_RE, HUNT_RE, IMAGE_RE,
                   NUMBERS_RE, RENDER_SIZE, ROOT, BuildError, Deck, rel, scannable_lines, tail)
from hunts import hunt_numbers_line, render_hunt


# The measured numbers a {{numbers:K}} line shows, in this order, when present and not null.
NUMBER_LABELS = [
    ("acne_percent", "acne", "%"),
    ("leak_percent", "leak", "%"),
    ("contact_gap_texels", "contact gap", "texels"),
    ("area_mean_abs_percent", "area-light error", "%"),
    ("pcf_diff_percent", "vs PCF", "%"),
]


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


def renderer(prefix: str, deck: Deck, build_dir: Path) -> list:
    """The renderer's command line before its options: the prefix with {lab}, {name} and {build_dir}."""
    return [w.replace("{lab}", deck.lab).replace("{name}", deck.name).replace("{build_dir}", str(build_dir))
            for w in shlex.split(prefix)]


def render_command(prefix: str, deck: Deck, build_dir: Path, step: int, png: Path, rec: Path, measure: bool) -> list:
    words = renderer(prefix, deck, build_dir) + ["--headless", "--size", RENDER_SIZE, "--demo-step", str(step),
                                                 "--screenshot", str(png), "--record", str(rec), "--quiet"]
    if measure:  # the numbers, and what the frame costs, from the same build and the same render
        words += ["--metrics"]
        if not deck.steps[step - 1].get("compare"):  # (a split frame's cost is neither half's: below)
            words += ["--bench", str(rec.with_suffix(".bench.csv")), "--frames", str(BENCH_FRAMES)]
    return words


def bench_halves(deck: Deck, prefix: str, build_dir: Path, k: int, rec: Path, timeout: float) -> None:
    """A measured split-screen step: each half's setting alone, timed (--bench) as a whole frame, from
    a copy of the demo whose step K has no split screen; writes stepKK.a.bench.csv and .b.bench.csv."""
    demo = json.loads(deck.demo.read_text(encoding="utf-8"))
    step = demo["steps"][k - 1]
    for side in ("a", "b"):
        alone = dict(step, settings=dict(step.get("settings", {}), **{step["compare"]["key"]: step["compare"][side]}))
        alone.pop("compare"), alone.pop("measure", None)
        path = rec.with_suffix(f".{side}.demo.json")
        path.write_text(json.dumps(dict(demo, steps=demo["steps"][: k - 1] + [alone] + demo["steps"][k:])), "utf-8")
        cmd = renderer(prefix, deck, build_dir) + [
            "--headless", "--size", RENDER_SIZE, "--demo", str(path), "--demo-step", str(k), "--quiet",
            "--bench", str(rec.with_suffix(f".{side}.bench.csv")), "--frames", str(BENCH_FRAMES)]
        proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout)
        if proc.returncode != 0:
            raise BuildError(f"lab {deck.lab} step {k}: timing the {side} half failed\n  command: "
                             f"{' '.join(shlex.quote(c) for c in cmd)}\n{tail(proc.stderr)}")


SIZE_TEXT = RENDER_SIZE.replace("x", "\u00d7")  # "1280×720"


def frame_ms(csv_path: Path):
    """The wall-clock ms per timed frame of a --bench CSV, or None."""
    import csv
    try:
        rows = list(csv.reader(open(csv_path, newline="")))
        return next(float(r[4]) for r in rows[1:] if len(r) > 4 and r[3] == "frame_wall")
    except (OSError, StopIteration, ValueError):
        return None


def frame_cost(rec: Path) -> str:
    """' · frame 23.4 ms' (a split screen: each half's setting timed alone), or ''."""
    whole = frame_ms(rec.with_suffix(".bench.csv"))
    if whole is not None:
        return f" · frame {format_number(whole)}\u00a0ms at {SIZE_TEXT}"
    a, b = frame_ms(rec.with_suffix(".a.bench.csv")), frame_ms(rec.with_suffix(".b.bench.csv"))
    if a is None or b is None:
        return ""
    return f" · a whole frame of each at {SIZE_TEXT}: left {format_number(a)}\u00a0ms, right {format_number(b)}\u00a0ms"


def render_steps(deck: Deck, prefix: str, build_dir: Path, out: Path, timeout: float, reuse: bool) -> None:
    rdir = out / "renders" / deck.name
    rdir.mkdir(parents=True, exist_ok=True)
    for hid in sorted({u.step for u in deck.uses if isinstance(u.step, str)}):  # the bug gallery's
        deck.renders[hid] = render_hunt(deck, hid, deck.hunts[hid], build_dir, rdir, timeout)
    wanted = sorted({u.step for u in deck.uses if u.kind != "clip" and isinstance(u.step, int)})
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
            for p in (png, rec, stamp_file, *rdir.glob(f"step{k:02d}.*bench.csv")):
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
            if measure and step.get("compare"):
                bench_halves(deck, prefix, build_dir, k, rec, timeout)
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


def render_clips(deck: Deck, prefix: str, build_dir: Path, out: Path, timeout: float) -> None:
    """Renders every clip:K of the deck into renders/NAME/clipKK.webm (the lab's --record-video)."""
    rdir = out / "renders" / deck.name
    rdir.mkdir(parents=True, exist_ok=True)
    for k in sorted({u.step for u in deck.uses if u.kind == "clip"}):
        clip = deck.steps[k - 1]["clip"]
        webm = rdir / f"clip{k:02d}.webm"
        cmd = renderer(prefix, deck, build_dir) + [
            "--headless", "--size", CLIP_SIZE, "--demo-step", str(k), "--quiet", "--record-video", str(webm),
            "--frames", str(int(clip.get("frames", 60))), "--animate", clip["animate"]]
        if clip.get("flips"):
            cmd.append("--show-flips")
        shown = " ".join(shlex.quote(c) for c in cmd)
        webm.unlink(missing_ok=True)
        print(f"slides: lab {deck.lab} step {k}: rendering its clip", flush=True)
        try:
            proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired as e:
            raise BuildError(f"lab {deck.lab} clip {k}: the render took more than {timeout:g} s\n  command: {shown}") from e
        if proc.returncode != 0 or not webm.is_file():
            raise BuildError(f"lab {deck.lab} clip {k} ({rel(deck.source)}): the render failed (exit status "
                             f"{proc.returncode})\n  command: {shown}\n{tail(proc.stderr or proc.stdout)}")
        if webm.stat().st_size > CLIP_MAX_BYTES:
            raise BuildError(f"lab {deck.lab} clip {k}: {rel(webm)} is {webm.stat().st_size / 1e6:.1f} MB, more than "
                             f"{CLIP_MAX_BYTES / 1e6:.0f} MB (fewer frames in its \"clip\", or a shorter path)")
        deck.clips[k] = webm


def format_number(value: float) -> str:
    v = abs(value)
    if v != 0 and v < 1:
        return f"{value:.2f}"
    if v < 100:
        return f"{value:.1f}"
    return f"{value:.0f}"


def numbers_line(deck: Deck, k, line: int) -> str:
    if isinstance(k, str):  # a bug hunt ("02.H1"): the bug's numbers and the fix's
        return hunt_numbers_line(deck, k, line)
    record = deck.renders[k]["record"]
    m = record.get("measurement") if isinstance(record, dict) else None
    where = f"{rel(deck.source)}:{line}: {{{{numbers:{k}}}}}"
    if not isinstance(m, dict):
        raise BuildError(f"{where}: the record of lab {deck.lab} step {k} ({rel(deck.renders[k]['json'])}) "
                         "has no \"measurement\" (was it rendered with --metrics?)\n"
                         f"  command: {deck.renders[k]['command']}")
    step = record.get("demo_step") or {}
    said = step.get("numbers", "") if isinstance(step, dict) else ""
    cost = frame_cost(deck.renders[k]["json"])
    if " | " in said:  # a split screen: the presenter's own line, which measures each half on its own
        halves = said.removeprefix("measured: ").split(" | ")
        return "[" + " · ".join(h.strip().replace("%", "\u00a0%") for h in halves) + cost + "]{.numbers}"
    if isinstance(m.get("own_measure"), str):  # a frame that holds the lab's own measure, not visibility
        return "[" + m["own_measure"] + cost + "]{.numbers}"
    parts = []
    for key, label, unit in NUMBER_LABELS:
        v = m.get(key)
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            parts.append(f"{label} {format_number(v)}\u00a0{unit}")
    if not parts:
        raise BuildError(f"{where}: the measurement of lab {deck.lab} step {k} has none of "
                         f"{', '.join(k_ for k_, _, _ in NUMBER_LABELS)}")
    return "[" + " · ".join(parts) + cost + "]{.numbers}"


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
            cm = CLIP_RE.match(m.group(2).strip("<>"))
            if cm:  # a clip: a video that plays by itself, in a loop, silent (inlined by pandoc)
                webm = deck.clips[int(cm.group(1))]
                spans.append((m.start(), m.end(), f'<figure class="clip"><video src="renders/{deck.name}/{webm.name}" '
                                                  f'autoplay loop muted playsinline title="{html.escape(m.group(1))}">'
                                                  f'</video><figcaption>{html.escape(m.group(1))}</figcaption></figure>'))
            hm = HUNT_RE.match(m.group(2).strip("<>"))
            if fm or hm:
                k = hm.group(1) if hm else int(fm.group(1))
                png = deck.renders[k]["png"]
                target = f"renders/{deck.name}/{png.name}"
                spans.append((m.start(2), m.end(2), target))
        for m in NUMBERS_RE.finditer(text):
            key = m.group(1)
            spans.append((m.start(), m.end(), numbers_line(deck, key if ".H" in key else int(key), no)))
        for a, b, new in sorted(spans, reverse=True):
            line = line[:a] + new + line[b:]
        lines[no - 1] = line
    return "\n".join(lines)


