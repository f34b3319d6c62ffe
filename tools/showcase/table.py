#!/usr/bin/env python3
"""./workbook showcase --table: the whole workbook on one page.

Runs the showcase headlessly (no window) through its --sweep, which times every pass and the frame
in interleaved rounds (medians, with the frame's spread) and, with --metrics, measures each row
against exact (ray-cast) visibility, and writes one Markdown page and the CSVs beside it in
build/showcase-table/ (with --publish, the page also replaces docs/showcase-table.md, which the README
links: the tracked copy changes only when asked):
  1. every technique on the showcase scene: GPU ms per pass, frame ms, acne, leak, light in shadows,
     error against the area-light reference;
  2. seed 000's two tables: PCF, VSM, ESM, EVSM against the filter width, and against the map size;
  3. seed 004's table: shadow map, shadow volumes, ray tracing (one thread and every core).
Python 3 standard library only.
"""
import argparse
import csv
import datetime
import json
import os
import subprocess
import sys

TECHNIQUES = ["hard", "slope_bias", "pcf", "esm", "vsm", "evsm", "msm", "pcss", "cube_map", "volumes", "cascades",
              "lispsm", "sdsm", "ray_traced"]
FILTERED = ["pcf", "vsm", "esm", "evsm"]  # seed 000's columns, in its order
ROUNDS = 5
SIZE = "960x540"  # the showcase's own; tools/platforms/gpu_check.sh run --timings asks for 1920x1080 (--size)
# Seed 000's FPS by kernel (D3D11 on a GPU, 1920x1080, 1024² map; SYLLABUS.md, lab 05).
SEED000_FPS = {"1": {"pcf": 386, "vsm": 273, "esm": 277, "evsm": 199}, "3": {"pcf": 277, "vsm": 229, "esm": 232, "evsm": 124},
               "5": {"pcf": 141, "vsm": 192, "esm": 197, "evsm": 113}, "7": {"pcf": 86, "vsm": 177, "esm": 180, "evsm": 97}}


def sweep(exe, name, sweeps, frames, out_dir, metrics, size=SIZE):
    """One showcase --sweep; returns its rows as dicts (the CSV's header names)."""
    path = os.path.join(out_dir, name + ".csv")
    cmd = [exe, "--headless", "--quiet", "--size", size, "--frames", str(frames), "--rounds", str(ROUNDS),
           "--sweep-csv", path]
    for s in sweeps:
        cmd += ["--sweep", s]
    if metrics:
        cmd.append("--metrics")
    print("  " + " ".join(cmd), flush=True)
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=900)
    if done.returncode != 0:
        sys.exit("showcase --table: the sweep '%s' failed (exit %d):\n%s" % (name, done.returncode,
                                                                               done.stderr[-2000:]))
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def cell(row, key, fmt="%.2f"):
    v = row.get(key, "")
    try:
        return fmt % float(v)
    except ValueError:
        return v if v else "-"


def passes(row):
    """GPU ms per pass of one row, and the frame they were timed in: 'shadow 1.23, lighting 4.56 (of 7.1)'."""
    out = []
    for key, v in row.items():
        if key.endswith("_gpu_ms") and v not in ("", "-"):
            out.append("%s %.2f" % (key[: -len("_gpu_ms")], float(v)))
    return ", ".join(out) + " (of %s)" % cell(row, "timed_frame_ms", "%.1f")


def frame(row):
    """The frame's median over the rounds, and its spread: '20.9 (20.1-21.9)'."""
    return "%s (%s-%s)" % (cell(row, "frame_ms", "%.1f"), cell(row, "frame_ms_min", "%.1f"),
                           cell(row, "frame_ms_max", "%.1f"))


def main_table(rows):
    lines = ["| technique | GPU ms per pass (of the frame they were timed in) | frame ms (spread) | acne % | leak % | "
             "light in shadows % | off the area light % | texels per pixel (median) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["showcase.technique"], passes(r), frame(r), cell(r, "acne_%"), cell(r, "leak_%"),
            cell(r, "shadow_light_%"), cell(r, "area_diff_%"), cell(r, "texels_per_pixel", "%.3f")))
    return lines


def matrix(rows, row_key, row_label, label):
    """Seed 000's shape: one row per value of row_key, one column per technique: FPS and the ratio
    of frame time to the first row's."""
    values = []
    for r in rows:
        if r[row_key] not in values:
            values.append(r[row_key])
    ms = {(r["showcase.technique"], r[row_key]): float(r["frame_ms"]) for r in rows}
    head = "| %s | " % row_label + " | ".join("%s FPS (x time)" % t.upper() for t in FILTERED) + " |"
    lines = [head, "|---|" + "---|" * len(FILTERED)]
    for v in values:
        cells = []
        for t in FILTERED:
            first = ms[(t, values[0])]
            cells.append("%.0f (%.2f)" % (1000.0 / ms[(t, v)], ms[(t, v)] / first))
        lines.append("| %s | %s |" % (label(v), " | ".join(cells)))
    return lines


def order_against_seed000(kernels, size=SIZE):
    """Where the ranking differs from seed 000's, with the numbers of both, and why."""
    ms = {(r["showcase.technique"], r["showcase.kernel"]): float(r["frame_ms"]) for r in kernels}
    lines = []
    for k in ("3", "7"):
        here = sorted(FILTERED, key=lambda t: ms[(t, k)])
        there = sorted(FILTERED, key=lambda t: -SEED000_FPS[k][t])
        lines.append("- %sx%s: fastest first here %s (%s ms); seed 000 %s (%s FPS)." % (
            k, k, ", ".join(t.upper() for t in here), ", ".join("%.1f" % ms[(t, k)] for t in here),
            ", ".join(t.upper() for t in there), ", ".join(str(SEED000_FPS[k][t]) for t in there)))
    pcf7, vsm7 = ms[("pcf", "7")], ms[("vsm", "7")]
    if size != SIZE:  # (a GPU's run at seed 000's own size: the explanation below is llvmpipe's at 960x540)
        return lines + ["", "Measured here at %s, 7x7: PCF %.1f ms, VSM %.1f ms a frame (VSM/PCF %.2f; seed 000's "
                        "FPS give %.2f)." % (size, pcf7, vsm7, vsm7 / pcf7,
                                             SEED000_FPS["7"]["pcf"] / SEED000_FPS["7"]["vsm"])]
    lines += ["", "Seed 000 measured a GPU: at 7x7 PCF reads 49 texels per pixel of a 1920x1080 frame (about "
              "100 million reads), while VSM blurs its 1024² map in two passes of 7 taps (about 15 million) and then "
              "reads once per pixel, so VSM wins there (%.1fx PCF's FPS). Here the frame is 960x540: a quarter of the "
              "pixels, so a quarter of PCF's reads (about 25 million), while VSM's blur stays at 15 million taps "
              "and two full-map render passes, and llvmpipe runs every shader on two CPU cores, paying per "
              "instruction where a GPU pays mostly for memory traffic. Measured here at 7x7: PCF %.1f ms, VSM "
              "%.1f ms a frame (VSM/PCF %.2f). Compare rows of one run, as ratios." % (
                  SEED000_FPS["7"]["vsm"] / SEED000_FPS["7"]["pcf"], pcf7, vsm7, vsm7 / pcf7)]
    return lines


def seed004_table(sm_sv, rt):
    lines = ["| technique | frame ms | of which ray casting on the CPU, ms |", "|---|---|---|"]
    names = {"hard": "shadow map (SM)", "volumes": "shadow volumes (SV)"}
    for r in sm_sv:
        lines.append("| %s | %s | - |" % (names[r["showcase.technique"]], cell(r, "frame_ms")))
    for r in rt:
        threads = "1 thread" if r["ray_traced.threads"] == "1" else "every core"
        lines.append("| ray tracing (RT), %s | %s | %s |" % (threads, cell(r, "frame_ms"),
                                                             cell(r, "ray_tracing_cpu_gpu_ms")))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", default="build/showcase")
    ap.add_argument("--csv-dir", default="build/showcase-table", help="where the page and the CSVs go")
    ap.add_argument("--publish", action="store_true", help="also replace docs/showcase-table.md (tracked)")
    ap.add_argument("--frames", type=int, default=10, help="timed frames per row and round (%d rounds)" % ROUNDS)
    ap.add_argument("--size", default=SIZE, help="the frame's size, WxH (default %(default)s)")
    a = ap.parse_args()
    os.makedirs(a.csv_dir, exist_ok=True)
    print("showcase --table: sweeping (this takes a few minutes on a CPU)")
    everything = sweep(a.exe, "techniques", ["showcase.technique=" + ",".join(TECHNIQUES)], a.frames, a.csv_dir, True,
                       a.size)
    kernels = sweep(a.exe, "kernels", ["showcase.technique=" + ",".join(FILTERED), "showcase.kernel=1,3,5,7"],
                    a.frames, a.csv_dir, False, a.size)
    sizes = sweep(a.exe, "map_sizes", ["showcase.technique=" + ",".join(FILTERED), "showcase.map_size=512,1024,2048"],
                  a.frames, a.csv_dir, False, a.size)
    sm_sv = sweep(a.exe, "seed004", ["showcase.technique=hard,volumes"], a.frames, a.csv_dir, False, a.size)
    rt = sweep(a.exe, "ray_threads", ["showcase.technique=ray_traced", "ray_traced.threads=1,0"], a.frames, a.csv_dir,
               False, a.size)
    record = os.path.join(a.csv_dir, "frame.json")
    subprocess.run([a.exe, "--headless", "--size", a.size, "--record", record, "--quiet", "--screenshot",
                    os.path.join(a.csv_dir, "frame.png")], capture_output=True, text=True)
    try:
        with open(record) as f:
            where = json.load(f)["renderer"]
    except (OSError, ValueError, KeyError):
        where = "this machine"
    page = ["# The whole workbook on one page", "",
            "Generated by `./workbook showcase --table --publish` on %s (%s), %s. Every row is a lab's "
            "own solution on `scenes/showcase.json`, measured against exact ray-cast visibility. Timing: "
            "after a warm-up frame, %d timed frames a row in each of %d interleaved rounds (every row once, "
            "then again); a cell is the median over the rounds, the frame's spread is its fastest and slowest "
            "round, and the passes (GPU timer queries) were timed in frames of their own, whose time is given "
            "beside them. The measurements use frames of their own too. CSVs in build/showcase-table/."
            % (datetime.date.today().isoformat(), where, a.size, a.frames, ROUNDS), "",
            "## Every technique", "",
            "Defaults: 1024-texel maps, 3-texel filters (`showcase.kernel`, `showcase.map_size`). "
            "Acne and leak are against a point light at the spot light's centre (cube_map: the point "
            "light; cascades: the sun); *off the area light* is the mean difference from the spot "
            "light's disk (0.6 units), the truth for a light with a size. *Texels per pixel* is lab 11's "
            "measure, min(tx, ty), the texels of the map a step of one pixel right and up moves, through the "
            "map each pixel is drawn from, over the light-facing pixels a map holds (n/a: no map; cube_map: "
            "the first face that holds the pixel). *lispsm* is lab 11's LiSPSM, one map; *sdsm* is lab 11's "
            "cascades with logarithmic splits fitted to the frame's depth bounds (both: the sun, 30 m of shadow "
            "distance, as *cascades*, lab 10's).", ""]
    page += main_table(everything)
    page += ["", "## Seed 000's tables: filter width and map size", "",
             "Frames per second, and in brackets frame time relative to the first row of the column.", ""]
    page += matrix(kernels, "showcase.kernel", "filter", lambda v: "%sx%s" % (v, v))
    page += [""]
    page += matrix(sizes, "showcase.map_size", "map", lambda v: "%sx%s" % (v, v))
    page += ["", "### Where the order differs from seed 000's", ""] + order_against_seed000(kernels, a.size)
    page += ["", "## Seed 004's table: maps, volumes and ray tracing", ""]
    page += seed004_table(sm_sv, rt)
    page += [""]
    outs = [os.path.join(a.csv_dir, "showcase-table.md")] + (["docs/showcase-table.md"] if a.publish else [])
    for out in outs:
        with open(out, "w") as f:
            f.write("\n".join(page) + "\n")
    print("\n".join(page))
    print("wrote %s and %s/*.csv" % (" and ".join(os.path.abspath(o) for o in outs), os.path.abspath(a.csv_dir)))
    if not a.publish:
        print("(docs/showcase-table.md is unchanged: --publish replaces it)")


if __name__ == "__main__":
    main()
