#!/usr/bin/python3
"""./workbook showcase --table writes its page and CSVs under build/ and leaves the tracked
docs/showcase-table.md alone unless --publish asks; the page has every section, the frame's spread
and the comparison with seed 000's order. A stand-in showcase answers the sweeps with made-up rows
(the real one takes minutes; lecture_test.py runs its sweep).
usage: showcase_table_test.py SOURCE_DIR OUT_DIR"""
import hashlib
import os
import subprocess
import sys

root, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
fake = os.path.join(out, "fake_showcase")
with open(fake, "w") as f:
    f.write(r'''#!/usr/bin/python3
import itertools, json, sys
args = sys.argv[1:]
if "--record" in args:
    json.dump({"renderer": "a stand-in"}, open(args[args.index("--record") + 1], "w"))
    sys.exit(0)
sweeps = [args[i + 1].split("=") for i, a in enumerate(args) if a == "--sweep"]
keys = [k for k, _ in sweeps]
head = keys + ["acne_%", "leak_%", "shadow_light_%", "area_diff_%", "shadow_gpu_ms", "lighting_gpu_ms",
               "ray_tracing_cpu_gpu_ms", "frame_ms", "frame_ms_min", "frame_ms_max", "timed_frame_ms"]
with open(args[args.index("--sweep-csv") + 1], "w") as f:
    f.write(",".join(head) + "\n")
    for n, values in enumerate(itertools.product(*[v.split(",") for _, v in sweeps])):
        ms = 10.0 + n
        f.write(",".join(list(values) + ["0.1", "0.2", "0.3", "0.4", "1.0", "5.0", "-", str(ms), str(ms - 1),
                                         str(ms + 1), str(ms + 0.5)]) + "\n")
''')
os.chmod(fake, 0o755)
tracked = os.path.join(root, "docs/showcase-table.md")
before = hashlib.sha256(open(tracked, "rb").read()).hexdigest()
done = subprocess.run(["/usr/bin/python3", "-B", os.path.join(root, "tools/showcase/table.py"), "--exe", fake,
                       "--csv-dir", out], capture_output=True, text=True, cwd=root)
failed = []
if done.returncode != 0:
    failed.append("table.py failed: " + done.stderr[-1500:])
if hashlib.sha256(open(tracked, "rb").read()).hexdigest() != before:
    failed.append("docs/showcase-table.md changed without --publish")
page = open(os.path.join(out, "showcase-table.md")).read() if os.path.exists(os.path.join(out, "showcase-table.md")) else ""
for want in ("## Every technique", "frame ms (spread)", "(10.0-12.0)", "### Where the order differs from seed 000's",
             "seed 000 ESM, VSM, EVSM, PCF (180, 177, 97, 86 FPS)", "(of 10.5)", "interleaved rounds"):
    if want not in page:
        failed.append("the page lacks '%s'" % want)
for f in failed:
    print("FAIL: " + f)
print("showcase --table: %s" % ("every check passed" if not failed else "%d failed" % len(failed)))
sys.exit(1 if failed else 0)
