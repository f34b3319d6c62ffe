"""The bug gallery (tools/slides/build.py): a deck's ![caption](hunt:NN.Hk) is bug hunt NN.Hk's scene,
the bug as the student edition hands it out (build/labNN_bugs: the solution with the hunt's chunk
from labs/) on the left and the fix (build/labNN_solution) on the right, each measured against exact
visibility; {{numbers:NN.Hk}} gives both measurements. The scene is the hunt's "show" arguments in
the lab's exercises.json (the handout's "See it" command)."""
from __future__ import annotations

import json
import shlex
import shutil
import subprocess
from pathlib import Path

from decks import ROOT, BuildError, rel
HALF_SIZE = "640x720"  # each half of the 1280x720 figure
FONT = Path("/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf")  # fonts-dejavu-core


def _render(exe: Path, args: list, png: Path, rec: Path, timeout: float) -> str:
    cmd = [str(exe), "--headless", "--size", HALF_SIZE, *args, "--metrics", "--screenshot", str(png),
           "--record", str(rec), "--quiet"]
    shown = " ".join(shlex.quote(c) for c in cmd)
    if not exe.is_file():
        raise BuildError(f"{exe} does not exist: build it with cmake --build build --target bug_gallery_builds "
                         "(./workbook slides does)")
    try:
        proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        raise BuildError(f"the render took more than {timeout:g} s and was stopped\n  command: {shown}") from e
    if proc.returncode != 0 or not png.is_file() or not rec.is_file():
        raise BuildError(f"the render failed (exit status {proc.returncode})\n  command: {shown}\n"
                         f"  its stderr: {(proc.stderr or '').strip()[-1500:]}")
    return shown


def _side_by_side(bug: Path, fix: Path, out: Path, work: Path) -> None:
    """bug | fix as one PNG, each half labelled at its top left (ffmpeg's hstack and drawtext)."""
    ffmpeg = shutil.which("ffmpeg")
    if not ffmpeg:
        raise BuildError("the bug gallery needs ffmpeg (apt-get install -y ffmpeg)")
    labels = []
    for name, text in (("bug", "the bug, as handed out"), ("fix", "the fix")):
        f = work / f"{name}.label.txt"
        f.write_text(text, encoding="utf-8")  # (a file: no escaping of drawtext's own syntax)
        font = f"fontfile={FONT}:" if FONT.is_file() else ""
        labels.append(f"drawtext={font}textfile={f}:fontsize=40:fontcolor=white:box=1:boxcolor=black@0.6:"
                      "boxborderw=10:x=16:y=16")
    graph = f"[0:v]{labels[0]}[a];[1:v]{labels[1]}[b];[a][b]hstack=inputs=2"
    proc = subprocess.run([ffmpeg, "-v", "error", "-y", "-i", str(bug), "-i", str(fix), "-filter_complex", graph,
                           "-frames:v", "1", str(out)], capture_output=True, text=True)
    if proc.returncode != 0 or not out.is_file():
        raise BuildError(f"ffmpeg could not put {rel(bug)} beside {rel(fix)}: {proc.stderr.strip()[-800:]}")


def render_hunt(deck, hid: str, entry: dict, build_dir: Path, rdir: Path, timeout: float) -> dict:
    """Renders hunt `hid`'s bug and fix, puts them side by side; returns the deck's render entry."""
    stem = "hunt" + hid.replace(".", "_")
    halves, commands = {}, []
    for side, exe in (("bug", build_dir / f"lab{deck.lab}_bugs"), ("fix", build_dir / f"lab{deck.lab}_solution")):
        png, rec = rdir / f"{stem}.{side}.png", rdir / f"{stem}.{side}.json"
        for p in (png, rec):
            p.unlink(missing_ok=True)
        try:
            commands.append(_render(exe, entry["show"], png, rec, timeout))
        except BuildError as e:
            raise BuildError(f"lab {deck.lab} hunt {hid} ({side}): {e}") from e
        halves[side] = {"png": png, "record": json.loads(rec.read_text(encoding="utf-8"))}
    png, rec = rdir / f"{stem}.png", rdir / f"{stem}.json"
    _side_by_side(halves["bug"]["png"], halves["fix"]["png"], png, rdir)
    record = {"hunt": hid, "title": entry.get("title", ""), "show": entry["show"], "commands": commands,
              "bug": halves["bug"]["record"].get("measurement"), "fix": halves["fix"]["record"].get("measurement")}
    rec.write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    print(f"slides: lab {deck.lab} hunt {hid}: rendered the bug beside the fix")
    return {"png": png, "json": rec, "record": record, "command": " && ".join(commands)}


def hunt_numbers_line(deck, hid: str, line: int) -> str:
    """The bug's and the fix's acne and leak, as the deck's numbers line."""
    record = deck.renders[hid]["record"]
    parts = []
    for side, label in (("bug", "the bug"), ("fix", "the fix")):
        m = record.get(side)
        if not isinstance(m, dict) or not isinstance(m.get("leak_percent"), (int, float)):
            raise BuildError(f"{rel(deck.source)}:{line}: the {side} of hunt {hid} was not measured")
        parts.append(f"{label}: acne {m['acne_percent']:.2f}\u00a0%, leak {m['leak_percent']:.2f}\u00a0%")
    return "[" + " · ".join(parts) + "]{.numbers}"
