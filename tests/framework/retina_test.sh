#!/usr/bin/env bash
# A framebuffer twice the window's size, as on a Mac's Retina display, in a real window (Xvfb):
# retina_shim.so (LD_PRELOAD) makes GLFW report the window in points (half the framebuffer's pixels)
# and a content scale of 2. A Retina window of 320x180 points must look like a plain window of
# 320x180 pixels, at twice the pixels: every viewport, scissor, read-back, split screen and caption
# band follows the framebuffer. So its screenshot (panels hidden: their text changes from frame to
# frame), halved, must match the plain one (the mean difference per channel of every 20x20 tile, as
# edges are drawn at another resolution); and its panels' text must be twice as many pixels tall (the run's record,
# panel_text_pixels): the same size in points. Two broken runs show that each check fails where a
# Mac would show a bug: the framebuffer taken for the window's size (WB_RETINA_SHIM_BROKEN), and
# panels enlarged twice (the content scale applied on top of ImGui's own Retina scaling: ui.scale=2).
# Skips (77) without xvfb-run. usage: retina_test.sh LAB_EXE SHIM.so OUT_DIR
set -uo pipefail
exe=$1 shim=$2 out=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
command -v xvfb-run >/dev/null || { echo "SKIP: needs xvfb-run"; exit 77; }
rm -rf "$out" && mkdir -p "$out"
# name, extra arguments: the plain scene, a split screen, a presenter step (its caption band below)
cases=("scene|" "split|--compare shadow.bias=0.01,0.03" "presenter|--demo-step 2")
cat >"$out/run.sh" <<RUN
#!/usr/bin/env bash
shot() { # NAME PRELOAD BROKEN ARGS...
  local name=\$1 preload=\$2 broken=\$3; shift 3
  local size=640x360; [ -n "\$preload" ] || size=320x180  # (the plain window: the Retina one's points)
  env \${preload:+LD_PRELOAD=\$preload} WB_RETINA_SHIM_BROKEN=\$broken "$exe" --size \$size --frames 6 \\
    --screenshot "$out/\$name.png" --record "$out/\$name.json" --set ui.panels=0 "\$@" >"$out/\$name.log" 2>&1 ||
    echo "\$name: exit \$?" >>"$out/errors.txt"
}
RUN
for c in "${cases[@]}"; do
  name=${c%%|*} args=${c#*|}
  cat >>"$out/run.sh" <<RUN
shot $name-plain "" 0 $args
shot $name-retina "$shim" 0 $args
shot $name-broken-framebuffer "$shim" 1 $args
shot $name-broken-panels "$shim" 0 $args --set ui.scale=2
RUN
done
chmod +x "$out/run.sh"
# (a screen large enough that the pointer, at its centre, is over no window: no tooltip)
timeout 240 xvfb-run -a -s "-screen 0 2400x2400x24" "$out/run.sh" || { echo "FAIL: the window runs did not finish"; exit 1; }
[ -f "$out/errors.txt" ] && { echo "FAIL: a run failed:"; cat "$out/errors.txt"; exit 1; }
python3 - "$out" "$here/../../tools/platforms/windows" "${cases[@]%%|*}" <<'PY'
import json
import sys
sys.path.insert(0, sys.argv[2])
from compare_png import read_png
out, names, failures = sys.argv[1], sys.argv[3:], 0
def difference(plain, retina):  # the plain and the halved retina: the largest mean difference per channel
    wp, hp, pp = read_png(f"{out}/{plain}.png")  # (0..255) of any 20 x 20 tile, so a label drawn at the
    wr, hr, pr = read_png(f"{out}/{retina}.png")  # wrong size shows, however small
    if (wr, hr) != (2 * wp, 2 * hp):
        return 255.0
    tiles = {}
    for y in range(hp):
        for x in range(wp):
            quad = [pr[(2 * y + dy) * wr + 2 * x + dx] for dy in (0, 1) for dx in (0, 1)]
            d = sum(abs(pp[y * wp + x][c] - sum(q[c] for q in quad) / 4) for c in range(3)) / 3
            tiles[(x // 20, y // 20)] = tiles.get((x // 20, y // 20), 0) + d / 400
    return max(tiles.values())
def text(name):  # the panels' text height in the framebuffer's pixels
    return json.load(open(f"{out}/{name}.json")).get("panel_text_pixels", 0)
for name in names:
    same = difference(f"{name}-plain", f"{name}-retina")
    fb = difference(f"{name}-plain", f"{name}-broken-framebuffer")
    plain, retina, twice = text(f"{name}-plain"), text(f"{name}-retina"), text(f"{name}-broken-panels")
    ok = same <= 16 and fb > 40 and retina == 2 * plain > 0 and twice != 2 * plain
    failures += not ok
    print(f"{'ok' if ok else 'FAIL'}: {name}: a Retina window, halved, differs from a plain one by {same:.2f}/255 "
          f"per channel on average in its worst 20x20 tile (allowed 16; the framebuffer taken for the window's "
          f"size: {fb:.2f}, must be over 40); its panels' text is {retina:g} px tall, {plain:g} in the plain window (must be twice; "
          f"panels enlarged twice: {twice:g})")
sys.exit(1 if failures else 0)
PY
