#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 08
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 960x540 --frames 10 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot lantern
shot lantern_hard --set cube.filter=hard
shot table_corner --set camera.bookmark=2
shot table_corner_hard --set camera.bookmark=2 --set cube.filter=hard
"$student" --headless --size 640x360 --screenshot "$out/lab08_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab08_stubs.png"

# Against exact visibility (a ray from every pixel to the lantern), and the cost, at 960x540.
table filters --metrics --sweep cube.filter=hard,pcf --sweep cube.pcf_samples=16,32,64
table map_size --sweep shadow.map_size=512,1024,2048
