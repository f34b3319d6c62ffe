#!/usr/bin/env bash
# Lab 10's csm.filter=esm, vsm and evsm (the solutions of labs 04-06 on maps prefiltered per cascade)
# draw the shadows that 5x5 PCF on the same cascades draws: within 0.25 on 60 % of the pixels either
# leaves not fully lit (measured: ESM 64 %, VSM 80 %, EVSM 81 %), each with shadows, and never darker
# on the whole. Usage: cascades_filtered_test.sh LAB10_SOLUTION_EXE OUT_DIR
set -euo pipefail
exe=$1 out=$2
mkdir -p "$out"
for f in pcf esm vsm evsm; do
  "$exe" --headless --size 480x270 --set csm.filter=$f --set csm.kernel=5 --dump-visibility "$out/$f.pfm" --quiet
done
for f in esm vsm evsm; do
/usr/bin/python3 - "$out/pcf.pfm" "$out/$f.pfm" "$f" <<'PY'
import struct, sys
def pfm(p):
    with open(p, "rb") as f:
        f.readline(); w, h = map(int, f.readline().split()); s = float(f.readline())
        return struct.unpack(("<" if s < 0 else ">") + "%df" % (w * h), f.read(4 * w * h))
a, b = pfm(sys.argv[1]), pfm(sys.argv[2])
either = [(x, y) for x, y in zip(a, b) if x < 0.99 or y < 0.99]  # in shadow in one of them, at least partly
close = sum(abs(x - y) <= 0.25 for x, y in either) / len(either)
mean = [sum(v) / len(either) for v in zip(*either)]
dark = [sum(v < 0.5 for v in col) for col in zip(*either)]
print(f"{sys.argv[3]}: {len(either)} pixels not lit in one: within 0.25 of 5x5 PCF on {100 * close:.1f} %; mean visibility "
      f"pcf {mean[0]:.3f}, {sys.argv[3]} {mean[1]:.3f}; below 0.5: pcf {dark[0]}, {sys.argv[3]} {dark[1]}")
# Chebyshev's bound (VSM, EVSM) and ESM's exponential are upper bounds on the lit share: they may be
# lighter than PCF over the same footprint, not darker.
sys.exit(0 if close >= 0.6 and min(dark) > 100 and mean[1] >= mean[0] - 0.02 else 1)
PY
done
