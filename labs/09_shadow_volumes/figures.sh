#!/usr/bin/env bash
# Renders the handout's images, tables and plot from the solution build: ./workbook figures 09
# Arguments: SOLUTION_EXE STUDENT_EXE OUTPUT_DIR. Needs gnuplot (the workbook installs gnuplot-nox).
set -euo pipefail
solution=$1 student=$2 out=$3
scenes=$(cd "$(dirname "$0")/../../scenes" && pwd)
mkdir -p "$out"
shot() { local name=$1; shift; "$solution" --headless --size 640x360 --screenshot "$out/$name.png" "$@" >/dev/null; echo "wrote $out/$name.png"; }
table() { local name=$1; shift; "$solution" --headless --size 960x540 --frames 10 "$@" --sweep-csv "$out/$name.csv" 2>/dev/null | grep '^|' > "$out/$name.md"; echo "wrote $out/$name.md"; }

shot volumes
shot silhouettes --set camera.bookmark=2 --set debug.silhouettes=true
shot volumes_translucent --set camera.bookmark=2 --set debug.volumes=true
shot stencil_counts --set debug.stencil=true
shot inside_zpass --set camera.bookmark=3 --set volume.method=zpass
shot inside_zfail --set camera.bookmark=3 --set volume.method=zfail
shot shadow_map --set shadow.technique=shadow_map
shot ray_traced --set shadow.technique=ray_traced
"$student" --headless --size 640x360 --screenshot "$out/lab09_stubs.png" >/dev/null 2>&1 && echo "wrote $out/lab09_stubs.png"

# Seed 004's comparison, and exactness, from one run: volumes, the shadow map, the CPU ray tracer on
# one thread and on every core; then the camera inside a volume, z-pass against z-fail.
table techniques --metrics --sweep shadow.technique=volumes,shadow_map,ray_traced --sweep ray_traced.threads=1,0
table inside --metrics --set camera.bookmark=3 --sweep volume.method=zpass,zfail,auto

# Cost against geometry: nine spheres of 8 to 128 segments, volumes and the shadow map.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "segments,triangles,volumes_frame_ms,volumes_pass_ms,shadow_map_frame_ms,shadow_map_pass_ms" > "$out/tessellation.csv"
for n in 8 16 32 64 128; do
  sed "s/\"segments\": 32/\"segments\": $n/" "$scenes/volumes_spheres.json" > "$tmp/spheres.json"
  "$solution" --headless --size 960x540 --frames 10 --scene "$tmp/spheres.json" \
    --sweep shadow.technique=volumes,shadow_map --sweep-csv "$tmp/row.csv" >/dev/null 2>&1
  # Columns: technique, then the passes (depth, volumes, lighting, shadow_map), then frame_ms.
  awk -F, -v n="$n" 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i }
    NR == 2 { vf = $col["frame_ms"]; vp = $col["volumes_gpu_ms"] }
    NR == 3 { printf "%d,%d,%s,%s,%s,%s\n", n, 9 * (n * n - 2 * n), vf, vp, $col["frame_ms"], $col["shadow_map_gpu_ms"] }' \
    "$tmp/row.csv" >> "$out/tessellation.csv"
done
{
  echo "| segments | triangles | volumes: frame ms | volumes pass ms | shadow map: frame ms | shadow-map pass ms |"
  echo "|---|---|---|---|---|---|"
  tail -n +2 "$out/tessellation.csv" | awk -F, '{ printf "| %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6 }'
} > "$out/tessellation.md"
echo "wrote $out/tessellation.md"
gnuplot <<GNUPLOT
set terminal pngcairo size 720,400 font ",11" noenhanced
set output "$out/tessellation.png"
set datafile separator ","
set key top left
set logscale x 2
set xlabel "triangles in the nine spheres"
set ylabel "ms (960x540, llvmpipe)"
set title "What the shadow costs against geometry"
plot "$out/tessellation.csv" every ::1 using 2:4 with linespoints pt 7 lw 2 title "volumes pass", \
     "$out/tessellation.csv" every ::1 using 2:6 with linespoints pt 5 lw 2 title "shadow-map pass (2048^2)", \
     "$out/tessellation.csv" every ::1 using 2:3 with lines dt 2 title "frame, volumes", \
     "$out/tessellation.csv" every ::1 using 2:5 with lines dt 3 title "frame, shadow map"
GNUPLOT
echo "wrote $out/tessellation.png"
