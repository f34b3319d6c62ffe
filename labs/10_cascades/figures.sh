#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 10
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 960x540 --frames 10 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot field
shot field_cascades --set debug.cascades=true
shot near_shadows --set camera.bookmark=2
for s in uniform logarithmic practical; do shot "density_$s" --set csm.split=$s --set debug.density=true; done
"$student" --headless --size 640x360 --screenshot "$out/lab10_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab10_stubs.png"

# Shimmer and aliasing for every split scheme and both fits, from one command (480x270). Shimmer: the
# share of pixels that flip when path step k is drawn with step k-1's cascades, k = 1..5. Aliasing:
# shadow-map texels per screen pixel over the view (median, 5th and 95th percentiles, their ratio).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() { "$solution" --headless --size 480x270 "$@" --quiet; }
for s in uniform logarithmic practical; do
  for st in on off; do
    for k in 1 2 3 4 5; do
      run --set csm.split=$s --set csm.stable=$st --set path.step=$k --dump-visibility "$tmp/own_${s}_${st}_$k.pfm"
      run --set csm.split=$s --set csm.stable=$st --set path.step=$k --set path.matrices_step=$((k - 1)) \
        --dump-visibility "$tmp/prev_${s}_${st}_$k.pfm"
    done
  done
  run --set csm.split=$s --set debug.density=true --dump-visibility "$tmp/density_$s.pfm"
done
/usr/bin/python3 - "$tmp" "$out" <<'PY'
import struct, sys, pathlib
tmp, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
def pfm(p):
    with open(p, "rb") as f:
        f.readline(); w, h = map(int, f.readline().split()); scale = float(f.readline())
        return struct.unpack(("<" if scale < 0 else ">") + "%df" % (w * h), f.read(4 * w * h))
rows = ["| split | stabilised | pixels flipped per step, mean of 5 | most in one step |", "|---|---|---|---|"]
for s in ("uniform", "logarithmic", "practical"):
    for st in ("on", "off"):
        flips = []
        for k in range(1, 6):
            a, b = pfm(tmp / f"own_{s}_{st}_{k}.pfm"), pfm(tmp / f"prev_{s}_{st}_{k}.pfm")
            flips.append(100 * sum((x >= 0.5) != (y >= 0.5) for x, y in zip(a, b)) / len(a))
        rows.append(f"| {s} | {st} | {sum(flips) / 5:.4f} % | {max(flips):.4f} % |")
(out / "shimmer.md").write_text("\n".join(rows) + "\n")
rows = ["| split | median texels/pixel | 5th percentile | 95th percentile | p95 / p5 |", "|---|---|---|---|---|"]
for s in ("uniform", "logarithmic", "practical"):
    v = sorted(x for x in pfm(tmp / f"density_{s}.pfm") if x > 0 and x != 1.0 and x < 1e6)  # 1: the sky
    q = lambda p: v[min(len(v) - 1, int(p * len(v)))]
    rows.append(f"| {s} | {q(0.5):.3f} | {q(0.05):.3f} | {q(0.95):.3f} | {q(0.95) / q(0.05):.1f} |")
(out / "aliasing.md").write_text("\n".join(rows) + "\n")
PY
echo "wrote $out/shimmer.md $out/aliasing.md"

# Seed 000's CSM table, as ratios from one run: map size, blending, selection.
table cost --sweep shadow.map_size=512,1024,2048 --sweep csm.blend=0,0.1 --sweep csm.select=interval,map
