#!/usr/bin/env python3
"""No exercise's result reaches an array index, a loop bound or a divisor before the code has checked
that it is not a stub. NVIDIA inlines a GLSL stub, folds its -1 into the expression and rejects the
whole shader when that makes an index constant and out of bounds (error C1068): lab 10 did not start
until 10.5 was written, and only on NVIDIA (Mesa compiled it).

  stub_guard.py [ROOT]        exit 1 naming each finding (file:line, the variable, the use)
  stub_guard.py --self-test   prove that each kind of use is found and the checked forms pass

Scanned: labs/*/shaders/*, shaders/wb/* (GLSL); labs/*/main.cpp, common/shell/*.cpp (C++); the
exercise files (the students' answers) are read for what their functions' parameters reach. The
analysis is textual and line-ordered within a block. A variable is tainted when it is assigned from
an exercise's call (GLSL: a function of labs/*/shaders/exercise*; C++: labNN::f of exercise.hpp, or
the value `attempt("id", var, ...)` fills), or is the element of a range-for over one. A use is
`[... var ...]`, a for/while condition or range, the operand of / or %, or an argument that a
function of the scanned files passes on to such a use. A check is `var < 0` (>= 0, == -1, ...),
wbIsTodo(var), isTodo(var), `var < x.size()`, the attempt() that fills it, or a flag assigned from
that attempt(). It covers a use after it on the same line; the rest of the block when it is an
`if` whose body leaves (return, discard, continue, break, throw); else that `if`'s body. An exercise's
call written inside a use is a finding too. `// stub-checked: <why>` on the line or the line above
accepts a use: keep it rare.
"""
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from exercise_calls import exercise_functions  # (the C++ exercises of an exercise.hpp)

EXITS = re.compile(r"\b(return|discard|continue|break|throw)\b")
KEYWORDS = {"if", "for", "while", "switch", "return", "else", "do", "sizeof", "catch"}
# The commit whose cascades.glsl read u_splitNear[i] before testing i < 0 (the self-test finds it).
BROKEN_COMMIT = "6fa1769881bace64aec67cccc115a7d649098a64"
BROKEN_FILE = "labs/10_cascades/shaders/cascades.glsl"


def blank(text, strings):
    """`text` with comments, preprocessor lines and (C++) string contents as spaces, lines kept."""
    pattern = r"//[^\n]*|/\*.*?\*/|^[ \t]*#[^\n]*" + (r'|"(?:\\.|[^"\\\n])*"' if strings else "")

    def spaces(m):
        s = m.group(0)
        inner = re.sub(r"[^\n]", " ", s[1:-1] if s.startswith('"') else s)
        return f'"{inner}"' if s.startswith('"') else inner

    return re.sub(pattern, spaces, text, flags=re.S | re.M)


def matching(text, at):
    """The index just past the bracket that closes the one at `at` (len(text) when none does)."""
    close, depth = {"(": ")", "[": "]", "{": "}"}[text[at]], 0
    for k in range(at, len(text)):
        depth += (text[k] == text[at]) - (text[k] == close)
        if depth == 0:
            return k + 1
    return len(text)


def split_top(text, sep, base=0):
    """(begin, end) of each part of `text` between the `sep`s outside brackets, offset by `base`."""
    parts, depth, start = [], 0, 0
    for k, c in enumerate(text):
        depth += (c in "([{") - (c in ")]}")
        if c == sep and depth == 0:
            parts.append((base + start, base + k))
            start = k + 1
    return parts + [(base + start, base + len(text))]


class Source:
    """A file as statements, lines joined until their parentheses close: (start, end, the offsets
    of the `{` open at its start). A block is named by the offset of its `{`."""

    def __init__(self, text, strings):
        self.raw, self.text = text.split("\n"), blank(text, strings)
        self.stmts, self.ends, stack, depth, start, open_at = [], {}, [], 0, 0, ()
        for k, c in enumerate(self.text):
            if c == "{":
                stack.append(k)
            elif c == "}" and stack:
                self.ends[stack.pop()] = k
            depth += (c == "(") - (c == ")")
            if c == "\n" and depth <= 0 or k == len(self.text) - 1:
                self.stmts.append((start, k + 1, open_at))
                start, open_at = k + 1, tuple(stack)

    def line(self, offset):
        return self.text.count("\n", 0, offset) + 1

    def justified(self, line):
        """Whether `// stub-checked: <why>` is on the line, or alone on the line above."""
        above = self.raw[line - 2].strip() if line >= 2 else ""
        return "stub-checked:" in self.raw[line - 1] or above.startswith("//") and "stub-checked:" in above


def word(var):
    return r"(?<![\w.])" + re.escape(var) + r"(?!\w)"


def reaches(var, text):
    """Whether `var` is in `text` other than as a texture lookup's coordinate (a texel's value is
    not the coordinate's: the same shadow map at a stub's uv is no stub)."""
    for m in reversed(list(re.finditer(r"\b(?:texture|texel)\w*\s*\(", text))):
        text = text[:m.end()] + " " * (matching(text, m.end() - 1) - m.end()) + text[matching(text, m.end() - 1):]
    return re.search(word(var), text) is not None


def checks(var, flags):
    """A pattern of what checks `var` for a stub (or an unsigned one for its range)."""
    w, zero, minus1 = word(var), r"(?<![\w.])0(?:\.0*)?(?![\w.])", r"-\s*1(?![\w.])"
    forms = [w + r"\s*[<>]=?\s*" + zero, zero + r"\s*[<>]=?\s*" + w,
             w + r"\s*(?:<=|>|==|!=)\s*" + minus1, minus1 + r"\s*(?:>=|<|==|!=)\s*" + w,
             r"\b(?:wbIsTodo|isTodo)\s*\(\s*" + w, w + r"\s*(?:<|>=)\s*[\w.]+\.size\(\)",
             r'\battempt\s*\(\s*"[^"]*"\s*,\s*' + w]
    return re.compile("|".join(forms + [word(f) for f in flags]))


def uses(code, summaries):
    """(offset, begin, end, kind): each place in `code` whose value must not be a stub, as a span."""
    found = [(m.start(), m.start(), matching(code, m.start()), "an array index") for m in re.finditer(r"\[", code)]
    for m in re.finditer(r"\b(for|while)\s*\(", code):
        inner = split_top(code[m.end():matching(code, m.end() - 1) - 1], ";", m.end())
        if len(inner) == 1 and m.group(1) == "for":  # a range-for: the range
            inner = split_top(code[inner[0][0]:inner[0][1]], ":", inner[0][0])[-1:]
        found.append((m.start(),) + inner[1 if len(inner) == 3 else 0] + ("a loop bound",))
    for m in re.finditer(r"[/%]", code):
        k = m.end() + (code[m.end():m.end() + 1] == "=")
        k += len(code[k:]) - len(code[k:].lstrip())
        end = k + re.match(r"[\w.:]*", code[k:]).end()
        while end < len(code) and code[end] in "([":  # a call, a cast or a bracketed group
            end = matching(code, end)
        found.append((m.start(), k, end, "a divisor"))
    for m in re.finditer(r"\b(\w+)\s*\(", code):
        args = split_top(code[m.end():matching(code, m.end() - 1) - 1], ",", m.end())
        for p, kind in summaries.get(m.group(1), {}).items():
            if p < len(args):
                found.append((m.start(),) + args[p] + (f"{kind} via {m.group(1)}()",))
    return found


ASSIGN = re.compile(r"^\s*(?:[\w:<>,&*]+\s+)*?([A-Za-z_][\w.]*)\s*(?:\[[^\]]*\])?\s*=(?!=)(.*)$", re.S)
ATTEMPT = re.compile(r'\battempt\s*\(\s*"[^"]*"\s*,\s*([A-Za-z_][\w.]*)\s*(?:\[[^\]]*\])?\s*,')
RANGE_FOR = re.compile(r"\bfor\s*\(\s*[\w:<>&\s]+?(\w+)\s*:\s*([\w.]+)\s*\)")


def sources(code, calls):
    """What the statement taints, as (kind, var, what): ("taint", var, the exercise) for an
    assignment from an exercise's call or attempt()'s out-value; ("flag", flag, var) for a flag
    assigned from attempt(); ("element", var, container) for a range-for."""
    out = []
    for m in ATTEMPT.finditer(code):
        out.append(("taint", m.group(1), "attempt()"))
        if a := ASSIGN.match(code[:m.start()] + " "):
            out.append(("flag", a.group(1), m.group(1)))
    a = ASSIGN.match(code)
    if a and not out and not re.search(r"\battempt\w*\s*\(", a.group(2)) and (c := calls.search(a.group(2))):
        out.append(("taint", a.group(1), c.group(1)))
    if m := RANGE_FOR.search(code):
        out.append(("element", m.group(1), m.group(2)))
    return out


class Taint:
    def __init__(self, origin, block):
        self.origin, self.block = origin, block  # where the value came from; the block it lives in
        self.forever, self.in_block, self.next_stmt, self.flags = False, None, None, set()

    def cover(self, body, n):
        """Records what an `if` that checks this variable covers, given if_body()."""
        text, block, next_stmt = body
        if EXITS.search(text):
            self.forever = True
        elif block is not None:
            self.in_block = block
        elif next_stmt:
            self.next_stmt = n + 1


def if_body(src, stmts, n, start):
    """For an `if` statement: (its body's text, the block it opens, whether the body is the next
    statement); None for any other statement."""
    code = src.text[start:stmts[n][1]]
    m = re.match(r"\s*(?:\}\s*)?(?:else\s+)?if\s*\(", code)
    if not m:
        return None
    after = matching(code, m.end() - 1)
    rest = code[after:].strip()
    if rest.startswith("{"):
        at = start + code.index("{", after)
        return src.text[at:src.ends.get(at, len(src.text))], at, False
    if rest or n + 1 >= len(stmts):
        return rest, None, False
    return src.text[stmts[n + 1][0]:stmts[n + 1][1]], None, True


def analyse(src, calls, summaries, stmts=None, params=()):
    """Findings (line, var, use, origin) in `stmts` (default: the whole file). `params`: (name,
    block) tainted from the start, for a function's summary."""
    stmts = src.stmts if stmts is None else stmts
    taints, found = {p: Taint("parameter", block) for p, block in params}, []
    for n, (start, end, open_at) in enumerate(stmts):
        code = src.text[start:end]
        taints = {v: t for v, t in taints.items() if t.block is None or t.block in open_at}
        for kind, var, what in sources(code, calls):
            if kind == "taint":
                taints[var] = Taint(what, open_at[-1] if open_at else None)
            elif kind == "flag" and what in taints:
                taints[what].flags.add(var)
            elif kind == "element" and what in taints:
                taints[var] = Taint(f"an element of {what}", open_at[-1] if open_at else None)
        spans = uses(code, summaries)
        body = if_body(src, stmts, n, start)
        for var, t in taints.items():
            first = checks(var, t.flags).search(code)
            covered = t.forever or t.in_block in open_at or t.next_stmt == n
            for at, begin, finish, kind in spans:
                if not covered and not (first and first.start() < at) and reaches(var, code[begin:finish]):
                    found.append((src.line(start + at), var, kind, t.origin))
            if first and body:
                t.cover(body, n)
        for m in calls.finditer(code):  # an exercise's call written inside a use
            for at, begin, finish, kind in spans:
                if begin <= m.start() < finish:
                    found.append((src.line(start + m.start()), m.group(1) + "()", kind, "its call"))
    return sorted({f for f in found if not src.justified(f[0])})


FUNCTION = re.compile(r"^\s*(?:[\w:<>,&*]+\s+)+?[&*]?(\w+)\s*\(([^{;]*)\)\s*(?:const\s*)?(?:override\s*)?\{", re.S)


def functions(src):
    """(name, parameter names, the body's block, the body's statements) of each function defined."""
    for n, (start, end, open_at) in enumerate(src.stmts):
        m = FUNCTION.match(src.text[start:end])
        if not m or m.group(1) in KEYWORDS:
            continue
        at = start + m.end() - 1
        params = [re.sub(r"\[\[.*?\]\]|\[[^\]]*\]|=.*", "", m.group(2)[b - m.start(2):e - m.start(2)])
                  for b, e in split_top(m.group(2), ",", m.start(2))]
        names = [re.findall(r"\w+", p)[-1] for p in params if re.findall(r"\w+", p)]
        body = [(at + 1, end, open_at + (at,))] + [s for s in src.stmts[n + 1:] if at in s[2]]
        yield m.group(1), [p for p in names if p != "void"], at, body


def summarise(srcs, calls):
    """Per function name, the parameters (by position) that reach a use unchecked: a call passing a
    tainted value there uses it. Repeated until nothing changes (a call of a call)."""
    summaries = {}
    for _ in range(8):
        new = {}
        for src in srcs:
            for name, params, block, body in functions(src):
                for _, var, kind, origin in analyse(src, calls, summaries, body, [(p, block) for p in params]):
                    if origin == "parameter":
                        new.setdefault(name, {}).setdefault(params.index(var), kind)
        if new == summaries:
            break
        summaries = new
    return summaries


def report(path, findings):
    return [f"{path}:{line}: {var} ({'from ' + origin if origin != 'its call' else 'an exercise call'}) is used as "
            f"{kind} before a stub check" for line, var, kind, origin in findings]


def scan_group(root, files, calls, strings):
    """The findings in `files`, but for the exercise files: their functions are the students' answers
    (a correct pcss() divides by the depth of the blockers it has just found), read only for what
    their parameters reach."""
    srcs = {f: Source(f.read_text(errors="replace"), strings) for f in files}
    summaries = summarise(srcs.values(), calls)
    return [r for f, s in srcs.items() if not f.name.startswith("exercise")
            for r in report(f.relative_to(root).as_posix(), analyse(s, calls, summaries))]


GLSL_FUNCTION = re.compile(r"^(?:float|int|uint|bool|void|[iu]?vec[234]|mat[234])\s+(\w+)\s*\(", re.M)


def glsl_calls(root):
    files = sorted(root.glob("labs/*/shaders/exercise*"))
    names = {n for f in files for n in GLSL_FUNCTION.findall(blank(f.read_text(errors="replace"), False))}
    return re.compile(r"\b(" + "|".join(sorted(names - {"main"} - KEYWORDS)) + r")\s*\(")


def cpp_calls(root):
    per_lab = [f"lab{h.parent.name[:2]}::(?:{'|'.join(sorted(exercise_functions(h)))})"
               for h in sorted(root.glob("labs/[0-9][0-9]_*/exercise.hpp")) if exercise_functions(h)]
    return re.compile(r"\b(" + "|".join(per_lab) + r")\s*\(")


def scan(root):
    glsl = sorted(p for p in root.glob("labs/*/shaders/*") if p.is_file()) + sorted(root.glob("shaders/wb/*"))
    cpp = sorted(root.glob("labs/*/main.cpp")) + sorted(root.glob("common/shell/*.cpp"))
    return scan_group(root, glsl, glsl_calls(root), False) + scan_group(root, cpp, cpp_calls(root), True)


# Self-test snippets: (name, language, code, the findings expected as (line, var, what the use says)).
# Today's: the main() of cascades.glsl as it was, from its view depth to its stub check.
TODAY = """void main() {
  float depth = v_depth;
  vec4 splits = vec4(u_splits[0], u_splits[1], u_splits[2], u_splits[3]);
#ifdef WB_SELECT_MAP
  int i = cascadeByMap(v_world, u_cascades, u_count);
#else
  int i = cascadeByInterval(depth, splits, u_count);
#endif
  float w = i + 1 < u_count ? blendWeight(depth, u_splitNear[i], u_splits[i], u_band) : 0.0;
  if (u_ready == 0 || i < 0 || wbIsTodo(w)) {  // a stub: show it, never fake a shadow
    wbWriteOutputs(mix(albedo * 0.5, wbTodoPattern(gl_FragCoord.xy), 0.35), WB_TODO, v_world, true);
    return;
  }
}
"""
CASES = [
    ("today's cascades.glsl", "glsl", TODAY, [(9, "i", "an array index")]),
    ("today's, fixed", "glsl", """void main() {
  int i = cascadeByInterval(depth, splits, u_count);
  if (u_ready == 0 || i < 0) {
    writeTodo(albedo);
    return;
  }
  float w = i + 1 < u_count ? blendWeight(depth, u_splitNear[i], u_splits[i], u_band) : 0.0;
  if (wbIsTodo(w)) discard;
  float v = u_band / w;
}
""", []),
    ("loop bounds", "glsl", """void main() {
  int n = cascadeByMap(p, m, 4);
  for (int k = 0; k < n; ++k) a += 1.0;
  while (n > 0) --n;
}
""", [(3, "n", "a loop bound"), (4, "n", "a loop bound")]),
    ("loop bounds, checked", "glsl", """void main() {
  int n = cascadeByMap(p, m, 4);
  if (n == -1) return;
  for (int k = 0; k < n; ++k) a += 1.0;
}
""", []),
    ("divisors", "glsl", """void main() {
  float w = blendWeight(d, 0.0, 1.0, 0.1);
  float a = 1.0 / w;
  a /= (w + 1.0);
  int c = cascadeByInterval(d, s, 4);
  int r = 7 % c;
}
""", [(3, "w", "a divisor"), (4, "w", "a divisor"), (6, "c", "a divisor")]),
    ("divisors, checked", "glsl", """void main() {
  float w = blendWeight(d, 0.0, 1.0, 0.1);
  if (wbIsTodo(w))
    discard;
  float a = 1.0 / w;
  int c = cascadeByInterval(d, s, 4);
  int r = c >= 0 ? 7 % c : 0;
}
""", []),
    ("calls inside uses", "glsl", """void main() {
  float a = u_splits[cascadeByInterval(d, s, 4)];
  for (int k = 0; k < cascadeByMap(p, m, 4); ++k) a += 1.0;
  a = a / blendWeight(d, 0.0, 1.0, 0.1);
}
""", [(2, "cascadeByInterval()", "an array index"), (3, "cascadeByMap()", "a loop bound"),
      (4, "blendWeight()", "a divisor")]),
    ("through a function", "glsl", """bool inMap(int i) { return v_light[i].x < 1.0; }
float lookup(int i) {
  if (!inMap(i)) return 1.0;
  return 0.5;
}
void main() {
  int i = cascadeByMap(p, m, 4);
  float v = lookup(i);
  if (i < 0) return;
  v = lookup(i);
}
""", [(8, "i", "an array index via inMap() via lookup()")]),
    ("only inside the if", "glsl", """void main() {
  int i = cascadeByMap(p, m, 4);
  if (i >= 0) {
    a = u_splits[i];
  }
  b = u_splits[i];
}
""", [(6, "i", "an array index")]),
    ("justified", "glsl", """void main() {
  int i = cascadeByMap(p, m, 4);
  a = u_splits[i];  // stub-checked: the self-test says so
  // stub-checked: and so
  b = u_splits[i];
  c = u_splits[i];
}
""", [(6, "i", "an array index")]),
    ("C++ attempt, unchecked", "cpp", """bool castersOf(std::vector<bool>& drawn) {
  std::vector<uint32_t> kept;
  attempt("10.H2", kept, [&] { return lab10::castersFor(c, v, boxes); });
  for (uint32_t k : kept)
    drawn[k] = true;
  return true;
}
""", [(4, "kept", "a loop bound"), (5, "k", "an array index")]),
    ("C++ attempt, as lab 10 has it", "cpp", """bool castersOf(std::vector<bool>& drawn) {
  std::vector<uint32_t> kept;
  if (!attempt("10.H2", kept, [&] { return lab10::castersFor(cascade, view, sliceNear, sliceFar, boxes); }))
    return false;
  for (uint32_t k : kept)
    if (k < drawn.size()) drawn[k] = true;
  return true;
}
""", []),
    ("C++ flag", "cpp", """void f() {
  std::vector<float> s;
  const bool ok = attempt("10.1", s, [&] { return lab10::splitDistances(1, 2, 3, x, 0); });
  if (!ok) return;
  int n = 10 / int(s.size());
}
""", []),
]


def self_test(root):
    glsl = re.compile(r"\b(cascadeByInterval|cascadeByMap|blendWeight)\s*\(")
    cpp = re.compile(r"\b(lab10::(?:castersFor|splitDistances))\s*\(")
    failed = 0
    for name, language, code, expected in CASES:
        src = Source(code, language == "cpp")
        calls = cpp if language == "cpp" else glsl
        got = [(line, var, kind) for line, var, kind, _ in analyse(src, calls, summarise([src], calls))]
        ok = got == expected
        failed += not ok
        print(f"  {'ok  ' if ok else 'FAIL'} {name}" + ("" if ok else f": got {got}, expected {expected}"))
    try:  # today's file as it was, where git and that commit are here (not in a student's export)
        text = subprocess.run(["git", "-C", str(root), "show", f"{BROKEN_COMMIT}:{BROKEN_FILE}"], capture_output=True,
                              text=True, check=True).stdout
        where, expected = f"{BROKEN_FILE} at {BROKEN_COMMIT[:7]}", [(103, "i", "an array index")]
    except (OSError, subprocess.CalledProcessError):
        text, where, expected = TODAY, "the embedded copy of today's cascades.glsl", CASES[0][3]
    src = Source(text, False)
    found = [(line, var, kind) for line, var, kind, _ in analyse(src, glsl, summarise([src], glsl))]
    ok = found == expected
    failed += not ok
    print(f"  {'ok  ' if ok else 'FAIL'} {where}: {found or 'nothing found'}")
    print(f"stub_guard --self-test: {'every kind is found, and the checked forms pass' if not failed else 'FAILED'}")
    return 1 if failed else 0


def main(argv):
    root = pathlib.Path(__file__).resolve().parents[2]
    if argv[1:2] == ["--self-test"]:
        return self_test(root)
    root = pathlib.Path(argv[1]) if len(argv) > 1 else root
    found = scan(root)
    for f in found:
        print(f)
    print(f"stub_guard: {len(found)} exercise results used as an index, a loop bound or a divisor before a stub check")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
