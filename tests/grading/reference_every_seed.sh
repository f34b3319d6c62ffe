#!/usr/bin/env bash
# The reference passes every test, public and held-out, at every grading seed (ctest -L grading).
# The grader turns each scene a little by a random seed (WB_VARY_SEED, common/scene/scene.cpp varyScene),
# so a measured bound the reference meets on the published scene can still fail it at some seeds:
# that is what once made the complete reference lose 08.5 at random (its near plane clipped casters
# for some turns of the light: 3.02% at the seams against 1.75% allowed at seed 14). ctest runs it
# once per seed (tests/grading/CMakeLists.txt: those that caught it, 14 and 16, and the ends of the
# range), so the seeds share the cores with the other tests. The tests run here the way the judge
# runs them: the solution's own test binaries with the seed in their environment.
set -uo pipefail
build=${1:?usage: reference_every_seed.sh BUILD_DIR SEED...}
shift
seeds=("$@")
[ ${#seeds[@]} -gt 0 ] || seeds=(0 7 14 16 977 4294967295)
out=$build/test-output/every-seed
failed=0
for seed in "${seeds[@]}"; do
  rm -rf "${out:?}/$seed"
  line="seed $seed:"
  for exe in "$build"/lab[0-9][0-9]_solution_tests; do
    nn=$(basename "$exe" | cut -c4-5)
    log=$out/$seed/lab$nn.log
    mkdir -p "$(dirname "$log")"
    if WB_VARY_SEED=$seed WB_TEST_OUTPUT_DIR=$out/$seed/$nn timeout 300 "$exe" >"$log" 2>&1; then
      line+=" $nn ok"
    else
      line+=" $nn FAILED"
      failed=1
      echo "--- lab $nn at seed $seed (WB_VARY_SEED=$seed $exe):"
      grep -E "^\[  FAILED  \]|WRONG|ERROR|Failure" "$log" | head -20
    fi
  done
  echo "$line"
done
[ "$failed" = 0 ] && echo "the reference passes every test at ${#seeds[@]} seeds"
exit "$failed"
