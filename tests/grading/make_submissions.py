#!/usr/bin/python3
"""Writes a class of synthetic submissions, made from the solutions, to test the grader:
./workbook make-submissions DIR [--labs 01,02]

  full                 every exercise solved: full marks
  stubs                the student edition as handed out: zero
  one_wrong            full, with one mutant (tests/mutants) applied: loses that exercise only
  compile_error        full, with a C++ syntax error in one exercise: loses that exercise only
  segfault             full, with a null-pointer write in one C++ exercise
  endless_loop_cpp     full, with a loop that never ends in one C++ exercise
  endless_loop_glsl    full, with a loop that never ends in one GLSL exercise
  endless_build        full, with legal C++ in one exercise that takes GCC a quarter of an hour to
                       compile: its build runs into the grader's --build-timeout (the build of every
                       lab it touched, of its lab when it touched others too, of that exercise alone)
                       and loses that exercise
  archive.zip          full, zipped inside a top folder (as students upload it), missing one file

The red team (cheats score zero; honest oddities score full marks):
  forged_report        the stubs, plus C++ that forges every "passed" a runner could claim: a gtest
                       JSON report at exit, "PASSED" on stdout, exit code 0, files in its folder
  daemon               full, plus a process forked at start-up that never ends: it must not
                       outlive grading
  flood                full, plus 100 MB printed by one exercise
  empty_glsl           full, with an empty exercise.glsl: its exercises are lost, never graded
                       as the solution
  markers_removed      full, with the GLSL markers renamed: the whole file is graded (full marks)
  helpers_outside      full, with a GLSL helper above the first marker that an exercise calls
  crlf_bom             full, with Windows line ends and a UTF-8 byte-order mark in both files
  symlink              full, with exercise.cpp a link to the solution's: not followed, the stub is
                       graded
  include_solutions    the stubs, with exercise.cpp including the solution's (relative and absolute
                       paths, where __has_include finds one): nothing to include, the stub is graded
  leak_secrets         full, with C++ that looks for the solutions, the held-out tests and the
                       judge's build from its own path, in Gradescope's /autograder/source and in
                       PrairieLearn's /grade/serverFilesCourse, and throws what it finds: it finds nothing,
                       so full marks, and no output holds a line of them
  write_other          full, with C++ that tries to write a file into every folder it can reach
                       (other students' results, tapes, builds): full marks, and no such file
                       anywhere once grading ends
  drirc_poison         full, with C++ that leaves a Mesa configuration in /tmp/.drirc which would
                       stop the judge's OpenGL context: full marks, and every later submission too
  tests/grading/redteam/*  cheats a reviewer wrote (see its README), when lab 01 is in the class
  tests/grading/redteam.py     the second red team's cheats on the sandbox: GLSL includes of the reference,
                       a C++ include of a second copy (--second-copy DIR), IPC and /tmp smuggling,
                       memory and fork bombs, an endless loop that leaves the result as it was, a
                       link error; and the weakest sandbox's: /proc snooping, a daemon that forges
                       results, a FIFO swapped into the tape (see its doc)
--only NAME,NAME keeps those submissions alone.

DIR/expected.json gives the score each should get and the exercises it should lose, computed from
labs/*/exercises.json: the grader is held against it by tests/grading.
"""
import argparse
import json
import re
import shutil
import sys
import zipfile
from pathlib import Path

import redteam
from submission_tree import ROOT, edit, insert_after_marker, labs, prepend, remove_chunk, write_tree

FORGER = r"""
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>
namespace {
// Claims a pass every way a runner could: a gtest report wherever --gtest_output points, PASSED
// on stdout, files a grader might read, and exit code 0 whatever happened.
void forgeEverything() {
  std::ifstream cmdline("/proc/self/cmdline");
  std::string arg;
  while (std::getline(cmdline, arg, '\0')) {
    if (arg.rfind("--gtest_output=json:", 0) == 0)
      std::ofstream(arg.substr(20)) << "{\"tests\": 1, \"failures\": 0, \"testsuites\": [{\"name\": \"Lab\", "
                                       "\"testsuite\": [{\"name\": \"Ex_Forged\"}]}]}";  // one test, passed
  }
  for (const char* f : {"report.json", "results.json", "PASSED"}) std::ofstream(f) << "{\"score\": 100}";
  std::printf("[  PASSED  ] 999 tests.\n");
  std::fflush(stdout);
  _exit(0);
}
const int forged = std::atexit(forgeEverything);
}  // namespace
"""

DAEMON = r"""
#include <unistd.h>
namespace {
// A process that outlives its parent: grading must end it.
const int daemonStarted = [] {
  if (fork() == 0) {
    setsid();
    for (;;) sleep(1);
  }
  return 0;
}();
}  // namespace
"""

FLOOD = r"""
#include <cstdio>
#include <string>
#include <errno.h>
namespace {
// 100 MB on stdout from the test binary (the runner), once.
const int flooded = [] {
  if (std::string(program_invocation_short_name).find("_tests") == std::string::npos) return 0;
  const std::string line(1023, 'x');
  for (int i = 0; i < 100 * 1024; ++i) std::printf("%s\n", line.c_str());
  return 0;
}();
}  // namespace
"""


INCLUDER = r"""// Includes the solution's file wherever it might be, else is the stub.
#if __has_include("../../../../../solutions/@LAB@/exercise.cpp")
#include "../../../../../solutions/@LAB@/exercise.cpp"
#elif __has_include("../../../../solutions/@LAB@/exercise.cpp")
#include "../../../../solutions/@LAB@/exercise.cpp"
#elif __has_include("@ROOT@/solutions/@LAB@/exercise.cpp")
#include "@ROOT@/solutions/@LAB@/exercise.cpp"
#elif __has_include("/autograder/source/solutions/@LAB@/exercise.cpp")
#include "/autograder/source/solutions/@LAB@/exercise.cpp"
#else
@STUB@
#endif
"""

LEAKER = r"""
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
namespace {
// Looks for the instructor's files above its own executable, and where Gradescope and PrairieLearn
// keep them, and throws whatever it can read.
void leakSecrets() {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> dirs = {"/autograder/source", "/grade/serverFilesCourse/shadow-workbook/workbook"};
  for (fs::path d = fs::read_symlink("/proc/self/exe", ec).parent_path(); !d.empty() && dirs.size() < 10;
       d = d.parent_path())
    dirs.push_back(d);
  for (const fs::path& dir : dirs) {
    for (const char* rel : {"solutions/@LAB@/exercise.cpp", "solutions/@LAB@/shaders/exercise.glsl",
                            "tests/hidden/@LAB@/heldout_test.cpp", "tests/hidden/@LAB@/scenes/heldout.json",
                            "tests/mutants", "build/mutants/@LAB@", "build-grade/judge", ".git/config"}) {
      std::ifstream in(dir / rel);
      std::stringstream text;
      if (in && text << in.rdbuf() && !text.str().empty()) throw std::runtime_error("LEAKED " + text.str());
      if (fs::is_directory(dir / rel, ec))
        for (auto it = fs::recursive_directory_iterator(dir / rel, ec); it != fs::recursive_directory_iterator();
             it.increment(ec))
          if (std::ifstream f{it->path()}; f && it->is_regular_file(ec) && text << f.rdbuf() && !text.str().empty())
            throw std::runtime_error("LEAKED " + text.str());
    }
  }
}
}  // namespace
"""

INTRUDER = r"""
#include <filesystem>
#include <fstream>
namespace {
// Tries to leave a file in every folder it can reach from above its own executable.
const int intruded = [] {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path top = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (int up = 0; up < 4 && top.has_parent_path(); ++up) top = top.parent_path();
  int seen = 0;
  for (auto it = fs::recursive_directory_iterator(top, fs::directory_options::skip_permission_denied, ec);
       it != fs::recursive_directory_iterator() && seen < 20000; it.increment(ec), ++seen)
    if (it->is_directory(ec)) std::ofstream(it->path() / "WB_INTRUDER") << "written by another student\n";
  return 0;
}();
}  // namespace
"""


DRIRC = r"""
#include <fstream>
namespace {
// Leaves a Mesa configuration where a process with HOME=/tmp would read it: the solution's app,
// without GL_ARB_gpu_shader5 (part of 4.0), cannot make the OpenGL 4.1 context the judge needs.
const int poisoned = [] {
  std::ofstream("/tmp/.drirc") << "<driconf><device><application name=\"judge\" executable=\"lab01_solution\">"
                                  "<option name=\"mesa_extension_override\" value=\"-GL_ARB_gpu_shader5\" />"
                                  "</application></device></driconf>\n";
  return 0;
}();
}  // namespace
"""


def red_team(out, full, expect, cpp, glsl, points, the_labs):
    """The cheats and the honest oddities (see the module's doc)."""
    lab, e_cpp = cpp
    glsl_lab, e_glsl = glsl
    lab_ex = dict(the_labs)[glsl_lab]
    glsl_ids = [e["id"] for e in lab_ex if e["file"] == e_glsl["file"]]
    cpp_ids = [e["id"] for e in dict(the_labs)[lab] if e["file"] == e_cpp["file"]]
    write_tree(out / "forged_report", lambda name: ROOT / "labs" / name, the_labs)
    prepend(out / "forged_report", lab, e_cpp["file"], FORGER)
    expect("forged_report", list(points))
    for name, code in (("daemon", DAEMON), ("flood", FLOOD)):
        prepend(full(name), lab, e_cpp["file"], code)
        expect(name, [])
    d = full("empty_glsl")
    (d / "labs" / glsl_lab / e_glsl["file"]).write_text("")
    expect("empty_glsl", glsl_ids)
    d = full("markers_removed")
    path = d / "labs" / glsl_lab / e_glsl["file"]
    path.write_text(path.read_text().replace("// EXERCISE ", "// exercise "))
    expect("markers_removed", [])
    d = full("helpers_outside")
    path = d / "labs" / glsl_lab / e_glsl["file"]
    text = path.read_text()
    first = text.rfind("\n", 0, text.index("// EXERCISE ")) + 1
    path.write_text(text[:first] + "float studentHelperHalf(float x) { return 0.5 * x; }\n\n" + text[first:])
    edit(d, glsl_lab, e_glsl["file"], glsl_ids[-1], "  float helped = studentHelperHalf(2.0);\n")
    expect("helpers_outside", [])
    d = full("crlf_bom")
    for rel in (e_cpp["file"], e_glsl["file"]):
        path = d / "labs" / lab / rel
        path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes().replace(b"\n", b"\r\n"))
    expect("crlf_bom", [])
    d = full("symlink")
    target = d / "labs" / lab / e_cpp["file"]
    target.unlink()
    target.symlink_to(ROOT / "solutions" / lab / e_cpp["file"])
    expect("symlink", cpp_ids)
    write_tree(out / "include_solutions", lambda name: ROOT / "labs" / name, the_labs)
    path = out / "include_solutions" / "labs" / lab / e_cpp["file"]
    stub = path.read_text()
    path.write_text(INCLUDER.replace("@LAB@", lab).replace("@ROOT@", str(ROOT)).replace("@STUB@", stub))
    expect("include_solutions", list(points))
    d = full("leak_secrets")
    prepend(d, lab, e_cpp["file"], LEAKER.replace("@LAB@", lab))
    edit(d, lab, e_cpp["file"], cpp_ids[0], "  leakSecrets();\n")
    expect("leak_secrets", [])
    prepend(full("write_other"), lab, e_cpp["file"], INTRUDER)
    expect("write_other", [])
    prepend(full("drirc_poison"), lab, e_cpp["file"], DRIRC)
    expect("drirc_poison", [])
    fixtures = ROOT / "tests/grading/redteam"
    for fixture in sorted(p for p in fixtures.iterdir() if (p / "expect.json").exists()) if fixtures.is_dir() else []:
        fixture_labs = [d.name for d in (fixture / "labs").iterdir()]
        if not all(l in dict(the_labs) for l in fixture_labs):
            continue
        write_tree(out / fixture.name, lambda name: ROOT / "labs" / name, the_labs)  # stubs for the other labs
        shutil.copytree(fixture / "labs", out / fixture.name / "labs", dirs_exist_ok=True)
        lost = json.loads((fixture / "expect.json").read_text())["lost"]
        expect(fixture.name, lost + [e["id"] for name, ex in the_labs if name not in fixture_labs for e in ex])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir")
    ap.add_argument("--labs", help="only these labs, e.g. 01,02")
    ap.add_argument("--second-copy", help="a folder holding a second copy of the solutions (solutions/NN_name/...), "
                                          "for the cpp_include_copy cheat")
    ap.add_argument("--only", help="only these submissions, e.g. full,flood")
    args = ap.parse_args()
    only = [x.strip().zfill(2) for x in args.labs.split(",")] if args.labs else None
    the_labs = labs(only)
    if not (ROOT / "solutions").is_dir():
        sys.exit("make-submissions: needs solutions/ (the instructor edition)")
    out = Path(args.dir)
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    points = {e["id"]: e["points"] for _, ex in the_labs for e in ex}
    max_score = sum(e["points"] for _, ex in the_labs for e in ex if not e.get("extension"))
    bonus = sum(e["points"] for _, ex in the_labs for e in ex if e.get("extension"))
    solution = lambda lab: ROOT / "solutions" / lab
    expected = {}

    def full(name):
        write_tree(out / name, solution, the_labs)
        return out / name

    def expect(name, lost):
        expected[name] = {"score": max_score + bonus - sum(points[i] for i in lost), "lost": sorted(lost)}

    full("full")
    expect("full", [])
    full("full_again")  # the same again: grading it must give the same results (check_batch.py)
    expect("full_again", [])
    write_tree(out / "stubs", lambda lab: ROOT / "labs" / lab, the_labs)
    expect("stubs", list(points))

    # Written against an earlier edition, before the bug hunts were added: every lab's solution with
    # its hunts' chunks gone, markers and all. Only the hunts are lost (their stubs, bug included,
    # are graded in their place); every other exercise keeps its points.
    d = full("earlier_edition")
    hunts = []
    for lab, exercises in the_labs:
        for e in exercises:
            if "H" in e["id"]:
                remove_chunk(d, lab, e["file"], e["id"])
                hunts.append(e["id"])
    if hunts:
        expect("earlier_edition", hunts)
    else:
        shutil.rmtree(d)

    # Exercises to break: the first C++ and the first GLSL exercise of the first lab that has both.
    cpp = next(((lab, e) for lab, ex in the_labs for e in ex if e["file"].endswith(".cpp")), None)
    glsl = next(((lab, e) for lab, ex in the_labs for e in ex if e["file"].endswith(".glsl")), None)

    mutant = next((m for lab, _ in the_labs for m in sorted((ROOT / "tests/mutants" / lab).glob("*.mutant"))), None)
    if mutant:
        fields = {"find": [], "replace": []}
        meta = {}
        for line in mutant.read_text().splitlines():
            m = re.match(r"^(exercise|file|find|replace): ?(.*)$", line)
            if m and m.group(1) in fields:
                fields[m.group(1)].append(m.group(2))
            elif m:
                meta[m.group(1)] = m.group(2)
        d = full("one_wrong")
        path = d / "labs" / mutant.parent.name / meta["file"]
        text = path.read_text()
        for f, r in zip(fields["find"], fields["replace"]):
            text = text.replace(f, r)
        path.write_text(text)
        expect("one_wrong", [meta["exercise"]])

    # The faults and cheats below work on the lab of the exercises they break; the class's other labs
    # stay the stubs (untouched: the grader neither builds nor runs them), which keeps the class quick.
    # ("full" and "one_wrong" above and the archive below are whole.)
    broken_labs = {pair[0] for pair in (cpp, glsl) if pair}  # (cpp, glsl: (lab, exercise) or None)
    others = {e["id"] for name, ex in the_labs if name not in broken_labs for e in ex}

    def full_one(name):
        write_tree(out / name, lambda lab: solution(lab) if lab in broken_labs else ROOT / "labs" / lab, the_labs)
        return out / name

    def expect_one(name, lost):
        expect(name, sorted(set(lost) | others))

    if cpp:
        lab, e = cpp
        d = full_one("compile_error")
        edit(d, lab, e["file"], e["id"], "  this is not C++;\n")
        expect_one("compile_error", [e["id"]])
        d = full_one("segfault")
        edit(d, lab, e["file"], e["id"], "  *static_cast<volatile int*>(nullptr) = 1;  // crash\n")
        expect_one("segfault", [e["id"]])
        d = full_one("endless_loop_cpp")
        edit(d, lab, e["file"], e["id"], "  for (volatile bool forever = true; forever;) {\n  }\n")
        expect_one("endless_loop_cpp", [e["id"]])
        d = full_one("endless_build")
        # Legal C++ that takes GCC a quarter of an hour or more to compile: 800 template
        # instantiations (under the default -ftemplate-depth of 900), each with a constant
        # expression of 1.5 million loop steps (under GCC 12's -fconstexpr-ops-limit of 2^25 for
        # one expression, about a second each), memory flat at ~20 MB. Put before the exercise's
        # function, in its chunk, so the grader's build of that exercise alone runs long too.
        insert_after_marker(d, lab, e["file"], e["id"], """\
template <int N>
constexpr int compileTimeWork() {
  int s = N;
  for (int i = 0; i < 1500; ++i)
    for (int j = 0; j < 1000; ++j) s = (s + (i ^ j)) & 1023;
  return s;
}
template <int N>
struct CompileTimeSteps {
  static_assert(compileTimeWork<N>() >= 0, "every step is a constant expression of its own");
  static constexpr int value = CompileTimeSteps<N - 1>::value + 1;
};
template <>
struct CompileTimeSteps<0> {
  static constexpr int value = 0;
};
static_assert(CompileTimeSteps<800>::value == 800, "800 steps");
""")
        expect_one("endless_build", [e["id"]])
    if glsl:
        lab, e = glsl
        d = full_one("endless_loop_glsl")
        # The loop reads and writes a parameter the function goes on to use, and whether it ends
        # depends on that value, so no compiler can drop it. In GLSL it never ends (the value steps
        # past 12345.678, then stalls at 2^24); on a GPU it hangs until the grader's time limit.
        # The workbook's loop guard (common/platform/loop_guard.hpp) stops an exercise's loops after
        # 50000 steps on any GL implementation, so the parameter comes out wrong instead: only this
        # exercise is lost.
        text = (d / "labs" / lab / e["file"]).read_text()
        signature = text[text.index(f"// EXERCISE {e['id']}"):].split("\n", 1)[1]
        kind, param = re.search(r"\w+\s*\(\s*(?:in\s+)?(\w+)\s+(\w+)", signature).groups()
        c = param if kind == "float" else f"{param}[0][0]" if kind.startswith("mat") else f"{param}.x"
        edit(d, lab, e["file"], e["id"], f"  while ({c} != 12345.678) {c} += 1.0;\n")
        expect_one("endless_loop_glsl", [e["id"]])

    # An upload as students make it: the whole folder zipped under a top folder, one file missing
    # (its stub is graded, so that file's exercises are lost).
    first_lab, first_ex = the_labs[0]
    missing = first_ex[-1]["file"]
    src = full("archive_tmp")
    (src / "labs" / first_lab / missing).unlink()
    (src / "README.txt").write_text("my work\n")
    with zipfile.ZipFile(out / "archive.zip", "w") as z:
        for p in sorted(src.rglob("*")):
            z.write(p, Path("my-workbook") / p.relative_to(src))
    shutil.rmtree(src)
    expect("archive", [e["id"] for e in first_ex if e["file"] == missing])

    if cpp and glsl:
        red_team(out, full_one, expect_one, cpp, glsl, points, the_labs)

        def stubs_of(name):
            write_tree(out / name, lambda lab: ROOT / "labs" / lab, the_labs)
            return out / name
        redteam.sandbox_cheats(out, full_one, expect_one, cpp, glsl, the_labs, stubs_of, args.second_copy, ROOT)
        redteam.weak_sandbox_cheats(out, full_one, stubs_of, expect_one, cpp, the_labs)

    if args.only:  # (the others are not kept)
        keep = set(args.only.split(","))
        for name in set(expected) - keep:
            path = out / (name + ".zip" if (out / (name + ".zip")).exists() else name)
            shutil.rmtree(path) if path.is_dir() else path.unlink(missing_ok=True)
            del expected[name]
    (out / "expected.json").write_text(json.dumps(expected, indent=2) + "\n")
    print(f"wrote {len(expected)} submissions to {out} (expected scores in expected.json)")
    if "endless_build" in expected:
        print("endless_build runs into the grader's build time limit two or three times: grade it with a low one, "
              "e.g. ./workbook grade --batch DIR --build-timeout 20")


if __name__ == "__main__":
    main()
