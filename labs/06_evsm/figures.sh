#!/usr/bin/env bash
# Renders the handout's images and tables from the solution build: ./workbook figures 06
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null 2>&1; echo "wrote $out/$name.png"; }
shot evsm_bench --set prefilter.kernel=5
shot evsm_channels_split --set prefilter.kernel=5 --compare evsm.channels=2,4
shot evsm_msm_split --set prefilter.kernel=5 --compare evsm.technique=evsm,msm
"$student" --headless --size 640x360 --screenshot "$out/lab06_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab06_stubs.png"
"$solution" --headless --size 480x270 --metrics --set prefilter.kernel=5 --sweep evsm.channels=2,4 \
  --sweep evsm.c_positive=5,10,20,40 --sweep-csv "$out/bleeding_by_exponent.csv" 2>/dev/null | grep '^|' > "$out/bleeding_by_exponent.md"
echo "wrote $out/bleeding_by_exponent.md"
"$solution" --headless --size 480x270 --metrics --set prefilter.kernel=5 --set evsm.technique=msm \
  --sweep msm.moment_bias=0.00001,0.00003,0.0001,0.0003,0.001 2>/dev/null | grep '^|' > "$out/msm_moment_bias.md"
echo "wrote $out/msm_moment_bias.md"
