#!/usr/bin/env python3
"""The lecture tools, end to end: presenter steps, present.* and the showcase.

usage: lecture_test.py BUILD_DIR OUT_DIR
  demo_steps   every step of every lab's demo.json (and the showcase's) renders headlessly with its
               settings, bookmark and split screen, and says so in its record; a step that does not
               exist is a clear usage error; two consecutive steps differ in more than 0.5 % of their
               pixels, unless the second says "same_picture" (why: only its numbers change)
  present      present.srgb and present.grid change the colour and never the visibility buffer
  hosted       the showcase draws a technique with the lab's own code: its visibility buffer is the
               lab's own, byte for byte, on the same scene with the same settings
  truth        in the showcase, shadow volumes match the ray-traced truth, and the ray-traced view
               itself has no acne and no leak against the exact visibility
  video        --record-video writes a clip of the frames asked for (ffprobe counts them), in each
               format; a bad file name or --animate is a usage error
Prints one line per check; exits 1 if any failed.
"""
import glob
import json
import os
import subprocess
import sys

BUILD, OUT = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "platforms", "windows"))
from compare_png import read_png  # (width, height, pixels as tuples)
SIZE = ["--size", "320x180"]
failures = []


def run(exe, args, expect=0):
    done = subprocess.run([os.path.join(BUILD, exe), "--headless"] + SIZE + args, capture_output=True, text=True,
                          timeout=300)
    if done.returncode != expect:
        raise AssertionError("%s %s exited %d (expected %d): %s" % (exe, " ".join(args), done.returncode, expect,
                                                                    (done.stderr or done.stdout)[-600:]))
    return done


def check(name, f):
    try:
        f()
        print("PASS " + name)
    except AssertionError as e:
        print("FAIL %s: %s" % (name, e))
        failures.append(name)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def pfm(path):
    """A one-channel PFM's floats."""
    import struct
    data = read(path)
    lines = data.split(b"\n", 3)
    w, h = map(int, lines[1].split())
    little = float(lines[2]) < 0
    return struct.unpack(("<" if little else ">") + "%df" % (w * h), lines[3][:4 * w * h])


def changed_share(a, b):
    """The share of pixels that differ by more than 2/255 in a channel."""
    return sum(1 for p, q in zip(a, b) if max(abs(x - y) for x, y in zip(p, q)) > 2) / max(1, len(b))


def demo_steps():
    labs = sorted(os.path.basename(os.path.dirname(d)) for d in glob.glob(os.path.join(ROOT, "labs/*/demo.json")))
    every = glob.glob(os.path.join(ROOT, "labs/*/exercises.json"))
    assert len(labs) == len(every), "every lab has a demo.json (found %d of %d)" % (len(labs), len(every))
    cases = [("lab%s_solution" % lab[:2], os.path.join(ROOT, "labs", lab, "demo.json")) for lab in labs]
    cases.append(("showcase", os.path.join(ROOT, "tools/showcase/demo.json")))
    for exe, path in cases:
        steps = json.load(open(path))["steps"]
        assert 3 <= len(steps) <= 10, "%s has %d steps" % (path, len(steps))
        previous = None
        for k in range(1, len(steps) + 1):
            record = os.path.join(OUT, "%s-step%d.json" % (exe, k))
            png = os.path.join(OUT, "%s-step%d.png" % (exe, k))
            run(exe, ["--demo-step", str(k), "--record", record, "--quiet", "--screenshot", png])
            pixels = read_png(png)[2]
            if previous is not None:
                share = changed_share(previous, pixels)
                same = steps[k - 1].get("same_picture")
                assert share > 0.005 or same, ("%s step %d (\"%s\") draws the picture of step %d (%.2f %% of the "
                                               "pixels differ): show something new, or say \"same_picture\": why"
                                               % (path, k, steps[k - 1]["title"], k - 1, 100 * share))
            previous = pixels
            got = json.load(open(record))["demo_step"]
            assert got["step"] == k and got["title"] == steps[k - 1]["title"], "%s step %d: record %s" % (exe, k, got)
            if steps[k - 1].get("measure"):
                assert got["numbers"].startswith("measured:"), "%s step %d measures: %s" % (exe, k, got)
    # The check above can fail: two steps that differ only in their words draw the same pixels.
    twice = os.path.join(OUT, "twice_demo.json")
    same = {"title": "t", "caption": "c", "settings": {"bias.method": "slope"}, "bookmark": 1}
    json.dump({"steps": [same, dict(same, title="t2", caption="other words")]}, open(twice, "w"))
    shots = []
    for k in (1, 2):
        shots.append(os.path.join(OUT, "twice%d.png" % k))
        run("lab02_solution", ["--demo", twice, "--demo-step", str(k), "--quiet", "--screenshot", shots[-1]])
    assert changed_share(read_png(shots[0])[2], read_png(shots[1])[2]) <= 0.005, "two identical steps differ"
    bad = run("lab02_solution", ["--demo-step", "99"], expect=2)
    assert "steps 1 to" in bad.stderr, bad.stderr
    # --demo FILE: an edited demo is tried without touching the lab's; a malformed one is named.
    mine = os.path.join(OUT, "my_demo.json")
    json.dump({"steps": [{"title": "mine", "caption": "c", "settings": {"bias.method": "slope"}, "bookmark": 1}]},
              open(mine, "w"))
    record = os.path.join(OUT, "my_demo_record.json")
    run("lab02_solution", ["--demo", mine, "--demo-step", "1", "--record", record, "--quiet"])
    assert json.load(open(record))["demo_step"]["title"] == "mine"
    json.dump({"steps": [{"title": "no caption"}]}, open(mine, "w"))
    bad = run("lab02_solution", ["--demo", mine, "--demo-step", "1"], expect=2)
    assert "step 1" in bad.stderr and "caption" in bad.stderr, bad.stderr


def present():
    base = ["--set", "present.srgb=false", "--set", "present.grid=false"]
    on = ["--set", "present.srgb=true", "--set", "present.grid=true"]
    for name, args in (("off", base), ("on", on)):
        run("lab03_solution", args + ["--quiet", "--screenshot", os.path.join(OUT, "present-%s.png" % name),
                                      "--dump-visibility", os.path.join(OUT, "present-%s.pfm" % name)])
    assert read(os.path.join(OUT, "present-off.pfm")) == read(os.path.join(OUT, "present-on.pfm")), \
        "present.* changed the visibility buffer"
    assert read(os.path.join(OUT, "present-off.png")) != read(os.path.join(OUT, "present-on.png")), \
        "present.* changed nothing on screen"
    # 4x MSAA resolves the visibility too: only edge pixels may change (by the mean of their samples).
    msaa = os.path.join(OUT, "present-msaa.pfm")
    run("lab03_solution", base + ["--quiet", "--frames", "3", "--set", "present.msaa=4", "--dump-visibility", msaa])
    off, on = pfm(os.path.join(OUT, "present-off.pfm")), pfm(msaa)
    changed = sum(1 for a, b in zip(off, on) if abs(a - b) > 0.01) / len(off)
    assert 0 < changed < 0.05, "4x MSAA changed %.1f %% of the visibility buffer" % (100 * changed)


def hosted():
    scene = os.path.join(ROOT, "scenes/showcase.json")
    # (technique, lab, the lab's settings that the showcase's row and its defaults set)
    rows = [("pcf", "03", ["pcf.method=grid", "pcf.kernel=3", "shadow.map_size=1024"]),
            ("vsm", "05", ["prefilter.kernel=3", "shadow.map_size=1024"]),
            ("pcss", "07", ["shadow.map_size=1024"]),
            ("cube_map", "08", ["cube.filter=pcf", "shadow.map_size=1024"]),
            ("volumes", "09", [])]
    for technique, nn, sets in rows:
        mine = os.path.join(OUT, "hosted-%s.pfm" % technique)
        theirs = os.path.join(OUT, "lab%s-%s.pfm" % (nn, technique))
        run("showcase", ["--quiet", "--set", "showcase.technique=" + technique, "--set", "camera.bookmark=2",
                         "--dump-visibility", mine])
        lab_args = ["--quiet", "--scene", scene, "--set", "camera.bookmark=2", "--dump-visibility", theirs]
        for s in sets:
            lab_args += ["--set", s]
        run("lab%s_solution" % nn, lab_args)
        assert read(mine) == read(theirs), "showcase %s differs from lab %s's own frame" % (technique, nn)


def truth():
    csv_path = os.path.join(OUT, "truth.csv")
    run("showcase", ["--quiet", "--metrics", "--sweep", "showcase.technique=volumes,ray_traced",
                     "--sweep-csv", csv_path])
    import csv
    rows = {r["showcase.technique"]: r for r in csv.DictReader(open(csv_path))}
    for t in ("volumes", "ray_traced"):
        acne, leak = float(rows[t]["acne_%"]), float(rows[t]["leak_%"])
        assert acne < 0.5 and leak < 0.5, "%s: acne %.2f %%, leak %.2f %% against the exact visibility" % (t, acne,
                                                                                                          leak)
    split = os.path.join(OUT, "split.png")
    run("showcase", ["--quiet", "--compare", "showcase.technique=pcss,ray_traced", "--screenshot", split])


def video():
    import shutil
    assert shutil.which("ffmpeg") and shutil.which("ffprobe"), "ffmpeg is not installed (sudo apt-get install ffmpeg)"
    for ext in ("webm", "mp4", "gif"):
        clip = os.path.join(OUT, "clip." + ext)
        if os.path.exists(clip):
            os.remove(clip)
        run("lab10_solution", ["--quiet", "--compare", "csm.stable=on,off", "--set", "path.step=30", "--animate",
                               "path.matrices_step=1:12", "--frames", "12", "--show-flips", "--record-video", clip])
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                "stream=nb_read_frames,width,height", "-of", "csv=p=0", clip],
                               capture_output=True, text=True)
        assert probe.stdout.strip().split(",") == ["320", "180", "12"], "%s: ffprobe says %r" % (clip, probe.stdout)
    bad = run("lab01_solution", ["--record-video", os.path.join(OUT, "clip.avi"), "--frames", "2"], expect=2)
    assert ".mp4, .webm or .gif" in bad.stderr, bad.stderr
    bad = run("lab01_solution", ["--record-video", os.path.join(OUT, "x.mp4"), "--animate", "camera.dolly=1"], expect=2)
    assert "key=from:to" in bad.stderr, bad.stderr


os.makedirs(OUT, exist_ok=True)
for name, f in (("demo_steps", demo_steps), ("present", present), ("hosted", hosted), ("truth", truth),
                ("video", video)):
    check(name, f)
sys.exit(1 if failures else 0)
