"""The results of one submission: Gradescope's results.json (rewritten after every exercise),
junit.xml, report.md and report.html; what students see holds none of the grader's paths."""
import base64
import html
import json
import os
import re
from xml.sax.saxutils import escape, quoteattr

from .common import ROOT


def first_line(msg):
    """The diagnosis: the first line that starts at NOT IMPLEMENTED, WRONG or ERROR (gtest puts the
    test's file and line first), else the first line."""
    for line in msg.splitlines():
        for key in ("NOT IMPLEMENTED", "WRONG", "ERROR"):
            if key in line:
                return line[line.index(key):].strip()
    for line in msg.splitlines():
        if line.strip():
            return line.strip()
    return ""


def status_of(failures):
    text = " ".join(m for _, m in failures)
    return ("error" if "ERROR" in text else "wrong" if "WRONG" in text
            else "not implemented" if "NOT IMPLEMENTED" in text else "wrong")


# What students see on Gradescope holds none of the grader's paths or build commands (the instructor's
# report.md, report.html and junit.xml keep them): a line of make or of a compiler command goes, the
# student's own file is named as labs/NN_name/..., and any other path shrinks to its file name.
_BUILD_LINE = re.compile(r"^\s*(g?make(\[\d+\])?: |\[\s*\d+%\]|cd /|/usr/bin/(c\+\+|g\+\+|gcc|cc|clang|ld)\s|"
                         r"(/\S+/)?cmake (--build|-S|-E)\b|ninja: |Scanning dependencies|Consolidate compiler)")
_STUDENT_FILE = re.compile(r"(?:[\w.+-]*/)*(labs/\d\d_[\w-]+/[^\s:'\"()\[\],]+)")
_LONG_NUMBER = re.compile(r"(?<![\w.])-?\d+\.\d{8,}(?:[eE][-+]?\d+)?(?!\w)")
_ANY_PATH = re.compile(r"(?<![\w.~-])(?:/|(?:\.{1,2}|[\w.+-]+)/)(?:[^\s/:'\"()\[\],]+/)+([^\s/:'\"()\[\],]+)")


def _shrunk(path, name):
    """A path that is not the student's own: its file name, but never one that could be taken for the
    student's file (the solutions' exercise.cpp, quoted by an __has_include that probed them). The
    stubs as handed out (tests/stubs/, in every student's edition) are named as they are."""
    if path.startswith("labs/") or (path.startswith("tests/stubs/") and ".." not in path):
        return path
    return "(a file that is not yours)" if name.startswith("exercise") else name


def student_visible(text):
    """`text` without grader paths, build commands or absolute paths (see above). Whether a file that
    is not the student's exists is not told either: "Permission denied" reads as not found."""
    lines = [l for l in text.replace(str(ROOT) + "/", "").splitlines() if not _BUILD_LINE.search(l)]
    out = "\n".join(lines)
    out = _STUDENT_FILE.sub(r"\1", out)
    out = _ANY_PATH.sub(lambda m: _shrunk(m.group(0), m.group(1)), out)
    out = _LONG_NUMBER.sub(lambda m: f"{float(m.group(0)):.6g}", out)  # (gtest's 17 digits: 0.20000000298023224)
    return out.replace("Permission denied", "No such file or directory")


VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")
PICTURE_BYTES = 100 << 10  # a picture larger than this is left to the instructor's report
RESULTS_PICTURE_BYTES = 700 << 10  # what the pictures of one results.json may take, base64 included


def gradescope_visibility(visibility, points):
    """The visibility written for a test with `points`. Gradescope's specification: students do not see
    their total score while a test is hidden, but `hidden` tests do not count for that, since they are
    meant to carry no points; held-out points under `hidden` would show in the total, so such a test
    is written as after_published (shown when the instructor publishes the grades)."""
    if visibility not in VISIBILITIES:
        raise ValueError(f"visibility {visibility!r} is not one of {', '.join(VISIBILITIES)}")
    return "after_published" if visibility == "hidden" and points > 0 else visibility


class Results:
    def __init__(self, out_dir, name, labs, sandbox):
        self.out, self.name, self.labs, self.sandbox = out_dir, name, labs, sandbox
        self.entries = []  # one per exercise (and one per exercise's held-out tests)
        self.timing = {"build": 0.0, "tests": 0.0}
        self.problems = []  # what stopped the grading of some of it (build time-outs, grader failures)
        self.max_score = sum(e["points"] for l in labs for e in l["exercises"] if not e.get("extension"))
        self.write_json(partial=True)

    def fail_all(self, message):
        for lab in self.labs:
            for e in lab["exercises"]:
                self.add(lab, e, False, [("", message)], [], [])

    def fail_rest(self, message):
        """Every exercise that has no result yet fails with `message` (those graded keep theirs)."""
        graded = {(x["lab"], x["id"]) for x in self.entries}
        for lab in self.labs:
            for e in lab["exercises"]:
                if (lab["name"], e["id"]) not in graded:
                    self.add(lab, e, False, [("", message)], [], [])

    def add(self, lab, e, ok, failures, images, notes, hidden_result=None, hidden=False, explained=None):
        hidden_points = lab["hidden_points"].get(e["id"], 0) if hidden else 0
        visible_points = e["points"] - hidden_points
        bonus = " (extension: bonus points)" if e.get("extension") else ""
        entry = {"lab": lab["name"], "id": e["id"], "title": e["title"] + bonus, "points": visible_points,
                 "score": visible_points if ok else 0, "ok": ok, "failures": failures, "images": images,
                 "notes": notes, "visibility": "visible", "extension": bool(e.get("extension")),
                 "status": "done" if ok else status_of(failures), "explained": explained}
        self.entries.append(entry)
        if hidden:
            h_ok, h_failures = (hidden_result[0], hidden_result[1]) if hidden_result else (False, failures)
            self.entries.append({"lab": lab["name"], "id": e["id"], "title": e["title"] + " (held-out tests)",
                                 "points": hidden_points, "score": hidden_points if h_ok else 0, "ok": h_ok,
                                 "failures": h_failures, "images": [], "notes": [], "extension": False,
                                 "visibility": gradescope_visibility(lab["hidden_visibility"], hidden_points),
                                 "status": "done" if h_ok else status_of(h_failures)})
        self.write_json(partial=True)

    def score(self):
        return sum(x["score"] for x in self.entries)

    def entry_output(self, x, budget=None):
        """Markdown for Gradescope: the status, notes and first failures, without the grader's paths,
        then the pictures of its failing visible tests (a scene's three panels, a sweep's plot) inside
        it as data URIs, while `budget` (bytes, a one-item list shared by the whole results.json) lasts."""
        lines = [f"**{x['status']}**"] + [f"- {n}" for n in x["notes"]]
        explained = x.get("explained")
        if not x["ok"] and explained and explained["lines"]:  # check's own words for it (one definition)
            lines.append("\nWhat `./workbook check` says of it:\n```\n" + "\n".join(explained["lines"])[:4000] + "\n```")
            lines.append("\nThe failing tests:")
        for test, msg in x["failures"][:5]:
            lines.append(f"\n`{test}`\n```\n{msg.strip()[:2000]}\n```" if test else f"\n```\n{msg.strip()[:2000]}\n```")
        text = student_visible("\n".join(lines))
        if x["visibility"] != "visible" or budget is None:
            return text
        for test, label, name in x["images"]:
            path = self.out / "images" / name
            if test.startswith("Hidden") or not path.exists() or path.stat().st_size > PICTURE_BYTES:
                continue  # (a held-out test's picture would show its scene)
            data = base64.b64encode(path.read_bytes()).decode()
            if len(data) > budget[0]:
                text += "\n\n(more pictures in the instructor's report: this output has room for no more)"
                break
            budget[0] -= len(data)
            caption = ("reference, yours, difference" if name.endswith("panels.png") else
                       "yours against the reference" if label == "picture" else label)
            text += f"\n\n![{caption}](data:image/png;base64,{data})"
        return text

    def environment(self):
        """How the tests ran, for the instructor: a Gradescope test that students never see, with no
        points, failed when the isolation was weaker than intended (no network namespace in the
        container, tests not run as nobody)."""
        notes = self.sandbox.notes
        seed = getattr(self, "vary_seed", None)
        text = (f"Tests ran each exercise in its own process, in {self.sandbox.protections()}" +
                (f"; scenes varied with seed {seed} (WB_GRADE_SEED={seed} reproduces this grade)" if seed is not None
                 else "") + ".\n\n" +
                ("".join(f"- **{n}**\n" for n in notes) if notes else "- Isolation as intended: no network, an "
                 "unprivileged user."))
        return {"name": "Grading environment (instructors only)", "score": 0, "max_score": 0,
                "status": "failed" if notes else "passed", "output": text, "output_format": "md",
                "tags": ["grading-environment"], "visibility": "hidden"}

    def summary(self, partial):
        """The top-level output, which students always see: the points of the tests they can see now,
        never the total while held-out tests (after_due_date, after_published) are still hidden."""
        if partial:
            done = len({(x["lab"], x["id"]) for x in self.entries})
            total = sum(len(l["exercises"]) for l in self.labs)
            return f"Graded {done} of {total} exercises so far (grading stopped or is still running)."
        later = [x for x in self.entries if x["visibility"] != "visible" and x["points"] > 0 and not x["extension"]]
        seen = [x for x in self.entries if x["visibility"] == "visible"] if later else self.entries
        bonus = sum(x["score"] for x in seen if x["extension"])  # (on top of the maximum: said apart)
        plus = f" and {bonus} bonus points from extensions" if bonus else ""
        if later:
            text = (f"{sum(x['score'] for x in seen if not x['extension'])} of "
                    f"{sum(x['points'] for x in seen if not x['extension'])} points in the tests shown now{plus}. "
                    f"Held-out tests decide {sum(x['points'] for x in later)} more points; they and the total are "
                    "shown after the due date (or when grades are published).")
        else:
            text = f"{self.score() - bonus} of {self.max_score} points{plus}."
        return student_visible(text + "".join(f"\n\n**Note:** {p}." for p in self.problems))

    def write_json(self, partial, elapsed=0.0):
        """results.json, with only the keys of Gradescope's autograder specification (docs/gradescope.md).
        The top-level score is the total (the grade); Gradescope hides it from students while a test
        that carries points is not visible yet."""
        budget = [RESULTS_PICTURE_BYTES]  # (Gradescope's results.json stays under 1 MB)
        tests = [{"name": f"{x['id']} {x['title']}", "number": x["id"], "score": x["score"],
                  "max_score": 0 if x["extension"] else x["points"], "status": "passed" if x["ok"] else "failed",
                  "output": self.entry_output(x, budget), "output_format": "md", "visibility": x["visibility"]}
                 for x in self.entries]
        doc = {"score": self.score(), "output": self.summary(partial), "output_format": "md",
               "visibility": "visible", "stdout_visibility": "hidden",
               "extra_data": {"max_score": self.max_score, "student": self.name},
               "tests": tests + [self.environment()]}
        if not partial:
            doc["execution_time"] = round(elapsed, 1)
        tmp = self.out / "results.json.tmp"
        tmp.write_text(json.dumps(doc, indent=2))
        os.replace(tmp, self.out / "results.json")  # always a whole, valid file

    def finish(self, elapsed):
        self.write_json(partial=False, elapsed=elapsed)
        self.write_junit(elapsed)
        self.write_reports(elapsed)
        return {"name": self.name, "score": self.score(), "max_score": self.max_score, "entries": self.entries,
                "seconds": elapsed, "timing": self.timing, "problems": self.problems,
                "environment": list(self.sandbox.notes)}

    def write_junit(self, elapsed):
        parts = ['<?xml version="1.0" encoding="UTF-8"?>',
                 f'<testsuites name={quoteattr(self.name)} tests="{len(self.entries)}" '
                 f'failures="{sum(not x["ok"] for x in self.entries)}" time="{elapsed:.1f}">']
        for lab in self.labs:
            mine = [x for x in self.entries if x["lab"] == lab["name"]]
            parts.append(f'  <testsuite name="lab{lab["nn"]}" tests="{len(mine)}" '
                         f'failures="{sum(not x["ok"] for x in mine)}">')
            for x in mine:
                parts.append(f'    <testcase classname="lab{lab["nn"]}" name={quoteattr(x["id"] + " " + x["title"])}>')
                if not x["ok"]:
                    text = "\n\n".join(f"{t}\n{m}" for t, m in x["failures"])
                    parts.append(f'      <failure message={quoteattr(first_line(text) or x["status"])}>'
                                 f'{escape(text[:8000])}</failure>')
                parts.append("    </testcase>")
            parts.append("  </testsuite>")
        parts.append("</testsuites>")
        (self.out / "junit.xml").write_text("\n".join(parts) + "\n")

    def write_reports(self, elapsed):
        md = [f"# Grading report: {self.name}", "",
              f"**{self.score()} of {self.max_score} points** (graded in {elapsed:.0f} s: build "
              f"{self.timing['build']:.0f} s, tests {self.timing['tests']:.0f} s; tests ran as "
              f"{self.sandbox.user}, each exercise in its own process).", "",
              f"Sandbox: {self.sandbox.protections()}."]
        md += [f"- **isolation: {n}**" for n in self.sandbox.notes]
        md += [f"- **{p}**" for p in self.problems]
        body = [f"<h1>Grading report: {html.escape(self.name)}</h1>",
                f"<p><b>{self.score()} of {self.max_score} points</b> (graded in {elapsed:.0f} s)</p>"]
        body += [f"<p><b>{html.escape(p)}</b></p>" for p in self.problems]
        body += [f"<p><b>isolation: {html.escape(n)}</b></p>" for n in self.sandbox.notes]
        for lab in self.labs:
            mine = [x for x in self.entries if x["lab"] == lab["name"]]
            md += ["", f"## Lab {lab['nn']}: {lab['title']}", "", "| exercise | status | points |", "|---|---|---|"]
            md += [f"| {x['id']} {x['title']} | {x['status']} | {x['score']} / {x['points']} |" for x in mine]
            body.append(f"<h2>Lab {lab['nn']}: {html.escape(lab['title'])}</h2><table border=1 cellpadding=4>"
                        "<tr><th>exercise</th><th>status</th><th>points</th></tr>")
            body += [f"<tr><td>{x['id']} {html.escape(x['title'])}</td><td>{x['status']}</td>"
                     f"<td>{x['score']} / {x['points']}</td></tr>" for x in mine]
            body.append("</table>")
            for x in mine:
                if x["ok"] and not x["notes"]:
                    continue
                md += ["", f"### {x['id']} {x['title']}: {x['status']}"] + [f"- {n}" for n in x["notes"]]
                body.append(f"<h3>{x['id']} {html.escape(x['title'])}: {x['status']}</h3>")
                body += [f"<p>{html.escape(n)}</p>" for n in x["notes"]]
                for test, msg in x["failures"][:5]:
                    md += ["", f"`{test}`" if test else "", "```", msg.strip()[:3000], "```"]
                    body.append(f"<p><code>{html.escape(test)}</code></p><pre>{html.escape(msg.strip()[:3000])}</pre>")
                for test, label, img in x["images"]:
                    md.append(f"![{label}](images/{img})")
                    body.append(f"<figure style='display:inline-block'><img src='images/{img}' style='max-width:100%'>"
                                f"<figcaption>{label}</figcaption></figure>")
        (self.out / "report.md").write_text("\n".join(md) + "\n")
        (self.out / "report.html").write_text("<!doctype html><meta charset=utf-8><title>Grading report</title>"
                                              "<body style='font-family:sans-serif'>" + "\n".join(body) + "</body>\n")
