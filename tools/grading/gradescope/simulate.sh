#!/usr/bin/env bash
# A stand-in for Gradescope's autograder container that anyone can run (docs/gradescope.md):
#   tools/grading/gradescope/simulate.sh SUBMISSIONS [--labs 01,03] [--memory 768M] [--cpus 0.5] [--root DIR]
# As root, on Linux with cgroup v1 or v2. It makes a Debian 12 minbase root with debootstrap (once:
# --root, default build/gradescope-sim/root; Gradescope's image is Ubuntu 22.04, which this mirror
# does not have), lays out /autograder from `./workbook gradescope-bundle`, runs setup.sh in it, and
# then grades each submission (a folder or an archive in SUBMISSIONS) with run_autograder as
# Gradescope does: in a cgroup of --memory and --cpus (Gradescope's defaults: 768 MB, half a CPU), a
# read-only view of that cgroup as the container's own, no CAP_SYS_ADMIN and no user namespaces
# (user.max_user_namespaces is 0 while it grades, and put back), so bubblewrap and unshare cannot
# start. It prints each submission's score, wall time, peak memory and the first line of what the
# student sees, and setup.sh's time and the disk the grading tree takes.
set -euo pipefail
die() { echo "simulate: $*" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
subs="" labs="" memory=768M cpus=0.5 root="$here/build/gradescope-sim/root" setup=1
while [ $# -gt 0 ]; do
  case $1 in
    --labs) labs=${2:?}; shift 2 ;;
    --memory) memory=${2:?}; shift 2 ;;
    --cpus) cpus=${2:?}; shift 2 ;;
    --root) root=$(realpath -m "${2:?}"); shift 2 ;;
    --no-setup) setup=0; shift ;;  # (grade again with the /autograder of the last run)
    -*) die "unknown option $1 (usage: simulate.sh SUBMISSIONS [--labs 01,03] [--memory 768M] [--cpus 0.5] [--root DIR])" ;;
    *) subs=$(realpath "$1"); shift ;;
  esac
done
[ -n "$subs" ] && [ -d "$subs" ] || die "usage: simulate.sh SUBMISSIONS [--labs 01,03] [--memory 768M] [--cpus 0.5] [--root DIR]"
[ "$(id -u)" = 0 ] || die "run it as root: it makes a chroot, mounts and cgroups"
# shellcheck source=../sim_lib.sh
source "$here/tools/grading/sim_lib.sh"
sim_parse_limits "$memory" "$cpus"

# 1. The root, once.
sim_make_root bookworm
sim_no_userns

# 2. /autograder as Gradescope lays it out: the zip in source/, run_autograder beside it.
ag=$root/autograder
if [ "$setup" = 0 ] && [ -d "$ag/source/build-grade" ]; then
  echo "simulate: --no-setup: grading with $ag as it is"
else
zip=$(mktemp --suffix=.zip) && rm -f "$zip"
(cd "$here" && ./workbook gradescope-bundle "$zip" ${labs:+--labs "$labs"}) | tail -1
rm -rf "$ag" && mkdir -p "$ag/source" "$ag/submission" "$ag/results"
python3 - "$zip" "$ag/source" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as z:
    for info in z.infolist():
        path = z.extract(info, sys.argv[2])
        mode = info.external_attr >> 16
        if mode:
            os.chmod(path, mode & 0o7777)
PY
rm -f "$zip"
cp "$ag/source/run_autograder" "$ag/run_autograder"

# 3. setup.sh, as Gradescope runs it when it builds the image (root, network, no limits).
t0=$(date +%s)
chroot "$root" /bin/bash -c 'cd /autograder/source && bash ./setup.sh' >"$ag/setup.log" 2>&1 ||
  { tail -20 "$ag/setup.log"; die "setup.sh failed (its log: $ag/setup.log)"; }
echo "simulate: setup.sh took $(($(date +%s) - t0)) s; build-grade takes $(du -sh "$ag/source/build-grade" | cut -f1)"
fi

# 4. Each submission in a cgroup of its own, seen from inside as the container's (read-only).
printf '\n| submission | score | wall (s) | peak (MiB) | killed for memory | what the student sees first |\n|---|---|---|---|---|---|\n'
for sub in "$subs"/*; do
  name=$(basename "$sub") && [ "$name" != expected.json ] || continue
  find "$ag/submission" "$ag/results" -mindepth 1 -delete
  if [ -d "$sub" ]; then cp -r "$sub/." "$ag/submission/"; else cp "$sub" "$ag/submission/"; fi
  sim_contained "wbsim-$$-${name//[^A-Za-z0-9_]/_}" "$ag/run-$name.log" /autograder/run_autograder
  row=$(python3 - "$ag/results/results.json" <<'PY'
import json, sys
try:
    r = json.load(open(sys.argv[1]))
    first = (r.get("output") or "").strip().splitlines()
    print(f"{r.get('score')} | {(first[0] if first else '')[:90]}")
except Exception as e:
    print(f"NO VALID results.json ({type(e).__name__}) |")
PY
)
  # shellcheck disable=SC2154  # (wall, peak, ooms: set by sim_contained)
  echo "| $name | ${row%% | *} | $wall | $peak | $ooms | ${row#* | } |"
  cp "$ag/results/results.json" "$ag/results-$name.json" 2>/dev/null || true
done
echo "simulate: logs and each results.json in $ag (run-NAME.log, results-NAME.json)"
