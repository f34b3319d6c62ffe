#!/usr/bin/env python3
"""The truth suite: every lab's reference solution held against exact visibility on generated scenes.

    truth.py BUILD [--table FILE.md] [--lab NN] [--technique NAME] [--mutant NN_name/MUTANT]

For each technique (tools/truth/techniques.json) and each generated scene of a light type it
supports (tools/truth/scenes.py, fixed seeds), the lab's solution renders the scene headlessly with
--metrics and writes its record; the measurements there are compared with the technique's bounds:

  area    the drawn shadow's area over the exact one (light-facing pixels drawn below 0.5 against
          those the rays find shadowed), within [1 - area, 1 + area]; "outline": by at most the pixels
          along the exact shadow's outline (derived: an exact technique flips only pixels whose centre
          lies within rounding of an edge, a map finer than a pixel moves an edge by less than one);
          "outline+texel": by at most that plus, on each of those pixels, one map texel's size in pixels
          there (derived: a map moves an edge by at most a texel, measure.cpp's outline_texel_pixels);
  wrong   acne + leak, as a share of the light-facing pixels farther than kRimPixels (2) from an
          edge of the exact shadow, at most this (percent);
  leak    the light leak over all shadowed pixels, at most this (percent);
  area_light  (lights with a size) the mean |visibility - area-light reference|, at most this (percent).

Then the truths derived from geometry alone, which the labs' own tests hold (tests named ...Truth, run on
each solution's test binary: lab 11's texels per pixel on a ground plane), listed under the table.

Every failing row is printed with the command that reproduces it. --mutant runs one of the mutants
of tests/mutants/ instead of the solution, on its lab's techniques only (a C++ mutant's own build, or
the solution with the mutant's shader folder searched first), and then passes only if some row
fails: that is how the tests prove the suite bites.
"""
import argparse
import concurrent.futures
import json
import os
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.dont_write_bytecode = True  # nothing written into the source tree
import scenes

SEEDS = 3  # scenes per light type
SIZE = "320x240"


def load_techniques():
    with open(HERE / "techniques.json") as f:
        return json.load(f)["techniques"]


def run_one(build, out, tech, light_type, seed, exe, overlay):
    """Renders one scene with one technique; returns the row (measurements and verdicts)."""
    scene = out / "scenes" / f"{light_type}_{seed}.json"
    record = out / "records" / f"{tech['name'].replace(' ', '_')}_{light_type}_{seed}.json"
    cmd = [str(exe), "--headless", "--scene", str(scene), "--size", SIZE, "--metrics", "--quiet",
           "--record", str(record)]
    for s in tech.get("settings", []):
        cmd += ["--set", s]
    env = dict(os.environ)
    if overlay:
        env["WB_SHADER_OVERLAY"] = str(overlay)
    row = {"technique": tech["name"], "lab": tech["lab"], "light": light_type, "seed": seed,
           "command": (f"WB_SHADER_OVERLAY={overlay} " if overlay else "") + " ".join(cmd), "failures": []}
    stderr = ""
    try:
        record.unlink(missing_ok=True)
        proc = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=120)
        stderr = proc.stderr.strip()[-300:]
        m = json.loads(record.read_text())["measurement"]
        row.update(area=m["shadow_area_ratio"], wrong=m["wrong_outside_rim_percent"], acne=m["acne_percent"],
                   leak=m["leak_percent"], area_light=m.get("area_mean_abs_percent"),
                   outline=m["outline_pixels"] / max(1, m["shadowed_pixels"]),
                   outline_texel=(m["outline_pixels"] + m["outline_texel_pixels"]) / max(1, m["shadowed_pixels"]))
    except Exception as e:  # a crash, a timeout, no record: a failure of this row, not of the suite
        row["failures"].append(f"no measurement ({type(e).__name__}: {e}) {stderr}".strip())
        return row
    b = tech.get("bounds_by_light", {}).get(light_type, tech["bounds"])
    # "outline": at most the exact outline's pixels may flip (ground_truth.hpp), whatever the rasterizer;
    # "outline+texel": and a texel's width beside each of them may too (texel_footprint.hpp)
    derived = {"outline": ("outline", " (the outline's pixels)"),
               "outline+texel": ("outline_texel", " (the outline's pixels and a map texel beside each)")}
    kind = derived.get(b.get("area"))
    area = row[kind[0]] if kind else b.get("area")
    row["allowed_area"] = area
    if area is not None and abs(row["area"] - 1) > area:
        row["failures"].append(f"shadow area {100 * row['area']:.2f}% of exact, allowed 100 ± {100 * area:.2f}%"
                               + (kind[1] if kind else ""))
    if "wrong" in b and row["wrong"] > b["wrong"]:
        row["failures"].append(f"acne + leak beyond the rim {row['wrong']:.3f}%, allowed {b['wrong']}%")
    if "leak" in b and row["leak"] > b["leak"]:
        row["failures"].append(f"light leak {row['leak']:.2f}%, allowed {b['leak']}%")
    if "area_light" in b and (row["area_light"] is None or row["area_light"] > b["area_light"]):
        row["failures"].append(f"|visibility - area light| {row['area_light']}%, allowed {b['area_light']}%")
    return row


def geometry_truths(build, labs):
    """The truths derived from geometry alone, which the labs' own tests hold (tests named ...Truth: lab 11's
    texels per pixel on a ground plane for the uniform map, logarithmic cascades and LiSPSM at n_opt,
    tests/11_warping): each solution's test binary runs them. Returns rows (lab, test, verdict)."""
    rows = []
    for nn in labs:
        exe = build / f"lab{nn}_solution_tests"
        if not exe.exists():
            continue
        listed = subprocess.run([str(exe), "--gtest_list_tests", "--gtest_filter=*Truth"], capture_output=True,
                                text=True, timeout=60).stdout
        suite = ""
        for line in listed.splitlines():
            if not line.startswith(" "):
                suite = line.strip()
                continue
            name = suite + line.strip()
            try:
                proc = subprocess.run([str(exe), "--gtest_filter=" + name], capture_output=True, text=True,
                                      timeout=300)
                verdict = "pass" if proc.returncode == 0 else "FAIL: " + " ".join(
                    ln.strip() for ln in proc.stdout.splitlines() if "WRONG" in ln or "ERROR" in ln)[:300]
            except subprocess.TimeoutExpired:
                verdict = "FAIL: no answer in 300 s"
            rows.append({"lab": nn, "test": name, "verdict": verdict, "command": f"{exe} --gtest_filter={name}"})
    return rows


def comparisons(rows, techniques):
    """`better_than`: a technique's mean error against the area light must be below another's, scene by
    scene (PCSS against PCF over the same footprint)."""
    failures = []
    by_key = {(r["technique"], r["light"], r["seed"]): r for r in rows}
    for tech in techniques:
        for other in tech.get("better_than", []):
            for r in rows:
                if r["technique"] != tech["name"]:
                    continue
                o = by_key.get((other, r["light"], r["seed"]))
                if o and r.get("area_light") is not None and o.get("area_light") is not None \
                        and r["area_light"] >= o["area_light"]:
                    failures.append(f"{tech['name']} on {r['light']} {r['seed']}: {r['area_light']:.2f}% from the "
                                    f"area light, not below {other}'s {o['area_light']:.2f}%")
    return failures


def table(rows, techniques):
    lines = ["| technique | light | scene | area (drawn / exact) | acne + leak beyond the rim | acne | leak "
             "| vs area light | verdict |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "area" not in r:
            lines.append(f"| {r['technique']} | {r['light']} | {r['seed']} | | | | | | {r['failures'][0]} |")
            continue
        al = "" if r["area_light"] is None else f"{r['area_light']:.2f}%"
        allowed = "" if r.get("allowed_area") is None else f" (100 ± {100 * r['allowed_area']:.1f}%)"
        lines.append(f"| {r['technique']} | {r['light']} | {r['seed']} | {100 * r['area']:.2f}%{allowed} | {r['wrong']:.3f}% "
                     f"| {r['acne']:.2f}% | {r['leak']:.2f}% | {al} | "
                     f"{'pass' if not r['failures'] else 'FAIL: ' + '; '.join(r['failures'])} |")
    bounds = ["| technique | lab | settings | lights | bounds | why |", "|---|---|---|---|---|---|"]
    for t in techniques:
        b = ", ".join(f"{k} {v}" for k, v in t["bounds"].items())
        if t.get("better_than"):
            b += "; closer to the area light than " + ", ".join(t["better_than"])
        bounds.append(f"| {t['name']} | {t['lab']} | {' '.join(t.get('settings', []))} | {', '.join(t['lights'])} "
                      f"| {b} | {t['why']} |")
    return "\n".join(bounds), "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build")
    ap.add_argument("--table", help="write the Markdown table here")
    ap.add_argument("--lab", help="only this lab's techniques (NN)")
    ap.add_argument("--technique", help="only this technique")
    ap.add_argument("--mutant", help="NN_name/MUTANT: run this mutant; pass only if the suite catches it")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    build = pathlib.Path(args.build).resolve()
    exes, overlays, tag = {}, {}, "solution"
    if args.mutant:
        lab_dir, name = args.mutant.split("/")
        nn, tag = lab_dir[:2], f"{lab_dir[:2]}_{name}"
        args.lab = nn
        exe = build / f"lab{nn}_mutant_{name}"
        if exe.exists():  # a C++ mistake is compiled in
            exes[nn] = exe
        else:  # a shader mistake: the solution, with the mutant's shaders found first
            overlays[nn] = build / "mutants" / lab_dir / name / "shaders"
            if not overlays[nn].is_dir():
                ap.error(f"no mutant {args.mutant}: neither {exe} nor {overlays[nn]} exists (build first)")
    out = build / "test-output" / "truth" / tag
    (out / "scenes").mkdir(parents=True, exist_ok=True)
    (out / "records").mkdir(parents=True, exist_ok=True)
    techniques = [t for t in load_techniques() if (not args.lab or t["lab"] == args.lab)
                  and (not args.technique or t["name"] == args.technique)]
    for light_type in ("directional", "spot", "point"):
        for seed in range(SEEDS):
            scenes.write(out / "scenes" / f"{light_type}_{seed}.json", light_type, seed)
    jobs = []
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for t in techniques:
            exe = exes.get(t["lab"], build / f"lab{t['lab']}_solution")
            for light_type in t["lights"]:
                for seed in range(SEEDS):
                    jobs.append(pool.submit(run_one, build, out, t, light_type, seed, exe, overlays.get(t["lab"])))
    rows = [j.result() for j in jobs]
    extra = comparisons(rows, techniques)
    bounds, body = table(rows, techniques)
    print(body)
    # (a mutant's own tests would judge it by its lab's tests, not by this suite: the solution's only)
    geometry = [] if args.mutant or args.technique else geometry_truths(
        build, sorted({t["lab"] for t in load_techniques()} if not args.lab else {args.lab}))
    geo = "\n".join(["| lab | test (the lab's solution tests) | verdict |", "|---|---|---|"] +
                     [f"| {g['lab']} | {g['test']} | {g['verdict']} |" for g in geometry])
    if geometry:
        print("\nTruths from the geometry alone (the labs' own tests):\n" + geo)
    for g in geometry:
        if g["verdict"] != "pass":
            extra.append(f"{g['test']}: {g['verdict']}\n  {g['command']}")
    failed = [r for r in rows if r["failures"]]
    for r in failed:
        print(f"\nFAIL {r['technique']} / {r['light']} scene {r['seed']}: {'; '.join(r['failures'])}\n  {r['command']}")
    for f in extra:
        print("FAIL", f)
    if args.table:
        pathlib.Path(args.table).write_text(
            "# The truth table\n\nMade by `./workbook truth --table` (tools/truth/truth.py) on the generated scenes "
            "of tools/truth/scenes.py, at " + SIZE + " with each technique's settings below; "
            "see [docs/truth.md](truth.md) for how each number is measured.\n\n## Bounds\n\n" + bounds +
            "\n\n## Measured\n\n" + body + "\n" +
            ("\n## Truths from the geometry alone\n\nThe labs' own tests named ...Truth, run on each solution "
             "(tests/11_warping: texels per pixel on a ground plane, derived in double for the uniform map, "
             "logarithmic cascades and LiSPSM at n_opt; every sampled ground pixel within the bound).\n\n" + geo + "\n"
             if geometry else ""))
        print("wrote", args.table)
    n_fail = len(failed) + len(extra)
    print(f"\n{len(rows) - len(failed)} of {len(rows)} rows within bounds" + (f", {len(extra)} comparisons failed"
                                                                            if extra else ""))
    if args.mutant:
        print(f"mutant {args.mutant}:", "caught" if n_fail else "NOT CAUGHT: it passes the truth suite")
        return 0 if n_fail else 1
    return 1 if n_fail else 0


if __name__ == "__main__":
    sys.exit(main())
