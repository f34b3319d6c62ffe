#!/usr/bin/python3
"""OpenGL 4.1 core is macOS's ceiling, and the workbook's one code path. This fails on any use
beyond it in the tracked sources (C++, GLSL files, and GLSL in C++ strings):
  - an entry point that 4.5 core has and 4.1 core lacks (glCreateTextures, glDispatchCompute, ...),
    found by generating both loaders with glad 2 (python3-glad) and comparing their functions
    (the committed loader, third_party/glad, is 4.1: such a call would not even compile);
  - #version 420 to 460;
  - GLSL and C++ of 4.2+: layout(binding = N) (bind with glUniform1i), shader storage buffers,
    image load/store, compute shaders.
A line that says "gl41-optional" is not counted: it runs only where a run-time check found the
feature (the KHR_debug callback).

Usage: tools/platforms/gl41_check.py [--list] [--self-test]
  --list       every use, file:line: what
  --self-test  scan a made-up file with one of each and check that every one is found
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SOURCES = ("common", "labs", "solutions", "tests", "tools", "shaders")
SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".glsl", ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"}
# GLSL and GL features beyond 4.1 that are not entry points (name, pattern).
FEATURES = [
    ("#version 4x0", re.compile(r"#\s*version\s+4[2-6]0\b")),
    ("layout(binding)", re.compile(r"\blayout\s*\([^)]*\bbinding\s*=")),
    ("shader storage buffer", re.compile(r"\bstd430\b|\bGL_SHADER_STORAGE_BUFFER\b")),
    ("image load/store", re.compile(r"\b(imageLoad|imageStore|imageAtomic\w*|image[123]D\w*)\s*[(\s]")),
    ("compute shader", re.compile(r"\bGL_COMPUTE_SHADER\b|\blocal_size_x\b")),
]


def core_functions(version, out):
    """The functions of glad's loader for `version` core with no extension."""
    subprocess.run(["/usr/bin/python3", "-m", "glad", "--quiet", "--api", f"gl:core={version}", "--extensions", "",
                    "--out-path", str(out), "--reproducible", "c"], check=True, capture_output=True)
    text = (out / "include/glad/gl.h").read_text()
    return set(re.findall(r"^#define (gl[A-Z]\w*) glad_gl", text, re.M))


def beyond_41():
    with tempfile.TemporaryDirectory() as tmp:
        return core_functions("4.5", Path(tmp) / "45") - core_functions("4.1", Path(tmp) / "41")


def scan(name, text, call):
    """(file, line, what) for every use in `text`."""
    found = []
    for n, line in enumerate(text.splitlines(), 1):
        if "gl41-optional" in line:  # used only where the context has it, behind a check
            continue
        found += [(name, n, m.group(1)) for m in call.finditer(line)]
        found += [(name, n, what) for what, pattern in FEATURES if pattern.search(line)]
    return found


def tracked_files():
    listed = subprocess.run(["git", "ls-files", "--", *SOURCES], cwd=ROOT, capture_output=True, text=True)
    if listed.returncode == 0:
        return listed.stdout.split()
    return [str(p.relative_to(ROOT)) for d in SOURCES for p in sorted((ROOT / d).rglob("*"))]  # (no git checkout)


def main():
    argv = sys.argv[1:]
    if any(a not in ("--list", "--self-test") for a in argv):
        sys.exit(__doc__)
    if subprocess.run(["/usr/bin/python3", "-c", "import glad.generator.c"], capture_output=True).returncode:
        print("gl41_check: skipped: /usr/bin/python3 has no glad 2 (Debian 12: sudo apt-get install python3-glad)")
        return 77
    names = beyond_41()
    call = re.compile(r"\b(" + "|".join(sorted(names, key=len, reverse=True)) + r")\s*\(")
    if "--self-test" in argv:
        made_up = ("glCreateTextures(GL_TEXTURE_2D, 1, &t);\n#version 450 core\n"
                   "layout(binding = 1) uniform sampler2D s;\nlayout(std430) buffer B { float v[]; };\n"
                   "imageStore(img, p, v);\nlayout(local_size_x = 8) in;\n"
                   "glDispatchCompute(1, 1, 1);  // gl41-optional\n#version 410 core\n")
        got = [w for _, _, w in scan("made_up", made_up, call)]
        want = ["glCreateTextures", "#version 4x0", "layout(binding)", "shader storage buffer", "image load/store",
                "compute shader"]
        if got != want:
            sys.exit(f"gl41_check --self-test: found {got}, expected {want}")
        print("gl41_check --self-test: every kind of use is found, and a gl41-optional line is not")
        return 0
    found = []
    for name in tracked_files():
        path = ROOT / name
        if path.suffix in SUFFIXES and path.is_file() and name != "tools/platforms/gl41_check.py":
            found += scan(name, path.read_text(errors="replace"), call)
    for f, n, what in found if "--list" in argv or found else []:
        print(f"{f}:{n}: {what}")
    print(f"gl41_check: {len(found)} uses beyond OpenGL 4.1 core")
    if found:
        print("gl41_check: the workbook stays within OpenGL 4.1 core (macOS's ceiling): bind to edit instead of "
              "direct state access, glUniform1i instead of layout(binding), no compute, no #version above 410")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
