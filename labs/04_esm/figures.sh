#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 04
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null 2>&1; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot esm_c80 --set camera.bookmark=2 --set prefilter.kernel=5
shot esm_c10 --set camera.bookmark=2 --set esm.c=10 --set prefilter.kernel=5
shot esm_fp16 --set esm.format=fp16
shot esm_c_split --set camera.bookmark=3 --compare esm.c=10,80
"$student" --headless --size 640x360 --screenshot "$out/lab04_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab04_stubs.png"

# Leaking against the exponent, measured against exact visibility (480x270).
table leak_by_exponent --size 480x270 --metrics --set prefilter.kernel=5 --sweep esm.c=5,10,20,40,80
table leak_by_format --size 480x270 --metrics --set prefilter.kernel=5 --sweep esm.format=fp32,fp16
# Cost at 960x540: the prefilter grows with kernel width and map area, the lighting pass does not.
table cost_by_kernel --size 960x540 --frames 10 --sweep prefilter.kernel=1,3,5,7
table cost_by_map_size --size 960x540 --frames 10 --set prefilter.kernel=5 --sweep shadow.map_size=512,1024,2048
