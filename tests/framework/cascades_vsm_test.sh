#!/usr/bin/env bash
# Lab 10's csm.filter=vsm (the solution's lab 05 functions on moments prefiltered per cascade) draws
# the shadows that 5x5 PCF on the same cascades draws: within 0.25 on 70 % of the pixels either
# leaves not fully lit (measured: 80 %), each with shadows, and VSM never darker on the whole
# (Chebyshev's bound is an upper bound on the lit share). Usage: cascades_vsm_test.sh LAB10_SOLUTION_EXE OUT_DIR
set -euo pipefail
exe=$1 out=$2
mkdir -p "$out"
for f in pcf vsm; do
  "$exe" --headless --size 480x270 --set csm.filter=$f --set csm.kernel=5 --dump-visibility "$out/$f.pfm" --quiet
done
/usr/bin/python3 - "$out/pcf.pfm" "$out/vsm.pfm" <<'PY'
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
print(f"{len(either)} pixels not lit in one: VSM within 0.25 of 5x5 PCF on {100 * close:.1f} %; mean visibility "
      f"pcf {mean[0]:.3f}, vsm {mean[1]:.3f}; below 0.5: pcf {dark[0]}, vsm {dark[1]}")
# Chebyshev's bound is an upper bound on the lit share: VSM may be lighter than PCF, never darker.
sys.exit(0 if close >= 0.7 and min(dark) > 100 and mean[1] >= mean[0] - 0.02 else 1)
PY
