#!/usr/bin/env bash
# Renders the handout's images, tables and plot from the solution build: ./workbook figures 02
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR. Needs gnuplot (the workbook installs gnuplot-nox).
set -euo pipefail
solution=$1 student=$2 out=$3
scenes=$(cd "$(dirname "$0")/../../scenes" && pwd)
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 480x270 --metrics "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot acne_none --set bias.method=none
shot acne_constant --set bias.method=constant
shot peter_panning --scene "$scenes/bias_resting.json" --set bias.method=constant --set shadow.bias=0.04
shot receiver_plane --scene "$scenes/bias_resting.json" --set bias.method=receiver_plane --set pcf.kernel=5
shot thin_walls_front_faces --scene "$scenes/bias_thin_walls.json" --set bias.method=front_faces
"$solution" --headless --size 640x360 --scene "$scenes/bias_resting.json" --set bias.method=constant --set shadow.bias=0.04 \
  --heatmap "$out/heatmap_peter_panning.png" >/dev/null && echo "wrote $out/heatmap_peter_panning.png"
"$student" --headless --size 640x360 --screenshot "$out/lab02_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab02_stubs.png"

# The trade-off of a constant bias: acne on the grazing scene, contact gap on the resting one.
table constant_bias_grazing --sweep bias.method=constant --sweep shadow.bias=0,0.00125,0.0025,0.005,0.01,0.02,0.04
table constant_bias_resting --scene "$scenes/bias_resting.json" --sweep bias.method=constant \
  --sweep shadow.bias=0,0.00125,0.0025,0.005,0.01,0.02,0.04
# Every method at several sun elevations (acne), and on the resting scene with a 5x5 filter (gap).
table methods_by_elevation --sweep bias.method=none,constant,slope,polygon_offset,front_faces,normal_offset,receiver_plane \
  --sweep light.elevation=10,20,35,60
table methods_resting_5x5 --scene "$scenes/bias_resting.json" --set pcf.kernel=5 \
  --sweep bias.method=none,constant,slope,polygon_offset,front_faces,normal_offset,receiver_plane
table methods_thin_walls --scene "$scenes/bias_thin_walls.json" \
  --sweep bias.method=constant,slope,polygon_offset,front_faces,normal_offset,receiver_plane

gnuplot <<GNUPLOT
set terminal pngcairo size 720,400 font ",11" noenhanced
set output "$out/constant_bias_tradeoff.png"
set datafile separator ","
set key top center
set logscale x 2
set format x "%g"
set xtics (0.00125, 0.0025, 0.005, 0.01, 0.02, 0.04)
set xlabel "constant depth bias (shadow.bias, NDC depth units)"
set ylabel "acne rate on the grazing scene (%)"
set y2label "contact gap on the resting scene (texels)"
set ytics nomirror
set y2tics
set title "One constant bias cannot remove acne without detaching shadows"
plot "$out/constant_bias_grazing.csv" every ::2 using 2:3 with linespoints lw 2 title "acne rate (%)", \
     "$out/constant_bias_resting.csv" every ::2 using 2:5 axes x1y2 with linespoints lw 2 title "contact gap (texels)"
GNUPLOT
echo "wrote $out/constant_bias_tradeoff.png"
