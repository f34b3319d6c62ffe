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
bytes=$(numfmt --from=iec "${memory%B}") || die "--memory $memory: a size such as 768M"
quota=$(awk -v c="$cpus" 'BEGIN { q = int(c * 100000); if (q < 1000) exit 1; print q }') || die "--cpus $cpus: such as 0.5"

# 1. The root, once.
if [ ! -x "$root/usr/bin/apt-get" ]; then
  command -v debootstrap >/dev/null || apt-get install -y debootstrap >/dev/null
  mirror=$( (grep -h '^URIs:' /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list.d/*.sources 2>/dev/null |
    awk '{ print $2 }' | grep -v -e security -e snapshot | head -1) || true)  # (the mirror apt uses)
  echo "simulate: making a Debian 12 root in $root (${mirror:-deb.debian.org})"
  debootstrap --variant=minbase bookworm "$root" "${mirror:-http://deb.debian.org/debian}" >"$root.debootstrap.log" 2>&1 ||
    die "debootstrap failed: $root.debootstrap.log"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
[ -f /etc/apt/sources.list.d/debian.sources ] && cp /etc/apt/sources.list.d/debian.sources "$root/etc/apt/sources.list.d/"

mounted=()
userns=$(cat /proc/sys/user/max_user_namespaces)
cleanup() {
  { echo "$userns" >/proc/sys/user/max_user_namespaces; } 2>/dev/null || true
  for ((k = ${#mounted[@]} - 1; k >= 0; k--)); do umount -l "${mounted[k]}" 2>/dev/null || true; done
}
trap cleanup EXIT
bind() {  # SRC DEST [ro]
  mkdir -p "$2" && mount --bind "$1" "$2" && mounted+=("$2")
  [ "${3:-}" != ro ] || mount -o remount,bind,ro "$2"
}
bind /proc "$root/proc"
bind /dev "$root/dev"
mkdir -p "$root/dev/shm" "$root/tmp" && chmod 1777 "$root/tmp"

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
v2=0 && [ -f /sys/fs/cgroup/cgroup.controllers ] && v2=1
group() {  # NAME: makes the cgroup, prints the folders to join
  if [ "$v2" = 1 ]; then
    echo "+memory +cpu" >/sys/fs/cgroup/cgroup.subtree_control 2>/dev/null || true
    mkdir -p "/sys/fs/cgroup/$1" && echo "$bytes" >"/sys/fs/cgroup/$1/memory.max" &&
      echo "$quota 100000" >"/sys/fs/cgroup/$1/cpu.max" && echo "/sys/fs/cgroup/$1"
  else
    mkdir -p "/sys/fs/cgroup/memory/$1" "/sys/fs/cgroup/cpu/$1"
    echo "$bytes" >"/sys/fs/cgroup/memory/$1/memory.limit_in_bytes"
    echo 100000 >"/sys/fs/cgroup/cpu/$1/cpu.cfs_period_us" && echo "$quota" >"/sys/fs/cgroup/cpu/$1/cpu.cfs_quota_us"
    echo "/sys/fs/cgroup/memory/$1 /sys/fs/cgroup/cpu/$1"
  fi
}
peak() {  # NAME: the group's peak memory in MiB
  local f=/sys/fs/cgroup/$1/memory.peak
  [ "$v2" = 1 ] || f=/sys/fs/cgroup/memory/$1/memory.max_usage_in_bytes
  echo $(($(cat "$f" 2>/dev/null || echo 0) >> 20))
}
# No user namespaces, as in Docker (its seccomp profile refuses them). Where this machine will not
# let the sysctl be changed, the grader is told to use the weakest mode, which is what it falls back
# to in the container, and the table says so.
mode_env=()
if ! echo 0 2>/dev/null >/proc/sys/user/max_user_namespaces; then
  echo "simulate: user namespaces cannot be turned off here (/proc/sys is read-only): WB_SANDBOX_MODE=session stands in"
  mode_env=(env WB_SANDBOX_MODE=session)
fi
printf '\n| submission | score | wall (s) | peak (MiB) | what the student sees first |\n|---|---|---|---|---|\n'
for sub in "$subs"/*; do
  name=$(basename "$sub") && [ "$name" != expected.json ] || continue
  find "$ag/submission" "$ag/results" -mindepth 1 -delete
  if [ -d "$sub" ]; then cp -r "$sub/." "$ag/submission/"; else cp "$sub" "$ag/submission/"; fi
  cg="wbsim-$$-${name//[^A-Za-z0-9_]/_}"
  read -r -a dirs <<<"$(group "$cg")"
  views=()
  for d in "${dirs[@]}"; do  # (the container's view of its own group, where the grader reads its limits)
    if [ "$v2" = 1 ]; then view=$root/sys/fs/cgroup; else view=$root/sys/fs/cgroup/$(basename "$(dirname "$d")"); fi
    bind "$d" "$view" ro && views+=("$view")
  done
  t0=$(date +%s.%N)
  (
    for d in "${dirs[@]}"; do echo "$BASHPID" >"$d/cgroup.procs"; done
    exec setpriv --bounding-set=-sys_admin -- "${mode_env[@]}" chroot "$root" /autograder/run_autograder
  ) >"$ag/run-$name.log" 2>&1 || true
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  for view in "${views[@]}"; do umount -l "$view" 2>/dev/null || true; done
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
  echo "| $name | ${row%% | *} | $wall | $(peak "$cg") | ${row#* | } |"
  cp "$ag/results/results.json" "$ag/results-$name.json" 2>/dev/null || true
  for d in "${dirs[@]}"; do rmdir "$d" 2>/dev/null || true; done
done
echo "simulate: logs and each results.json in $ag (run-NAME.log, results-NAME.json)"
