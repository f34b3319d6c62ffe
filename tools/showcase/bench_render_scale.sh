#!/usr/bin/env bash
# render.scale on a projector: the showcase in a real window (Xvfb when there is no display) at
# 960x540, at 1920x1080 with render.scale=0.5 and at 1920x1080 in full, in interleaved rounds; prints
# each setting's median frame time and spread, and the ratios to 960x540 per round.
#   tools/showcase/bench_render_scale.sh [BUILD_DIR] [ROUNDS]     (default build-ci, 5 rounds)
set -euo pipefail
if [ -z "${DISPLAY:-}" ]; then  # a real window needs a display: Xvfb's
  exec xvfb-run -a -s "-screen 0 1920x1080x24" "$0" "$@"
fi
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$(cd "${1:-$ROOT/build-ci}" && pwd)
rounds=${2:-5}
[ -x "$build/showcase" ] || { echo "bench_render_scale: no $build/showcase (cmake --build $build --target showcase)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for r in $(seq "$rounds"); do
  for s in "960x540 1" "1920x1080 0.5" "1920x1080 1"; do
    # shellcheck disable=SC2086  # (split on purpose: the size and the scale)
    set -- $s
    "$build/showcase" --size "$1" --set render.scale="$2" --frames 90 --bench "$out/b.csv" >/dev/null 2>&1
    /usr/bin/python3 -c "import csv,sys; print(sys.argv[2], [r[4] for r in csv.reader(open(sys.argv[1])) if r[3]=='frame_wall'][0])" \
      "$out/b.csv" "$r,$1@$2" >>"$out/rounds.txt"
  done
done
/usr/bin/python3 - "$out/rounds.txt" <<'PY'
import statistics as st, sys
by = {}
for line in open(sys.argv[1]):
    key, ms = line.split()
    rnd, setting = key.split(",")
    by.setdefault(setting, {})[rnd] = float(ms)
base = by["960x540@1"]
for s, v in by.items():
    print(f"{s:>15}: median {st.median(v.values()):6.1f} ms a frame (from {min(v.values()):.1f} to {max(v.values()):.1f})")
for s in ("1920x1080@0.5", "1920x1080@1"):
    r = [by[s][k] / base[k] for k in base]
    print(f"{s} / 960x540@1, per round: {' '.join(f'{x:.2f}' for x in r)}; median {st.median(r):.2f}")
PY
