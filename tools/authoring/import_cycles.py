#!/usr/bin/env python3
"""No Python module under tools/ may import, directly or through others, a module that imports it.

  import_cycles.py [ROOT]        exit 1 naming each cycle (a module is a .py file; `import x` and
                                 `from x import` name a sibling of the importing file, `from
                                 grading.x import` a module of the tools/grading package)
  import_cycles.py --self-test   prove a cycle of two is found
"""
import pathlib
import re
import sys
import tempfile

IMPORT = re.compile(r"^\s*(?:from\s+([\w.]+)\s+import|import\s+([\w.]+))", re.M)


def graph(tools):
    """{module path: set of module paths it imports}, for the .py files under `tools`."""
    edges = {}
    for f in sorted(tools.rglob("*.py")):
        targets = set()
        for m in IMPORT.finditer(f.read_text(errors="replace")):
            parts = (m.group(1) or m.group(2)).split(".")
            for base in (f.parent, tools):  # a sibling, or a package under tools/
                candidate = base.joinpath(*parts).with_suffix(".py")
                if candidate.is_file() and candidate != f:
                    targets.add(candidate)
                    break
        edges[f] = targets
    return edges


def cycles(tools):
    """Each cycle once, as a list of paths relative to tools/."""
    edges, found, seen = graph(tools), [], set()

    def walk(node, stack):
        for nxt in sorted(edges.get(node, ())):
            if nxt in stack:
                cycle = stack[stack.index(nxt):]
                key = frozenset(cycle)
                if key not in seen:
                    seen.add(key)
                    found.append([p.relative_to(tools).as_posix() for p in cycle])
            elif len(stack) < 32:
                walk(nxt, stack + [nxt])

    for start in sorted(edges):
        walk(start, [start])
    return found


def main(argv):
    if argv[1:2] == ["--self-test"]:
        with tempfile.TemporaryDirectory() as tmp:
            tools = pathlib.Path(tmp) / "tools"
            (tools / "a").mkdir(parents=True)
            (tools / "a" / "one.py").write_text("import two\n")
            (tools / "a" / "two.py").write_text("def f():\n    import one\n")
            found = cycles(tools)
        ok = found == [["a/one.py", "a/two.py"]]
        print(f"import_cycles --self-test: a cycle of two is {'found' if ok else 'NOT found: ' + str(found)}")
        return 0 if ok else 1
    root = pathlib.Path(argv[1]) if len(argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
    found = cycles(root / "tools")
    for c in found:
        print("import cycle: " + " -> ".join(c + c[:1]))
    print(f"import_cycles: {len(graph(root / 'tools'))} modules under tools/, {len(found)} cycles")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
