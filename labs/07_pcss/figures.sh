#!/usr/bin/env bash
# Renders the handout's images, tables and plot from the solution build: ./workbook figures 07
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR. Needs gnuplot (the workbook installs gnuplot-nox).
set -euo pipefail
solution=$1 student=$2 out=$3
scenes=$(cd "$(dirname "$0")/../../scenes" && pwd)
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 480x270 --frames 5 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot plank
shot edge --set camera.bookmark=2
shot contact --set camera.bookmark=3
shot plank_pcf_16 --set pcss.method=pcf --set pcss.pcf_width=16
shot overlap --scene "$scenes/pcss_overlap.json" --set camera.bookmark=2
shot overlap_edge --scene "$scenes/pcss_overlap.json"
"$student" --headless --size 640x360 --screenshot "$out/lab07_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab07_stubs.png"

# Against the area light: PCSS and fixed-width PCF of every width, one run; then the overlap scene.
table against_pcf --metrics --sweep pcss.method=pcss,pcf --sweep pcss.pcf_width=4,8,16,32
table overlap --metrics --scene "$scenes/pcss_overlap.json" --sweep pcss.method=pcss,pcf --sweep pcss.pcf_width=16
# Cost at 960x540 (20 timed frames each): PCSS and fixed-width PCF against filter taps (16 search
# taps), then PCSS against search taps.
"$solution" --headless --size 960x540 --frames 20 --sweep pcss.method=pcss,pcf --sweep pcss.filter_samples=16,25,32,64 \
  2>/dev/null | grep '^|' >"$out/cost_filter.md"
"$solution" --headless --size 960x540 --frames 20 --sweep pcss.search_samples=16,25,32,64 2>/dev/null |
  grep '^|' >"$out/cost_search.md"
echo "wrote $out/cost_filter.md $out/cost_search.md"
# The area light's reference: its time at 480x270 for 16, 64 and 256 rays a pixel.
for n in 16 64 256; do
  "$solution" --headless --size 480x270 --metrics --set truth.light_samples=$n 2>/dev/null |
    sed -n "s/^against the area light (\([0-9]*\) rays a pixel, \([0-9]*\) ms, \([0-9.]*\) M rays\/s).*/| \1 | \2 | \3 |/p"
done | { echo "| rays a pixel | reference at 480x270 (ms) | million rays/s |"; echo "|---|---|---|"; cat; } >"$out/reference_time.md"
echo "wrote $out/reference_time.md"

# The penumbra, slab by slab (960x540), from the record: along the plank, and along the plate.
penumbra() {  # NAME [LAB OPTIONS]
  local name=$1; shift
  "$solution" --headless --size 960x540 --metrics --record "$out/$name.json" "$@" >/dev/null
  /usr/bin/python3 - "$out/$name.json" "$out/$name.csv" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["measurement"]["penumbra"]
with open(sys.argv[2], "w") as f:
    f.write("x,distance,theory,pcss,reference\n")
    for r in rows:
        f.write(f'{r["x"]:.2f},{r["distance"]:.3f},{r["theory"]:.3f},{r["width"]:.3f},{r["reference_width"]:.3f}\n')
PY
  rm "$out/$name.json"
  { echo "| x | receiver-blocker distance | theory | PCSS | area light |"; echo "|---|---|---|---|---|"
    tail -n +2 "$out/$name.csv" | sed 's/,/ | /g; s/^/| /; s/$/ |/'; } >"$out/$name.md"
  echo "wrote $out/$name.md"
}
penumbra penumbra
penumbra penumbra_overlap --scene "$scenes/pcss_overlap.json"
gnuplot <<GNUPLOT
set terminal pngcairo size 720,400 font ",11" noenhanced
set output "$out/penumbra.png"
set datafile separator ","
set key top left
set xlabel "receiver - blocker distance along the light's axis (m)"
set ylabel "10-90% penumbra width (m)"
set title "Contact hardening along the leaning plank: PCSS follows the parallel-planes theory"
plot "$out/penumbra.csv" every ::1 using 2:3 with lines lw 2 title "theory: 0.687 w_light (zR - zB) / zB", \
     "$out/penumbra.csv" every ::1 using 2:5 with points pt 7 ps 1.3 title "area light, ray-traced (64 rays)", \
     "$out/penumbra.csv" every ::1 using 2:4 with linespoints pt 5 lw 1 title "PCSS (16 + 16 taps)"
GNUPLOT
echo "wrote $out/penumbra.png"
