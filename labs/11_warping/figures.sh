#!/usr/bin/env bash
# Renders the handout's images and its table from the solution build: ./workbook figures 11
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR.
set -euo pipefail
solution=$1 student=$2 out=$3
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }

shot field_lispsm
shot field_uniform --set warp.scheme=uniform
for v in density perspective projective; do shot "field_$v" --set warp.scheme=uniform --set warp.view=$v; done
shot field_density_lispsm --set warp.sdsm=on --set warp.view=density
shot orchard_toward_sun --scene scenes/warp_orchard.json --set light.orbit=180 --set warp.sdsm=on
"$student" --headless --size 640x360 --screenshot "$out/lab11_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab11_stubs.png"

# The table: texels per pixel over the ground (the worst pixel and the median) for every scheme, on
# the field and the orchard, with the sun behind the camera (light.orbit=0) and in front (180), at
# 960x540 with a 1024 map, printed by the lab's own --metrics line.
measure() {
  "$solution" --headless --size 960x540 --set warp.view=density --metrics "$@" 2>&1 |
    sed -n 's/.*worst \([0-9.e+-]*\), median \([0-9.e+-]*\),.*/\1 | \2/p'
}
{
  echo "| scene | sun | scheme | worst | median |"
  echo "|---|---|---|---:|---:|"
  for scene in field orchard; do
    file=scenes/csm_field.json
    [ "$scene" = orchard ] && file=scenes/warp_orchard.json
    for orbit in 0 180; do
      sun="behind the camera"
      [ "$orbit" = 180 ] && sun="in front"
      for row in "uniform:uniform:off" "CSM:csm:off" "CSM + SDSM:csm:on" "LiSPSM:lispsm:off" "LiSPSM + SDSM:lispsm:on" \
        "CSM + LiSPSM:csm_lispsm:off" "CSM + LiSPSM + SDSM:csm_lispsm:on"; do
        IFS=: read -r name scheme sdsm <<<"$row"
        echo "| $scene | $sun | $name | $(measure --scene "$file" --set light.orbit=$orbit --set warp.scheme="$scheme" --set warp.sdsm="$sdsm") |"
      done
    done
  done
} >"$out/table.md"
echo "wrote $out/table.md"

# The slider: LiSPSM + SDSM on the orchard toward the sun, from the uniform map to n_opt.
{
  echo "| warp.strength | worst | median |"
  echo "|---:|---:|---:|"
  for s in 0 0.05 0.1 0.25 0.5 1; do
    echo "| $s | $(measure --scene scenes/warp_orchard.json --set light.orbit=180 --set warp.sdsm=on --set warp.strength=$s) |"
  done
} >"$out/strength.md"
echo "wrote $out/strength.md"

# The practical splits' lambda with and without SDSM, on the field.
{
  echo "| csm.lambda | CSM worst | CSM median | CSM + SDSM worst | CSM + SDSM median |"
  echo "|---:|---:|---:|---:|---:|"
  for l in 0.5 0.75 0.9 1; do
    a=$(measure --set warp.scheme=csm --set csm.lambda=$l)
    b=$(measure --set warp.scheme=csm --set warp.sdsm=on --set csm.lambda=$l)
    echo "| $l | $a | $b |"
  done
} >"$out/lambda.md"
echo "wrote $out/lambda.md"

# The bias: a world bias (before the warp) against a depth bias (after it), uniform and LiSPSM + SDSM
# on the field, 480x270: the acne rate and the shadow area against exact visibility (--metrics).
bias() {
  "$solution" --headless --size 480x270 --set warp.sdsm=on --metrics "$@" 2>&1 | tr '\n' ' ' |
    sed -n 's/.*acne rate \([0-9.]*%\).*shadow area \([0-9.]*%\) of the exact.*/\1 | \2/p'
}
{
  echo "| bias | uniform: acne | uniform: shadow area | LiSPSM: acne | LiSPSM: shadow area |"
  echo "|---|---:|---:|---:|---:|"
  for b in 0.02 0.05 0.1; do
    echo "| $b m, world | $(bias --set warp.scheme=uniform --set warp.bias=$b) | $(bias --set warp.scheme=lispsm --set warp.bias=$b) |"
  done
  for b in 0.0005 0.001 0.002; do
    echo "| $b, depth | $(bias --set warp.scheme=uniform --set warp.bias_space=depth --set warp.depth_bias=$b) | $(bias --set warp.scheme=lispsm --set warp.bias_space=depth --set warp.depth_bias=$b) |"
  done
} >"$out/bias.md"
echo "wrote $out/bias.md"
