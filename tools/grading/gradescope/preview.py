#!/usr/bin/python3
"""A results.json as a student would see it on Gradescope, as one HTML page: the top-level output,
then each test a student can see now (visibility "visible"), its name, score and output, with the
output's Markdown (bold, code, fenced blocks, lists, images) turned into HTML the way Gradescope shows
it. PrairieLearn's results.json (tools/grading/prairielearn/results.py: it has "gradable") is shown
the way its <pl-external-grader-results> lays one out: the score and message, then each test's
name, points, message, output as plain text and images. For looking at what the grader writes, in a
browser or headless Chromium:

  tools/grading/gradescope/preview.py RESULTS_JSON OUT_HTML
"""
import html
import json
import re
import sys


def inline(text):
    text = html.escape(text, quote=False)
    text = re.sub(r"!\[([^\]]*)\]\((data:image/png;base64,[A-Za-z0-9+/=]+)\)",
                  r'<figure><img src="\2" alt="\1" style="max-width:100%"><figcaption>\1</figcaption></figure>', text)
    text = re.sub(r"\*\*([^*]+)\*\*", r"<b>\1</b>", text)
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", text)


def markdown(md):
    out, fenced, block = [], False, []
    for line in md.splitlines():
        if line.startswith("```"):
            if fenced:
                out.append("<pre>" + html.escape("\n".join(block)) + "</pre>")
                block = []
            fenced = not fenced
        elif fenced:
            block.append(line)
        elif line.startswith("- "):
            out.append("<li>" + inline(line[2:]) + "</li>")
        elif line.strip():
            out.append("<p>" + inline(line) + "</p>")
    return "\n".join(out)


STYLE = ("body{font-family:Helvetica,Arial,sans-serif;max-width:60em;margin:2em auto;color:#222}"
         "section{border:1px solid #ccc;border-left:6px solid #c33;margin:1em 0;padding:.2em 1em}"
         "section.ok{border-left-color:#3a3}h3 span{float:right;font-weight:normal}"
         "pre{background:#f4f4f4;padding:.6em;white-space:pre-wrap}img{border:1px solid #ccc}"
         "figcaption{font-size:80%;color:#666}")


def prairielearn_page(res):
    rows = []
    for t in res.get("tests", []):
        ok = t.get("points", 0) >= t.get("max_points", 0)
        figures = "".join(f'<figure><img src="{html.escape(i["url"])}" style="max-width:100%"><figcaption>'
                          f'{html.escape(i.get("label", "Figure"))}</figcaption></figure>' for i in t.get("images", []))
        rows.append(f"<section class={'ok' if ok else 'no'}><h3>{html.escape(t.get('name', ''))}<span>"
                    f"{t.get('points', 0)} / {t.get('max_points', 0)}</span></h3><p><i>{html.escape(t.get('message', ''))}"
                    f"</i></p>{'<pre>' + html.escape(t['output']) + '</pre>' if t.get('output') else ''}{figures}</section>")
    errors = "".join(f"<pre>{html.escape(e)}</pre>" for e in res.get("format_errors", []) if isinstance(e, str))
    return (f"<!doctype html><html><head><meta charset=utf-8><title>External grader results</title><style>{STYLE}"
            f"</style></head><body><h1>Score: {round(100 * res.get('score', 0))}%"
            f"{'' if res.get('gradable', True) else ' (invalid, not gradable)'}</h1><p>{html.escape(res.get('message', ''))}"
            f"</p>{errors}" + "\n".join(rows) + "</body></html>")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    res = json.load(open(sys.argv[1]))
    if "gradable" in res:
        open(sys.argv[2], "w").write(prairielearn_page(res))
        return
    rows = []
    for t in res.get("tests", []):
        if t.get("visibility", res.get("visibility", "visible")) != "visible":
            continue
        ok = t.get("status") == "passed"
        rows.append(f"<section class={'ok' if ok else 'no'}><h3>{html.escape(t.get('name', ''))}"
                    f"<span>{t.get('score', 0)} / {t.get('max_score', 0)}</span></h3>{markdown(t.get('output', ''))}"
                    "</section>")
    page = (f"<!doctype html><html><head><meta charset=utf-8><title>Autograder results</title><style>{STYLE}"
            "</style></head><body>"
            f"<h1>Autograder results</h1><div>{markdown(res.get('output', ''))}</div>" + "\n".join(rows) +
            "</body></html>")
    open(sys.argv[2], "w").write(page)


if __name__ == "__main__":
    main()
