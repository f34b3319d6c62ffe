"""The submissions and the manifests: which labs and exercise files there are, and how a
submission (a folder or an archive) is unpacked and searched for them, regular files only."""
import json
import os
import stat
import tarfile
import tempfile
import zipfile
from pathlib import Path

from .common import MAX_FILE_BYTES, ROOT
from .sandbox import run_killable


def is_hunt(exercise):
    """A bug hunt ("kind": "hunt", id NN.Hk): working code with a real bug, graded like any exercise."""
    return exercise.get("kind") == "hunt"


def load_labs(only=None, kinds="all"):
    """Every lab with its exercises (id, title, file, points, extension, kind) and its held-out tests.
    kinds: "all", "builds" (the exercises written into stubs) or "hunts" (the bug hunts alone), so that
    hunts can be an assignment of their own."""
    labs = []
    for manifest in sorted((ROOT / "labs").glob("*/exercises.json")):
        data = json.loads(manifest.read_text())
        lab = manifest.parent.name
        if only and lab[:2] not in only:
            continue
        hidden_file = ROOT / "tests/hidden" / lab / "hidden.json"
        hidden = json.loads(hidden_file.read_text()) if hidden_file.exists() else {"points": {}}
        exercises = [e for e in data["exercises"] if kinds == "all" or is_hunt(e) == (kinds == "hunts")]
        if not exercises:
            continue
        labs.append({"name": lab, "nn": lab[:2], "title": data.get("title", lab), "exercises": exercises,
                     "hidden_points": hidden.get("points", {}),
                     "hidden_visibility": hidden.get("visibility", "after_due_date")})
    if not labs:
        raise SystemExit("grade: no labs found" + (f" for --labs {','.join(only)}" if only else "") +
                         (f" with --exercises {kinds}" if kinds != "all" else ""))
    return labs


def student_files(lab):
    """The whitelisted files of a lab, relative to labs/NN_name."""
    return sorted({e["file"] for e in lab["exercises"]})


def fill_missing(tool, lab, rel, content):
    """A file written against an earlier edition of the lab: the exercises it lacks are taken from
    the stub, so only those are lost. `tool` is the judge build's wb_check, whose --fill-missing does it
    as `check` does (one implementation: common/exercise/exercise_chunks.hpp). Returns (content, the
    lines that say so); the content as it was where there is no stub or no tool."""
    stub = ROOT / "labs" / lab["name"] / rel
    if not stub.is_file() or not tool.is_file():
        return content, []
    with tempfile.TemporaryDirectory(prefix="fill-") as tmp:
        mine = Path(tmp) / Path(rel).name
        mine.write_bytes(content)
        code, out, _ = run_killable([str(tool), "--fill-missing", str(mine), str(stub), f"labs/{lab['name']}/{rel}",
                                     f"tests/stubs/{lab['name']}/{rel}", "grader"], 30, cwd=tmp)
        if code != 0:
            return content, []
        return mine.read_bytes(), [line for line in out.splitlines() if " predates exercise " in line]


# --- Submissions ----------------------------------------------------------------------------------
ARCHIVE_SUFFIXES = (".tar.gz", ".tgz", ".zip", ".tar")  # longest first: "x.tar.gz" is "x"


def archive_suffix(path):
    """The archive suffix of a file name (.zip, .tar, .tar.gz, .tgz, any case), or "" for none."""
    lower = path.name.lower()
    return next((s for s in ARCHIVE_SUFFIXES if lower.endswith(s) and len(lower) > len(s)), "")


def submission_name(path):
    """A student's name from a submission: the whole name less a known archive suffix, so that
    erin.smith.zip is "erin.smith" and erin.jones (a folder) is "erin.jones"."""
    suffix = archive_suffix(path) if path.is_file() else ""
    return path.name[:len(path.name) - len(suffix)] if suffix else path.name


def unique_names(subs):
    """{submission: name}: submission_name, with -2, -3, ... after a name that an earlier submission
    (in sorted order) already has (erin/ and erin.zip are "erin" and "erin-2"), so no result
    overwrites another."""
    names, taken = {}, set()
    for sub in sorted(subs):
        base = submission_name(sub)
        name, k = base, 2
        while name in taken:
            name, k = f"{base}-{k}", k + 1
        taken.add(name)
        names[sub] = name
    return names


def unpack(submission, scratch):
    """A folder to read the submission from (archives are extracted safely into scratch). A folder
    that holds nothing but one archive (an upload of a zip that was not unpacked) is that archive."""
    path = Path(submission)
    if path.is_dir():
        entries = [p for p in path.iterdir() if not p.name.startswith(".")]
        if len(entries) == 1 and entries[0].is_file() and not entries[0].is_symlink() and archive_suffix(entries[0]):
            path = entries[0]
        else:
            return path
    if not path.exists():
        raise ValueError(f"no such submission: {path}")
    dest = Path(tempfile.mkdtemp(prefix="submission-", dir=scratch))
    if zipfile.is_zipfile(path):
        with zipfile.ZipFile(path) as z:
            for info in z.infolist():
                target = (dest / info.filename).resolve()
                if not str(target).startswith(str(dest.resolve())) or info.file_size > 64 * MAX_FILE_BYTES:
                    continue  # a path outside the folder, or a huge member: ignored
                z.extract(info, dest)
    elif tarfile.is_tarfile(path):
        with tarfile.open(path) as t:
            members = [m for m in t.getmembers() if (m.isfile() or m.isdir()) and not m.name.startswith("/")
                       and ".." not in Path(m.name).parts and m.size <= 64 * MAX_FILE_BYTES]
            t.extractall(dest, members=members)
    else:
        raise ValueError(f"{path.name} is neither a folder nor a .zip/.tar archive")
    return dest


def regular_inside(path, folder):
    """True when `path` is a regular file reached from `folder` without following any link (a linked
    file or a linked folder on the way could point at the solutions)."""
    try:
        current = folder
        for part in path.relative_to(folder).parts:
            current = current / part
            if stat.S_ISLNK(os.lstat(current).st_mode):
                return False
        return stat.S_ISREG(os.lstat(path).st_mode)
    except (ValueError, OSError):
        return False


def find_student_file(folder, lab, rel, assignment_labs=None):
    """(path or None, note or None): the submission's copy of labs/<lab>/<rel>. It is looked for at
    that path under the folder or under one level of nesting (an archive with a top folder), then as
    the only file whose path ends with <lab>/<rel>, then as a flat upload: the file alone
    (exercise.cpp, exercise.glsl or shaders/exercise.glsl at the top of the upload), which belongs to
    the lab only when the assignment (assignment_labs, the names of the labs graded) has one lab;
    with several, a flat file is ambiguous and the note says so."""
    regular = lambda p: regular_inside(p, folder)
    bases = [folder] + sorted(d for d in folder.iterdir() if d.is_dir() and not d.is_symlink())
    for base in bases:
        candidate = base / "labs" / lab / rel
        if regular(candidate):
            return candidate, None
        if os.path.lexists(candidate):  # there, but a link (or not a file): never followed
            return None, f"labs/{lab}/{rel} is a link or not a regular file: it is not followed (submit the file itself)"
    matches = [p for p in folder.rglob(Path(rel).name) if p.as_posix().endswith(f"{lab}/{rel}") and regular(p)]
    if len(matches) == 1:
        return matches[0], None
    flat = next((p for base in bases for p in (base / rel, base / Path(rel).name) if regular(p)), None)
    if flat is None:
        return None, None
    shown = flat.relative_to(folder).as_posix()
    labs = list(assignment_labs or [])
    if labs == [lab]:
        return flat, f"{shown} (uploaded without its folder) is graded as labs/{lab}/{rel}"
    return None, (f"{shown} is in the upload without its folder, and this assignment grades labs "
                  f"{', '.join(l[:2] for l in labs)}: it cannot tell which lab it belongs to, so labs/{lab}/{rel} "
                  f"is not graded from it; upload it as labs/{lab}/{rel}")
