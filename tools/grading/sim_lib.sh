# Sourced by the stand-ins for a grading service's container (gradescope/simulate.sh,
# prairielearn/simulate.sh): a Debian 12 root made once with debootstrap, binds into it, and a cgroup
# per submission with a memory limit and a CPU quota (v1 or v2), seen from inside as the container's
# own, with no user namespaces. Needs: root, and $root, $bytes and $quota set by the caller.
# shellcheck shell=bash disable=SC2034,SC2154
# (SC2034, SC2154: root, bytes and quota come from the caller; rc, wall, peak and ooms go to it)

# shellcheck source=../workbook/packages.sh
source "$(dirname "${BASH_SOURCE[0]}")/../workbook/packages.sh"

sim_parse_limits() {  # MEMORY CPUS: sets bytes and quota
  bytes=$(numfmt --from=iec "${1%B}") || die "--memory $1: a size such as 768M"
  quota=$(awk -v c="$2" 'BEGIN { q = int(c * 100000); if (q < 1000) exit 1; print q }') || die "--cpus $2: such as 0.5"
}

sim_make_root() {  # [SUITE]: once, a Debian minbase root in $root (bookworm: 12; trixie: 13), with this
  # machine's apt mirror and DNS, and /proc and /dev bound into it until the script ends
  local suite=${1:-bookworm}
  if [ ! -x "$root/usr/bin/apt-get" ]; then
    command -v debootstrap >/dev/null || apt-get install -y debootstrap >/dev/null
    local mirror
    mirror=$(apt_mirror || true)  # (tools/workbook/packages.sh)
    echo "simulate: making a Debian $suite root in $root (${mirror:-deb.debian.org})"
    mkdir -p "$(dirname "$root")"
    debootstrap --variant=minbase "$suite" "$root" "${mirror:-http://deb.debian.org/debian}" >"$root.debootstrap.log" 2>&1 ||
      die "debootstrap failed: $root.debootstrap.log"
  fi
  cp /etc/resolv.conf "$root/etc/resolv.conf"
  [ "$suite" != bookworm ] || [ ! -f /etc/apt/sources.list.d/debian.sources ] ||
    cp /etc/apt/sources.list.d/debian.sources "$root/etc/apt/sources.list.d/"
  mounted=()
  userns=$(cat /proc/sys/user/max_user_namespaces)
  trap sim_cleanup EXIT
  sim_bind /proc "$root/proc"
  sim_bind /dev "$root/dev"
  mkdir -p "$root/dev/shm" "$root/tmp" && chmod 1777 "$root/tmp"
}

sim_no_userns() {  # as in a container: no user namespaces while the script runs (or the weakest mode)
  v2=0 && [ -f /sys/fs/cgroup/cgroup.controllers ] && v2=1
  # No user namespaces, as in Docker (its seccomp profile refuses them). Where this machine will not
  # let the sysctl be changed, the grader is told to use the weakest mode, which is what it falls back
  # to in the container, and the output says so.
  mode_env=()
  if ! echo 0 2>/dev/null >/proc/sys/user/max_user_namespaces; then
    echo "simulate: user namespaces cannot be turned off here (/proc/sys is read-only): WB_SANDBOX_MODE=session stands in"
    mode_env=(env WB_SANDBOX_MODE=session)
  fi
}

sim_cleanup() {
  { echo "$userns" >/proc/sys/user/max_user_namespaces; } 2>/dev/null || true
  for ((k = ${#mounted[@]} - 1; k >= 0; k--)); do umount -l "${mounted[k]}" 2>/dev/null || true; done
}

sim_bind() {  # SRC DEST [ro]
  mkdir -p "$2" && mount --bind "$1" "$2" && mounted+=("$2")
  [ "${3:-}" != ro ] || mount -o remount,bind,ro "$2"
}

sim_group() {  # NAME: makes the cgroup, prints the folders to join
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

sim_peak() {  # NAME: the group's peak memory in MiB (page cache included), and its processes the
  # kernel killed for memory (v2's memory.events, v1's memory.oom_control; "?" where it has no count)
  local f=/sys/fs/cgroup/$1/memory.peak events=/sys/fs/cgroup/$1/memory.events kills
  [ "$v2" = 1 ] || { f=/sys/fs/cgroup/memory/$1/memory.max_usage_in_bytes; events=/sys/fs/cgroup/memory/$1/memory.oom_control; }
  kills=$(awk '$1 == "oom_kill" { print $2 }' "$events" 2>/dev/null)
  echo "$(($(cat "$f" 2>/dev/null || echo 0) >> 20)) ${kills:-?}"
}

sim_contained() {  # NAME LOG COMMAND...: runs COMMAND in the root, in cgroup NAME; sets rc (its exit
  # code), wall (s), peak (MiB) and ooms (the processes killed for memory)
  local name=$1 log=$2 d view t0
  shift 2
  local dirs views=()
  read -r -a dirs <<<"$(sim_group "$name")"
  for d in "${dirs[@]}"; do  # (the container's view of its own group, where the grader reads its limits)
    if [ "$v2" = 1 ]; then view=$root/sys/fs/cgroup; else view=$root/sys/fs/cgroup/$(basename "$(dirname "$d")"); fi
    sim_bind "$d" "$view" ro && views+=("$view")
  done
  t0=$(date +%s.%N)
  (
    for d in "${dirs[@]}"; do echo "$BASHPID" >"$d/cgroup.procs"; done
    exec setpriv --bounding-set=-sys_admin -- "${mode_env[@]}" chroot "$root" "$@"
  ) >"$log" 2>&1 && rc=0 || rc=$?
  wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  for view in "${views[@]}"; do umount -l "$view" 2>/dev/null || true; done
  read -r peak ooms <<<"$(sim_peak "$name")"
  for d in "${dirs[@]}"; do rmdir "$d" 2>/dev/null || true; done
}
