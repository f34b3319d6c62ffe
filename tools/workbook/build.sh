# Sourced by ./workbook: configuring and building a preset, lab names, and running a lab (in a
# window, or headlessly to a file when there is no display).
# shellcheck shell=bash
configure_and_build() {  # $1 = preset, then targets; QUIET=1 shows the build log only when it fails
  local preset=$1 dir=build
  [ "$preset" = ci ] && dir=build-ci
  shift
  if [ "${QUIET:-0}" = 1 ]; then
    mkdir -p "$dir"
    if ! { [ -f "$dir/CMakeCache.txt" ] || cmake --preset "$preset"; } >"$dir/workbook-build.log" 2>&1 ||
       ! cmake --build "$dir" -j "$JOBS" "$@" >>"$dir/workbook-build.log" 2>&1; then
      # (|| true: under pipefail, a log without such lines, or head closing the pipe after 60 lines,
      # would end the script here, before the message that says where the full log is)
      grep -E -A3 "error|Error" "$dir/workbook-build.log" | head -60 >&2 || true
      die "the build failed (full log: $dir/workbook-build.log)"
    fi
  else
    [ -f "$dir/CMakeCache.txt" ] || cmake --preset "$preset" >/dev/null
    cmake --build "$dir" -j "$JOBS" "$@"
  fi
}

lab_name() {  # 01 -> 01_depth_map
  local nn=$1 d
  [[ "$nn" =~ ^[0-9]{2}$ ]] || die "expected a two-digit lab number such as 01, got '$nn'"
  for d in labs/"$nn"_*/; do [ -d "$d" ] && { basename "$d"; return; }; done
  die "there is no lab $nn; the labs are: $(cd labs && echo *)"
}

fill_from_stubs() {  # NN_name: the student edition's files that predate an exercise get its stub
  # A file written before one of its exercises was added (a new edition of the labs mid-term) gets
  # that exercise's stub from the stubs as handed out (tests/stubs/NN_name/), as the grader grades it:
  # build/wb_check --fill-missing (common/exercise/exercise_chunks.hpp) does it and says so, one line each.
  local name=$1 stub rel
  while IFS= read -r stub; do
    rel=${stub#"tests/stubs/$name/"}
    if [ -f "labs/$name/$rel" ]; then
      build/wb_check --fill-missing "labs/$name/$rel" "$stub" "labs/$name/$rel" "$stub" check
    fi
  done < <(find "tests/stubs/$name" -type f -name 'exercise*' | sort)
}

has_display() { [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; }

run_lab() {  # NN [--solution] [options]
  local nn=$1; shift
  lab_name "$nn" >/dev/null
  local target="lab$nn"
  if [ "${1:-}" = "--solution" ]; then
    shift
    [ -d "solutions/$(lab_name "$nn")" ] && target="lab${nn}_solution" || echo "workbook: no solutions in the student edition; running your build" >&2
  fi
  install_packages "${PACKAGES[@]}"
  local args=("$@") targets=("$target") nodisplay=0 picture=0
  if ! has_display && [[ ! " ${args[*]:-} " =~ " --headless "|" --help "|" --list-settings " ]]; then
    echo "workbook: no display found, so lab $nn renders headlessly (Mesa llvmpipe) to a file"
    nodisplay=1 picture=1
  fi
  # A headless run that asks for no output writes its picture there too (one place for both).
  [[ " ${args[*]:-} " =~ " --headless " &&
     ! " ${args[*]} " =~ " --"(screenshot|dump-visibility|bench|metrics|record|sweep|help|list-settings)" " ]] && picture=1
  if [ "$picture" = 1 ]; then  # (first: a --screenshot of the student's own, later, wins)
    mkdir -p build/renders
    args=(--screenshot "build/renders/lab$nn.png" "${args[@]}")
  fi
  [ "$nodisplay" = 0 ] || args=(--headless "${args[@]}")
  # A window checks the running code with the lab's tests (built from the same exercise object).
  [[ " ${args[*]:-} " =~ " --headless " ]] || targets+=("${target}_tests")
  echo "workbook: building ${targets[*]}"
  QUIET=1 configure_and_build default --target "${targets[@]}"
  "build/$target" "${args[@]}"
}

bench_lab() {  # NN [--solution] [--window]: GPU time per pass and frame rate at 960x540
  [ $# -ge 1 ] || die "usage: ./workbook bench NN [--solution] [--window]"
  local nn=$1 a args=()
  shift
  mkdir -p build/bench
  if [[ " $* " =~ " --window " ]]; then
    # In a real window (the panels, the blit and the swap included); under Xvfb without a display.
    for a in "$@"; do [ "$a" = --window ] || args+=("$a"); done
    if has_display; then
      run_lab "$nn" "${args[@]}" --size 960x540 --frames 120 --bench "build/bench/lab$nn-window.csv"
    else
      install_packages "${PACKAGES[@]}" xvfb xauth
      xvfb-run -a -s "-screen 0 1280x800x24" "$0" bench "$nn" "${args[@]}" --window
    fi
  else
    run_lab "$nn" "$@" --headless --size 960x540 --frames 60 --bench "build/bench/lab$nn.csv"
  fi
}

build_solutions() {  # every lab's reference solution (instructor edition), the build log shown only on failure
  local d n targets=()
  echo "workbook: building every lab's solution"
  for d in solutions/[0-9][0-9]_*/; do n=$(basename "$d"); targets+=(--target "lab${n:0:2}_solution"); done
  QUIET=1 configure_and_build default "${targets[@]}"
}
