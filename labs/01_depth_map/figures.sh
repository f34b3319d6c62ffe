#!/usr/bin/env bash
# Renders the handout's images from the solution build: ./workbook figures 01
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local exe=$1 name=$2; shift 2; "$exe" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
shot "$solution" directional
shot "$solution" spot_debug_views --set light.index=1 --set debug.shadow_map=true --set debug.frustum=true
shot "$solution" view_from_light --set debug.view=light --set debug.shadow_map=true
shot "$solution" tree_alpha_tested --set camera.bookmark=2
shot "$solution" tree_solid_quads --set camera.bookmark=2 --set alpha.cutoff=0
shot "$solution" no_bias --set shadow.bias=0 --set camera.bookmark=3
shot "$student" lab01_stubs 2>/dev/null
