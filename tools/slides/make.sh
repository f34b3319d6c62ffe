#!/usr/bin/env bash
# ./workbook slides [NN ...]: every lab's lecture deck (or these labs'), with its figures rendered
# from the labs' demo steps by the solutions, as self-contained HTML and PDF in build/slides/, then
# checked in Chromium (slides/README.md).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../workbook/lib.sh"
extra=(pandoc chromium fonts-lmodern ffmpeg)  # pandoc 2.17, the browser test and PDF, the math font, the clips
command -v npm >/dev/null 2>&1 || extra+=(nodejs npm)
install_packages "${PACKAGES[@]}" "${extra[@]}"
labs=""
for nn in "$@"; do lab_name "$nn" >/dev/null; labs+="${labs:+,}$nn"; done
targets=()
for d in labs/[0-9][0-9]_*/; do
  nn=$(basename "$d" | cut -c1-2)
  [[ -z "$labs" || ",$labs," == *",$nn,"* ]] || continue
  targets+=("lab${nn}_solution")
  # the bug gallery's ![...](hunt:NN.Hk): the solution with the hunts as handed out (cmake/Lab.cmake)
  if grep -q '"kind": "hunt"' "$d/exercises.json"; then targets+=("lab${nn}_bugs"); fi
done
echo "workbook: building ${targets[*]}"
QUIET=1 configure_and_build default --target "${targets[@]}"
echo "workbook: installing the slides' pinned npm packages (slides/package-lock.json)"
npm ci --prefix slides --prefer-offline --no-audit --no-fund --loglevel=error >/dev/null
/usr/bin/python3 -B tools/slides/build.py --build-dir build --out build/slides ${labs:+--labs "$labs"} --pdf
node tools/slides/check_decks.mjs build/slides/manifest.json ${labs:+--labs "$labs"}
