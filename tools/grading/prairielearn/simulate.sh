#!/usr/bin/env bash
# A stand-in for PrairieLearn's external-grading container that anyone can run (docs/prairielearn.md):
#   tools/grading/prairielearn/simulate.sh SUBMISSIONS --lab NN [--memory 768M] [--cpus 0.5] [--root DIR] [--no-setup]
# As root, on Linux with cgroup v1 or v2. In a Debian 12 root (made once with debootstrap, as
# gradescope/simulate.sh does; the export's image is Ubuntu 22.04, which this mirror does not have) it
# builds the image as the export's Dockerfile does (image/workbook in /opt/shadow-workbook, then
# image_setup.sh), then grades each submission (a folder from ./workbook make-submissions, or the
# lab's exercise files alone) as PrairieLearn runs a job: /grade laid out (serverFilesCourse, student
# with the files flat as pl-file-upload gives them, data, tests), info.json's entrypoint run in a
# cgroup of --memory and --cpus with no user namespaces and no network use. It prints each
# submission's score, wall time (PrairieLearn stops a job at the question's timeout, 600 s at most)
# and peak memory, and checks every results.json against PrairieLearn's contract.
set -euo pipefail
die() { echo "simulate: $*" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
usage="usage: simulate.sh SUBMISSIONS --lab NN [--memory 768M] [--cpus 0.5] [--root DIR] [--no-setup]"
subs="" lab="" memory=768M cpus=0.5 root="$here/build/prairielearn-sim/root" setup=1
while [ $# -gt 0 ]; do
  case $1 in
    --lab) lab=$(printf '%02d' "$((10#${2:?}))"); shift 2 ;;
    --memory) memory=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --root) root=$(realpath -m "${2:?}"); shift 2 ;;
    --no-setup) setup=0; shift ;;  # (grade again with the image of the last run)
    -*) die "unknown option $1 ($usage)" ;;
    *) subs=$(realpath "$1"); shift ;;
  esac
done
[ -n "$subs" ] && [ -d "$subs" ] && [ -n "$lab" ] || die "$usage"
[ "$(id -u)" = 0 ] || die "run it as root: it makes a chroot, mounts and cgroups"
lab_name=$(basename "$(ls -d "$here/labs/${lab}_"*)") || die "no lab $lab"
# shellcheck source=../sim_lib.sh
source "$here/tools/grading/sim_lib.sh"
sim_parse_limits "$memory" "$cpus"
sim_make_root bookworm
sim_no_userns

# 1. The export, and the image built from it as its Dockerfile says (root, network, no limits).
# The image's tree is kept in $image and mounted for each job with an overlay of its own, so every job
# starts from the image as it was built, as each of PrairieLearn's containers does.
export_dir=$root/../prairielearn-export
image=$root/../prairielearn-image
tree=$root/opt/shadow-workbook
if [ "$setup" = 0 ] && [ -d "$image/build-grade" ]; then
  echo "simulate: --no-setup: grading with the image in $image as it is"
else
  rm -rf "$export_dir" "$tree" "$image"
  "$here/workbook" prairielearn-export "$export_dir" --labs "$lab" | head -1
  grep -q "^FROM ubuntu:22.04" "$export_dir/image/Dockerfile" || die "the export's Dockerfile changed: update this stand-in"
  mkdir -p "$tree" && cp -a "$export_dir/image/workbook/." "$tree/"
  t0=$(date +%s)
  chroot "$root" /bin/bash /opt/shadow-workbook/tools/grading/prairielearn/image_setup.sh "$lab" >"$root/../image_setup.log" 2>&1 ||
    { tail -20 "$root/../image_setup.log"; die "image_setup.sh failed (its log: $root/../image_setup.log)"; }
  echo "simulate: the image's setup took $(($(date +%s) - t0)) s; its prebuilt tree takes $(du -sh "$tree" | cut -f1)"
  mv "$tree" "$image"
fi
mkdir -p "$tree"
entry=$(python3 -c 'import json,sys; print(" ".join(json.load(open(sys.argv[1]))["externalGradingOptions"]["entrypoint"]))' \
  "$export_dir/course/questions/shadow-workbook/$lab_name/info.json")
read -r -a entrypoint <<<"$entry"

# 2. Each submission as one job, in a cgroup of its own.
printf '\n| submission | score | gradable | wall (s) | peak (MiB) | killed for memory | message |\n|---|---|---|---|---|---|---|\n'
for sub in "$subs"/*; do
  name=$(basename "$sub") && [ "$name" != expected.json ] || continue
  layer=$(mktemp -d) && mkdir "$layer/upper" "$layer/work"
  mount -t overlay overlay -o "lowerdir=$image,upperdir=$layer/upper,workdir=$layer/work" "$tree" ||
    die "could not mount the image's overlay on $tree"
  rm -rf "$root/grade" && mkdir -p "$root/grade/student" "$root/grade/data" "$root/grade/serverFilesCourse"
  cp -a "$export_dir/course/serverFilesCourse/shadow-workbook" "$root/grade/serverFilesCourse/"
  mkdir -p "$root/grade/shared" && cp -a "$export_dir/course/serverFilesCourse/shadow-workbook" "$root/grade/shared/"  # (PrairieLearn's older copy)
  echo '{"params": {}, "correct_answers": {}, "submitted_answers": {}}' >"$root/grade/data/data.json"
  # pl-file-upload's files, flat: the lab's exercise files from the submission's labs/NN_name/ (or its top)
  python3 - "$sub" "$here/labs/$lab_name/exercises.json" "$root/grade/student" "$lab_name" <<'PY'
import json, shutil, sys
from pathlib import Path
sub, manifest, dest, lab = Path(sys.argv[1]), json.load(open(sys.argv[2])), Path(sys.argv[3]), sys.argv[4]
for rel in sorted({e["file"] for e in manifest["exercises"]}):
    for src in (sub / "labs" / lab / rel, sub / Path(rel).name):
        if src.is_file():
            shutil.copyfile(src, dest / Path(rel).name)
            break
PY
  sim_contained "wbpl-$$-${name//[^A-Za-z0-9_]/_}" "$root/../job-$name.log" "${entrypoint[@]}"
  # shellcheck disable=SC2154  # (rc: set by sim_contained)
  row=$(python3 - "$root/grade/results/results.json" "$rc" <<'PY'
import json, os, sys
try:
    size = os.path.getsize(sys.argv[1])
    r = json.load(open(sys.argv[1]))
    bad = [f"the entrypoint exited {sys.argv[2]} (PrairieLearn reads no results then)"] * (sys.argv[2] != "0")
    bad += [k for k in ("score",) if not isinstance(r.get(k), (int, float)) or not 0 <= r[k] <= 1]
    bad += ["over 1 MB"] * (size > 1_000_000)
    bad += [f"test {t.get('name')} lacks {k}" for t in r.get("tests", []) for k in ("name", "points", "max_points")
            if k not in t]
    print(f"{r.get('score'):.3f} | {r.get('gradable', True)} | {('CONTRACT BROKEN: ' + '; '.join(bad)) if bad else r.get('message', '')[:90]}")
except Exception as e:
    print(f"NO VALID results.json ({type(e).__name__}) | | ")
PY
)
  umount "$tree" && rm -rf "$layer"
  IFS='|' read -r score gradable message <<<"$row"
  # shellcheck disable=SC2154  # (wall, peak, ooms: set by sim_contained)
  echo "| $name | ${score% } | ${gradable# } | $wall | $peak | $ooms | ${message# } |"
  cp "$root/grade/results/results.json" "$root/../results-$name.json" 2>/dev/null || true
done
echo "simulate: each job's log and results.json in $(realpath "$root/..") (job-NAME.log, results-NAME.json)"
