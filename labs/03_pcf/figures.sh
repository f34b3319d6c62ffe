#!/usr/bin/env bash
# Renders the handout's images and benchmark tables from the solution build: ./workbook figures 03
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --set camera.bookmark=2 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
bench() { local name=$1; shift; "$solution" --headless --size 960x540 --frames 10 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot hard_1x1 --set pcf.method=grid --set pcf.kernel=1
shot grid_5x5 --set pcf.method=grid --set pcf.kernel=5
shot grid_5x5_spacing_3 --set pcf.method=grid --set pcf.kernel=5 --set pcf.spacing=3
shot gaussian_5x5 --set pcf.method=gaussian --set pcf.kernel=5 --set pcf.spacing=1.5
shot poisson_16 --set pcf.method=poisson --set pcf.poisson_count=16 --set pcf.poisson_radius=4
shot poisson_64 --set pcf.method=poisson --set pcf.poisson_count=64 --set pcf.poisson_radius=4
shot hardware_2x2 --set pcf.method=hardware
"$student" --headless --size 640x360 --set camera.bookmark=2 --screenshot "$out/lab03_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab03_stubs.png"

# GPU time per pass at 960x540 (10 timed frames each): cost against kernel width, and against map size.
bench cost_by_kernel --sweep pcf.method=grid,gaussian,gather --sweep pcf.kernel=1,3,5,7
bench cost_by_poisson_taps --sweep pcf.method=poisson --sweep pcf.poisson_count=16,32,64
bench cost_by_map_size --set pcf.kernel=3 --sweep pcf.method=grid,gather --sweep shadow.map_size=512,1024,2048
