#!/usr/bin/env python3
"""Ubuntu 22.04's CMake, 3.22, kept honest: lists every command, keyword argument and generator
expression our CMake files use that this machine's CMake documentation marks as newer than 3.22
(".. versionadded:: 3.23" and later in /usr/share/cmake-*/Help), and the presets' schema version.
Exit 1 with each use named (file:line) where there is one.

usage: cmake_floor.py [ROOT] [--floor 3.22] [--help-dir DIR]
       cmake_floor.py --self-test     (a file that uses block(), FILE_SET and $<LINK_LIBRARY:...> must fail)

ImGui needs no list: Debian 12, where the suite builds, ships ImGui 1.86 itself, so any newer call
fails that build.
"""
import glob
import json
import os
import re
import sys
import tempfile

PRESET_SCHEMA = {2: (3, 20), 3: (3, 21), 4: (3, 23), 5: (3, 24), 6: (3, 25)}  # schema version -> CMake


def version(text):
    return tuple(int(x) for x in text.split(".")[:2])


def newer_keywords(rst, floor):
    """(command-level version or None, {KEYWORD: version}) for the versionadded markers past `floor`."""
    lines = open(rst, encoding="utf-8").read().splitlines()
    command, keywords = None, {}
    for k, line in enumerate(lines):
        m = re.match(r"\s*\.\. versionadded:: (\d+\.\d+)", line)
        if not m or version(m.group(1)) <= floor:
            continue
        v = version(m.group(1))
        if k < 6:  # right under the title: the whole command
            command = v
            continue
        following = next((lines[j] for j in range(k + 1, len(lines)) if lines[j].strip()), "")
        if not line.startswith(" ") and following.startswith(".. code-block::"):
            # A section of new signatures: their keywords that no earlier signature has.
            start = lines.index(following, k + 1) + 1
            end = next((j for j in range(start + 1, len(lines)) if lines[j].strip() and not lines[j][0].isspace()),
                       len(lines))
            earlier = set(re.findall(r"[A-Z][A-Z0-9_]+", "\n".join(l for l in lines[:k] if l.startswith("  "))))
            for word in re.findall(r"[A-Z][A-Z0-9_]+", "\n".join(lines[start:end])):
                if word not in earlier:
                    keywords.setdefault(word, v)
            continue
        previous = next((lines[j] for j in range(k - 1, -1, -1) if lines[j].strip()), "")
        found = re.findall(r"``([A-Z][A-Z0-9_]+)", previous) if previous.lstrip().startswith("``") else []
        indent = len(line) - len(line.lstrip())
        for j in range(k + 1, min(k + 8, len(lines))):  # the directive's own text
            if lines[j].strip() and len(lines[j]) - len(lines[j].lstrip()) <= indent:
                break
            found += re.findall(r"``([A-Z][A-Z0-9_]+)``", lines[j])
        for word in found:
            keywords.setdefault(word, v)
    return command, keywords


def newer_genexes(help_dir, floor):
    rst = os.path.join(help_dir, "manual", "cmake-generator-expressions.7.rst")
    out, name = {}, None
    for line in open(rst, encoding="utf-8").read().splitlines():
        m = re.match(r"\.\. genex:: \$<([A-Z_]+)", line)
        if m:
            name = m.group(1)
        m = re.match(r"\s+\.\. versionadded:: (\d+\.\d+)", line)
        if m and name and version(m.group(1)) > floor:
            out.setdefault(name, version(m.group(1)))
    return out


def calls(text):
    """(command, its arguments' words, line) for each command call in a CMake file."""
    text = re.sub(r"#[^\n]*", lambda m: " " * len(m.group(0)), text)  # (comments, kept in place)
    for m in re.finditer(r"(?m)^\s*([A-Za-z_][A-Za-z0-9_]*)\s*\(", text):
        depth, k = 1, m.end()
        while k < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[k], 0)
            k += 1
        yield m.group(1).lower(), re.findall(r"[A-Z][A-Z0-9_]+", text[m.end():k]), text.count("\n", 0, m.start()) + 1


def check(files, help_dir, floor):
    problems, cache = [], {}
    genexes = newer_genexes(help_dir, floor)
    for path in files:
        text = open(path, encoding="utf-8").read()
        for command, words, line in calls(text):
            rst = os.path.join(help_dir, "command", command + ".rst")
            if not os.path.exists(rst):
                continue  # (our own functions)
            if rst not in cache:
                cache[rst] = newer_keywords(rst, floor)
            since, keywords = cache[rst]
            if since:
                problems.append(f"{path}:{line}: {command}() is new in CMake {since[0]}.{since[1]}")
            for w in sorted(set(words) & set(keywords)):
                problems.append(f"{path}:{line}: {command}({w} ...) is new in CMake "
                                f"{keywords[w][0]}.{keywords[w][1]}")
        for m in re.finditer(r"\$<([A-Z_]+)", text):
            if m.group(1) in genexes:
                v = genexes[m.group(1)]
                problems.append(f"{path}:{text.count(chr(10), 0, m.start()) + 1}: $<{m.group(1)}> is new in "
                                f"CMake {v[0]}.{v[1]}")
    return problems


def main():
    args = sys.argv[1:]
    floor = version(args[args.index("--floor") + 1]) if "--floor" in args else (3, 22)
    helps = sorted(glob.glob("/usr/share/cmake-*/Help"))
    help_dir = args[args.index("--help-dir") + 1] if "--help-dir" in args else (helps[-1] if helps else "")
    if not os.path.isdir(os.path.join(help_dir, "command")):
        print("cmake_floor: no CMake documentation found (Debian's cmake-data has it in /usr/share/cmake-*/Help)")
        return 2
    if "--self-test" in args:
        with tempfile.TemporaryDirectory() as d:
            bad = os.path.join(d, "CMakeLists.txt")
            open(bad, "w").write("block()\nendblock()\ntarget_sources(x PRIVATE FILE_SET HEADERS FILES a.h)\n"
                                 "target_link_libraries(x PRIVATE $<LINK_LIBRARY:WHOLE_ARCHIVE,y>)\n"
                                 "file(COPY_FILE a b ONLY_IF_DIFFERENT)  # 3.21: allowed\n")
            found = check([bad], help_dir, floor)
            want = ["block()", "FILE_SET", "$<LINK_LIBRARY>"]
            missing = [w for w in want if not any(w in p for p in found)]
            wrong = [p for p in found if "COPY_FILE" in p or "ONLY_IF_DIFFERENT" in p]
            print("\n".join(found))
            if missing or wrong:
                print(f"cmake_floor self-test FAILED: missing {missing}, wrongly flagged {wrong}")
                return 1
            print(f"cmake_floor self-test: the three uses past {floor[0]}.{floor[1]} are named, the older one is not")
            return 0
    root = next((a for a in args if not a.startswith("--") and a not in (
        args[args.index(f) + 1] for f in ("--floor", "--help-dir") if f in args)), ".")
    files = [os.path.join(root, "CMakeLists.txt")] + sorted(glob.glob(os.path.join(root, "cmake", "*.cmake")))
    for pattern in ("common", "tests", "labs", "solutions", "tools", "third_party"):
        files += sorted(glob.glob(os.path.join(root, pattern, "**", "CMakeLists.txt"), recursive=True))
    problems = check(files, help_dir, floor)
    presets = json.load(open(os.path.join(root, "CMakePresets.json")))
    needs = PRESET_SCHEMA.get(presets.get("version"), (99, 0))
    if needs > floor:
        problems.append(f"CMakePresets.json: schema version {presets.get('version')} needs CMake {needs[0]}.{needs[1]}")
    declared = presets.get("cmakeMinimumRequired", {})
    if (declared.get("major", 0), declared.get("minor", 0)) > floor:
        problems.append(f"CMakePresets.json: cmakeMinimumRequired is past {floor[0]}.{floor[1]}")
    for p in problems:
        print(p)
    print(f"cmake_floor: {len(files)} CMake files and the presets against CMake {floor[0]}.{floor[1]} "
          f"(documentation: {help_dir}): {len(problems)} uses of anything newer")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
