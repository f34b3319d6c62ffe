#!/usr/bin/env bash
# Presenter keys in a real window (Xvfb): Page Down three times and Page Up once must show steps 1,
# 2, 3, then 2, each tap as short as a presenter's clicker makes it (shorter than a frame). Skips
# (77) without xvfb-run or xdotool.
# usage: presenter_keys_test.sh LAB_EXE OUT_DIR
set -uo pipefail
exe=$1 out=$2
command -v xvfb-run >/dev/null && command -v xdotool >/dev/null || { echo "SKIP: needs xvfb-run and xdotool"; exit 77; }
mkdir -p "$out"
cat >"$out/drive.sh" <<DRIVE
#!/usr/bin/env bash
"$exe" --size 640x360 --frames 100000 >"$out/lab.log" 2>&1 &
pid=\$!
for i in \$(seq 50); do w=\$(xdotool search --name "^Lab " 2>/dev/null | head -1); [ -n "\$w" ] && break; sleep 0.2; done
[ -n "\$w" ] || { echo "no window appeared"; kill \$pid; exit 1; }
sleep 1
xdotool mousemove 320 300; xdotool windowfocus "\$w" 2>/dev/null
for k in Next Next Next Prior; do xdotool key --delay 5 \$k; sleep 1.5; done
kill \$pid; wait \$pid 2>/dev/null
exit 0
DRIVE
chmod +x "$out/drive.sh"
timeout 120 xvfb-run -a -s "-screen 0 640x360x24" "$out/drive.sh" || { echo "FAIL: the window could not be driven"; exit 1; }
steps=$(grep -o '^step [0-9]*' "$out/lab.log" | awk '{printf "%s ", $2}')
if [ "$steps" != "1 2 3 2 " ]; then
  echo "FAIL: Page Down x3 and Page Up showed steps '$steps', expected '1 2 3 2 '"; cat "$out/lab.log"; exit 1
fi
echo "PASS: Page Down x3, Page Up: steps $steps"
