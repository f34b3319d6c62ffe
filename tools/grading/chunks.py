"""Exercise chunks (as in common/exercise/glsl_harness.cpp): finding an exercise's marked chunk, grading a
chunk alone in the stub's file, and what a failed build says about an exercise."""
import re
import shutil
import subprocess


def find_marker(text, ex_id):
    """Where exercise ex_id's marker is: the exact id ("// EXERCISE 01" is not 01.3's), or -1."""
    m = re.search(r"// EXERCISE " + re.escape(ex_id) + r"(?=[ \t\r\n:]|$)", text)
    return m.start() if m else -1


def chunk(text, ex_id):
    marker = f"// EXERCISE {ex_id}"
    begin = find_marker(text, ex_id)
    if begin < 0:
        return None
    begin = text.rfind("\n", 0, begin) + 1
    end = text.find("// EXERCISE ", begin + len(marker))
    end = len(text) if end < 0 else text.rfind("\n", 0, end) + 1
    return begin, end


STUB_CODE = "stub of another exercise"


def keep_only_chunks(mine, stub, keep, path):
    """The student's whole file (helpers above the first marker included) with every exercise chunk
    whose id is not in `keep` swapped for the stub's (public code: no solution text is ever compiled
    with a student's; the judge runs the solution's code for those exercises anyway). The file is
    written at `path`; #line keeps compiler messages on the student's line numbers."""
    starts = [0 if p == 0 else mine.rfind("\n", 0, p) + 1 for p in
              (m.start() for m in re.finditer(r"// EXERCISE ", mine))]
    # (the stubs throw wb::NotImplemented, which the student's own includes may not declare)
    out = f'#include "common/base/error.hpp"\n#line 1 "{path}"\n' + mine[:starts[0] if starts else len(mine)]
    for k, begin in enumerate(starts):
        end = starts[k + 1] if k + 1 < len(starts) else len(mine)
        ex_id = re.match(r"[^\s:]+", mine[mine.index("// EXERCISE ", begin) + 12:])
        ex_id = ex_id.group(0) if ex_id else ""
        first = ex_id and mine.rfind("\n", 0, find_marker(mine, ex_id)) + 1 == begin  # the id's first marker
        theirs = chunk(stub, ex_id) if first and ex_id not in keep else None
        if not theirs:
            out += mine[begin:end]
            continue
        out += f'#line {stub.count(chr(10), 0, theirs[0]) + 1} "{STUB_CODE}"\n' + stub[theirs[0]:theirs[1]]
        out += ("" if out.endswith("\n") else "\n") + f'#line {mine.count(chr(10), 0, end) + 1} "{path}"\n'
    return out


# The lines of a failed build that say why: the compiler's errors and the linker's (a "multiple
# definition" or an "undefined reference", with the "in function" line before it); collect2's
# summary alone says nothing.
_ERROR_LINE = re.compile(r"error|Error|undefined reference|multiple definition|first defined here|: in function")


def demangle(text):
    """`text` with any mangled C++ name (_Z...) the linker printed turned readable (c++filt)."""
    names = sorted(set(re.findall(r"\b_Z\w+", text)))
    if not names or not shutil.which("c++filt"):
        return text
    r = subprocess.run(["c++filt"], input="\n".join(names), capture_output=True, text=True)
    for name, readable in zip(names, r.stdout.splitlines()):
        text = text.replace(name, readable)
    return text


def compiler_errors(output, limit=12):
    lines = [l for l in output.splitlines() if _ERROR_LINE.search(l) and not l.startswith("collect2:")]
    keep = lines[:limit] or output.strip().splitlines()[-limit:]
    return demangle("\n".join(l[:300] for l in keep))


BUILD_TIMED_OUT = "ERROR: the build timed out"
DEFAULT_BUILD_TIMEOUT = 300  # seconds for one build of a submission's code (--build-timeout)


def build_failure(output):
    """What a failed build says about an exercise: the time-out message as it is, else the compiler's errors."""
    return output if output.startswith(BUILD_TIMED_OUT) else compiler_errors(output)
