#!/usr/bin/env bash
# Builds the Gradescope autograder zip: ./workbook gradescope-bundle [ZIP] [--labs 03,04]
# (docs/gradescope.md). Gradescope unpacks the zip into /autograder/source, so the zip holds the
# instructor edition at its top (solutions and held-out tests included) beside setup.sh and
# run_autograder, and gradescope-labs, the labs this assignment grades (empty: every lab).
# Only files that git tracks go in: never a build folder, an earlier zip or a __pycache__.
set -euo pipefail
die() { echo "gradescope-bundle: $*" >&2; exit 2; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
zip="" labs=""
while [ $# -gt 0 ]; do
  case "$1" in
    --labs) [ $# -ge 2 ] || die "--labs needs a list such as 03 or 03,04"; labs=$2; shift 2 ;;
    --labs=*) labs=${1#--labs=}; shift ;;
    -*) die "unknown option $1 (usage: ./workbook gradescope-bundle [ZIP] [--labs 03,04])" ;;
    *) [ -z "$zip" ] || die "one ZIP only (got $zip and $1)"; zip=$1; shift ;;
  esac
done
zip=$(realpath -m "${zip:-$root/build/gradescope-autograder.zip}")
cd "$root"
# The workbook itself must be the checkout's top (a copy inside another repository is not one).
[ "$(git rev-parse --show-toplevel 2>/dev/null)" = "$(pwd -P)" ] ||
  die "$root is not a git checkout: the bundle holds the files git tracks, so it is made from the instructor edition's repository"
[ -d solutions ] || die "the autograder needs the instructor edition (solutions/ is missing)"
changed=$(git status --porcelain --untracked-files=no | wc -l)
[ "$changed" = 0 ] || echo "gradescope-bundle: note: $changed tracked files have uncommitted changes; they go in as they are on disk" >&2
mkdir -p "$(dirname "$zip")"
list=$(mktemp)
trap 'rm -f "$list"' EXIT
git ls-files -z >"$list"
LABS="$labs" /usr/bin/python3 -B - "$zip" "$root" "$list" <<'PY'
import json, os, sys, zipfile
from pathlib import Path
zip_path, root, listing = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
files = [f for f in listing.read_text().split("\0") if f and (root / f).is_file() and not (root / f).is_symlink()]
manifests = {p.parent.name[:2]: p for p in sorted((root / "labs").glob("*/exercises.json"))}
wanted = [x.strip().zfill(2) for x in os.environ["LABS"].split(",") if x.strip()]
unknown = [x for x in wanted if x not in manifests]
if unknown:
    sys.exit(f"gradescope-bundle: no lab {', '.join(unknown)}; the labs are {', '.join(manifests)}")
chosen = wanted or list(manifests)
points = sum(e["points"] for nn in chosen for e in json.loads(manifests[nn].read_text())["exercises"]
             if not e.get("extension"))
def add(z, src, name):
    info = zipfile.ZipInfo.from_file(src, name)
    info.external_attr = (os.stat(src).st_mode & 0xFFFF) << 16  # keep the executable bits
    with open(src, "rb") as f:
        z.writestr(info, f.read(), zipfile.ZIP_DEFLATED)
tmp = zip_path + ".tmp"
with zipfile.ZipFile(tmp, "w") as z:
    for name in ("setup.sh", "run_autograder"):
        add(z, root / "tools/grading/gradescope" / name, name)
    for f in files:
        add(z, root / f, f)
    z.writestr("gradescope-labs", ",".join(wanted) + "\n")
os.replace(tmp, zip_path)
print(f"gradescope-bundle: wrote {zip_path} ({len(files)} tracked files)")
print(f"gradescope-bundle: the assignment grades lab{'s' if len(chosen) > 1 else ''} {', '.join(chosen)}: "
      f"set its total to {points} points on Gradescope (extensions are bonus points on top)")
print("gradescope-bundle: Gradescope's defaults are 768 MB, half a CPU and 10 minutes; docs/gradescope.md "
      "gives the time and memory measured per assignment; grade one honest submission first, and raise the "
      "autograder's memory or timeout where it comes near them")
PY
