"""A submission's tree of exercise files, written and edited in place: the helpers that
make_submissions.py and redteam.py share (neither imports the other's helpers, so there is no cycle)."""
import json
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def labs(only):
    out = []
    for manifest in sorted((ROOT / "labs").glob("*/exercises.json")):
        if only and manifest.parent.name[:2] not in only:
            continue
        out.append((manifest.parent.name, json.loads(manifest.read_text())["exercises"]))
    return out


def write_tree(dest, source_dir_of, the_labs):
    for lab, exercises in the_labs:
        for rel in sorted({e["file"] for e in exercises}):
            target = dest / "labs" / lab / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source_dir_of(lab) / rel, target)


def edit(dest, lab, rel, ex_id, transform):
    """Applies `transform` to the body of the first function inside exercise `ex_id`'s chunk."""
    path = dest / "labs" / lab / rel
    text = path.read_text()
    at = text.index(f"// EXERCISE {ex_id}")
    brace = text.index("{", text.index(")", at)) + 1  # the first function body after the marker
    # (a body on one line, as lab 04's solution writes 04.4, gets the new lines before its code)
    path.write_text(text[:brace] + "\n" + transform + text[brace:])


def prepend(dest, lab, rel, text):
    """Puts `text` at the top of the file, above every marker (where a student's helpers go)."""
    path = dest / "labs" / lab / rel
    path.write_text(text + path.read_text())


def insert_after_marker(dest, lab, rel, ex_id, text):
    """Inserts `text` on the line after exercise `ex_id`'s marker (in its chunk, before its code)."""
    path = dest / "labs" / lab / rel
    content = path.read_text()
    at = content.index("\n", content.index(f"// EXERCISE {ex_id}")) + 1
    path.write_text(content[:at] + text + content[at:])


def remove_chunk(dest, lab, rel, ex_id):
    """Takes exercise `ex_id`'s chunk out of the file, marker and all, as a file written before that
    exercise existed; a C++ file's closing "}  // namespace" stays."""
    path = dest / "labs" / lab / rel
    text = path.read_text()
    begin = text.rfind("\n", 0, text.index(f"// EXERCISE {ex_id}")) + 1
    end = text.find("// EXERCISE ", begin + 12)
    end = len(text) if end < 0 else text.rfind("\n", 0, end) + 1
    close = text.rfind("}  // namespace", begin, end)
    path.write_text(text[:begin] + (text[close:end] if close >= 0 else "") + text[end:])
