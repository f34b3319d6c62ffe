#!/usr/bin/env bash
# The grader on a synthetic class (ctest -L grading): submissions made from the solutions (full,
# stubs, one mutant, a compile error, a segfault, endless loops in C++ and GLSL, a build that runs
# past the build time limit, a zipped upload) are graded as a batch, which must complete, and held
# against their expected scores; then the Gradescope bundle is built and its layout checked. Labs
# 01 and 02 keep it to a few minutes (the build time limit of 20 s costs endless_build about 1 min).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
out=${1:?usage: run_synthetic_class.sh OUTPUT_DIR}
rm -rf "$out" && mkdir -p "$out"
/usr/bin/python3 "$root/tools/make_submissions.py" "$out/submissions" --labs 01,02
/usr/bin/python3 "$root/tools/grade.py" --batch "$out/submissions" --out "$out/grades" --labs 01,02 --jobs 1 \
  --timeout 20 --build-timeout 20
cat "$out/grades/summary.md"
/usr/bin/python3 "$root/tests/grading/check_batch.py" "$out/submissions" "$out/grades"
"$root/tools/gradescope/bundle.sh" "$out/autograder.zip"
/usr/bin/python3 - "$out/autograder.zip" <<'PY'
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = set(z.namelist())
mode = {i.filename: i.external_attr >> 16 for i in z.infolist()}
need = ["setup.sh", "run_autograder", "source/workbook", "source/tools/grade.py", "source/CMakeLists.txt"]
missing = [n for n in need if n not in names]
assert not missing, f"the bundle lacks {missing}"
assert all(mode[n] & 0o111 for n in ("setup.sh", "run_autograder")), "setup.sh and run_autograder must be executable"
assert any(n.startswith("source/solutions/") for n in names), "the bundle needs the solutions"
assert not any(n.split("/")[1].startswith("build") for n in names if n.startswith("source/")), "build folders leaked"
print(f"the autograder bundle holds {len(names)} files, laid out as Gradescope expects")
PY
