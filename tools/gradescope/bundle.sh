#!/usr/bin/env bash
# Builds the Gradescope autograder zip: ./workbook gradescope-bundle [ZIP] (docs/gradescope.md).
# The zip holds setup.sh and run_autograder at its top and the instructor edition (solutions and
# held-out tests included, build folders excluded) in source/.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
zip=$(realpath -m "${1:-$root/build/gradescope-autograder.zip}")
mkdir -p "$(dirname "$zip")"
cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  files=$(git ls-files --cached --others --exclude-standard)
else
  files=$(find . -type f -not -path './build*' -not -path './grades/*' -not -path './.git/*' | sed 's|^\./||')
fi
FILES="$files" /usr/bin/python3 - "$zip" "$root" <<'PY'
import os, sys, zipfile
zip_path, root = sys.argv[1], sys.argv[2]
files = [f for f in os.environ["FILES"].split("\n") if f and os.path.isfile(os.path.join(root, f))]
def add(z, src, name):
    info = zipfile.ZipInfo.from_file(src, name)
    info.external_attr = (os.stat(src).st_mode & 0xFFFF) << 16  # keep the executable bits
    with open(src, "rb") as f:
        z.writestr(info, f.read(), zipfile.ZIP_DEFLATED)
with zipfile.ZipFile(zip_path, "w") as z:
    for name in ("setup.sh", "run_autograder"):
        add(z, os.path.join(root, "tools/gradescope", name), name)
    for f in files:
        add(z, os.path.join(root, f), "source/" + f)
print(f"wrote {zip_path} ({len(files)} files of the instructor edition in source/)")
PY
