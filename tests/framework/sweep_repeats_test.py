#!/usr/bin/python3
"""The sweep's timing method (common/shell/bench.cpp) repeats itself: one setting measured twice in one run,
in interleaved rounds, gives two medians that agree within their spreads, and the passes of a row fit
inside the frame they were timed in.
usage: sweep_repeats_test.py LAB_EXE OUT_DIR"""
import csv
import os
import subprocess
import sys

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
path = os.path.join(out, "repeat.csv")
cmd = [exe, "--headless", "--quiet", "--size", "480x270", "--frames", "5", "--rounds", "5",
       "--sweep", "shadow.map_size=1024,1024", "--sweep-csv", path]
subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
rows = list(csv.DictReader(open(path)))
assert len(rows) == 2, rows
a, b = rows
print("\n".join("frame %s ms (%s-%s), passes in a %s ms frame" % (r["frame_ms"], r["frame_ms_min"], r["frame_ms_max"],
                                                                    r["timed_frame_ms"]) for r in rows))
failed = []
for x, y in ((a, b), (b, a)):
    if not float(y["frame_ms_min"]) <= float(x["frame_ms"]) <= float(y["frame_ms_max"]) and not (
            float(x["frame_ms_min"]) <= float(y["frame_ms"]) <= float(x["frame_ms_max"])):
        failed.append("the same setting twice: medians %s and %s ms, outside each other's spreads (%s-%s, %s-%s)" % (
            a["frame_ms"], b["frame_ms"], a["frame_ms_min"], a["frame_ms_max"], b["frame_ms_min"], b["frame_ms_max"]))
        break
for r in rows:
    passes = sum(float(v) for k, v in r.items() if k.endswith("_gpu_ms") and v not in ("", "-"))
    if passes > float(r["timed_frame_ms"]) * 1.02:
        failed.append("passes add up to %.2f ms, more than the %s ms frame they were timed in" % (passes,
                                                                                                 r["timed_frame_ms"]))
for f in failed:
    print("FAIL: " + f)
sys.exit(1 if failed else 0)
