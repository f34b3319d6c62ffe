#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 08
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 960x540 --frames 10 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot lantern
shot lantern_pcf --set cube.filter=pcf
shot table_corner --set camera.bookmark=2
shot table_corner_pcf --set camera.bookmark=2 --set cube.filter=pcf
shot floor --scene scenes/cube_floor.json
shot floor_bias --scene scenes/cube_floor.json --set shadow.bias=0.1
shot debug_cross --set debug.shadow_map=true
shot debug_frusta --set debug.frustum=true
shot light_face_minus_y --set debug.view=light --set debug.light_face=3
"$student" --headless --size 640x360 --screenshot "$out/lab08_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab08_stubs.png"

# Against exact visibility (a ray from every pixel to the lantern), seams included, at 960x540.
table filters --metrics --sweep cube.filter=hard,pcf --sweep cube.pcf_samples=16,32,64
# The three ways to fill the cube, timed with the cache off (every frame redraws all six faces),
# twice over in one run, so the noise shows.
table methods --frames 30 --set cube.cache=off \
  --sweep cube.method=six_passes,geometry,instanced,six_passes,geometry,instanced
table map_size --set cube.cache=off --sweep shadow.map_size=512,1024,2048
# The low bulb: a constant distance bias against grazing floors far away.
table floor_bias --scene scenes/cube_floor.json --metrics --sweep shadow.map_size=512,1024 --sweep shadow.bias=0.03,0.06,0.1,0.2
table floor_filters --scene scenes/cube_floor.json --metrics --sweep cube.filter=hard,pcf --sweep shadow.bias=0.03,0.1
