#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 05
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null 2>&1; echo "wrote $out/$name.png"; }
shot vsm_bench --set prefilter.kernel=5
shot vsm_reduction_split --set prefilter.kernel=5 --compare vsm.bleeding_reduction=0,0.3
"$student" --headless --size 640x360 --screenshot "$out/lab05_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab05_stubs.png"
# The experiments: measured three-plane bleeding against the formula, and VSM against box PCF.
"$solution" --headless --size 64x64 --set vsm.experiments=true 2>/dev/null | grep -v '^wrote' > "$out/experiments.md"
echo "wrote $out/experiments.md"
"$solution" --headless --size 480x270 --metrics --set prefilter.kernel=5 --sweep vsm.bleeding_reduction=0,0.1,0.2,0.3,0.5 \
  --sweep-csv "$out/bleeding_reduction.csv" 2>/dev/null | grep '^|' > "$out/bleeding_reduction.md"
echo "wrote $out/bleeding_reduction.md"
