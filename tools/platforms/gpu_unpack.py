"""Where a pack's tree goes on the target machine, and how it gets there (for gpu_check.py run).

The binaries have the build machine's absolute paths compiled in: add_lab() generates each variant's
kSourceDir, kLabDir, kShaderPath, kLabExe, kSolutionExe and kOutputDir (cmake/Lab.cmake,
common/base/variant.hpp), and the test list names commands, folders and ENVIRONMENT by absolute
path too. So the tree goes either at that very path (when it does not exist here and can be made:
nothing is changed), or at a path of the same length under /tmp, and every copy of the old path in
the executables is replaced byte for byte by the new one: a string of the same length, so no offset
in the binary moves. A shorter path (--at) is padded with slashes ("/tmp/////x" is "/tmp/x").
A real folder, not a symlink: a path that the code canonicalises would come out as the link's target,
and the messages that shorten paths by the root would no longer match.
Python 3.7 or newer, standard library only.
"""
import hashlib
import json
import os
import shutil
import sys
import tarfile

MARKER = ".gpu_check_unpacked"  # in the tree's root: this pack's id once unpacked whole
PREFIX = "/tmp/wb"


class Tree:
    """The unpacked tree: its source root and build folder here, the pack's library folders, and
    the (old, new) path pairs to apply to what names the old paths."""

    def __init__(self, root, build, mapping):
        self.root, self.build, self.mapping = root, build, mapping
        self.lib = os.path.join(root, ".gpu_check", "lib")
        self.compat = os.path.join(root, ".gpu_check", "compat")


def read_manifest(pack):
    path = os.path.join(pack, "manifest.json")
    try:
        with open(path) as f:
            return json.load(f)
    except OSError:
        sys.exit("gpu_check: %s is not a pack (no manifest.json); make one with gpu_check.sh pack" % pack)


def _marker(path):
    try:
        with open(os.path.join(path, MARKER)) as f:
            return f.read().strip()
    except OSError:
        return None


def _can_make(path):
    if os.path.lexists(path):
        return False
    try:
        os.makedirs(path)
        return True
    except OSError:
        return False


def _pad(path, length):
    """`path`, `length` characters long, padded with slashes before its last component."""
    if len(path) > length:
        sys.exit("gpu_check: --at %s is longer than the path the pack was built at (%d characters at most)"
                 % (path, length))
    cut = path.rstrip("/").rfind("/")
    return path[:cut] + "/" * (length - len(path)) + path[cut:]


def _tmp_twin(orig):
    """A /tmp path as long as `orig`, the same one for this user and path on every run (so a second
    run finds the tree unpacked), skipping paths that someone else holds."""
    room = len(orig) - len(PREFIX)
    if room < 1:
        sys.exit("gpu_check: the pack's path %s is too short to have a twin under /tmp; unpack it at that very "
                 "path (it must not exist) or pass --at with a path of at most %d characters" % (orig, len(orig)))
    for attempt in range(100):
        digest = ""
        while len(digest) < room:
            digest += hashlib.sha256(("%s %d %d %d" % (orig, os.getuid(), attempt, len(digest))).encode()).hexdigest()
        candidate = PREFIX + digest[:room]
        if not os.path.lexists(candidate) or _marker(candidate) is not None:
            return candidate
    sys.exit("gpu_check: no free /tmp path of %d characters; pass --at" % len(orig))


def choose(orig, at):
    """Where the tree built at `orig` goes here."""
    if at:
        return _pad(os.path.normpath(os.path.abspath(at)), len(orig))
    if _marker(orig) is not None or _can_make(orig):
        return orig
    return _tmp_twin(orig)


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _destination(tree, name):
    """Where the archive's member `name` goes: root/ and build/ are the two trees, lib/ and
    compat/ the libraries."""
    top, _, rest = name.partition("/")
    parts = rest.split("/")
    if not rest or name.startswith("/") or ".." in parts:
        sys.exit("gpu_check: the pack holds a bad path: %s" % name)
    base = {"root": tree.root, "build": tree.build, "lib": tree.lib, "compat": tree.compat}.get(top)
    if base is None:
        sys.exit("gpu_check: the pack holds an unknown path: %s" % name)
    return os.path.join(base, *parts)


def _extract(archive, tree):
    with tarfile.open(archive, "r:xz") as tar:
        for member in tar:
            dest = _destination(tree, member.name)
            if member.isdir():
                os.makedirs(dest, exist_ok=True)
            elif member.isfile():
                os.makedirs(os.path.dirname(dest), exist_ok=True)
                with tar.extractfile(member) as src, open(dest, "wb") as dst:
                    shutil.copyfileobj(src, dst, 1 << 20)
                os.chmod(dest, member.mode & 0o755 | 0o600)


def _patch(files, mapping):
    """Replaces each old path by its new one, of the same length, inside `files`."""
    pairs = [(old.encode(), new.encode()) for old, new in mapping]
    for path in files:
        with open(path, "rb") as f:
            data = f.read()
        patched = data
        for old, new in pairs:
            patched = patched.replace(old, new)
        if patched != data:
            with open(path, "wb") as f:
                f.write(patched)


def _places(manifest, at):
    """The tree's root and build folder here, and the (old, new) pairs, longest old path first."""
    root_was, build_was = manifest["root"], manifest["build"]
    root = choose(root_was, at)
    mapping = [(root_was, root)]
    if build_was.startswith(root_was + "/"):
        build = root + build_was[len(root_was):]
    else:  # (a build folder outside the source tree: a place of its own)
        build = choose(build_was, os.path.join(at, "build") if at else None)
        mapping.append((build_was, build))
    mapping = sorted([(o, n) for o, n in mapping if o != n], key=lambda p: -len(p[0]))
    return Tree(root, build, mapping)


def unpack(pack, manifest, at=None, fresh=False):
    """The tree of `pack`, unpacked (once: a second run finds it) where its binaries find it."""
    tree = _places(manifest, at)
    if _marker(tree.root) == manifest["sha256"] and not fresh:
        print("gpu_check: the tree is unpacked at %s already" % tree.root, flush=True)
        return tree
    archive = os.path.join(pack, manifest["archive"])
    if sha256(archive) != manifest["sha256"]:
        sys.exit("gpu_check: %s is damaged (its checksum is not the manifest's); copy the pack again" % archive)
    places = [tree.root] + ([] if tree.build.startswith(tree.root + "/") else [tree.build])
    for place in places:
        if _marker(place) is None and os.path.isdir(place) and os.listdir(place):
            sys.exit("gpu_check: %s holds files this tool did not unpack; it writes only into a new folder or one "
                     "of its own (pass --at with another)" % place)
        if _marker(place) is not None:  # (only a tree this tool unpacked is ever removed)
            shutil.rmtree(place)
        os.makedirs(place, exist_ok=True)
        with open(os.path.join(place, MARKER), "w") as f:
            f.write("unpacking\n")
    print("gpu_check: unpacking %s at %s%s" % (manifest["archive"], tree.root,
                                                "" if not tree.mapping else " (paths in the binaries changed from %s)"
                                                % manifest["root"]), flush=True)
    _extract(archive, tree)
    if tree.mapping:
        _patch([os.path.join(tree.build, e) for e in manifest["executables"]], tree.mapping)
    for place in places:
        with open(os.path.join(place, MARKER), "w") as f:
            f.write(manifest["sha256"] + "\n")
    return tree


def relocate(value, mapping):
    """`value` (a JSON value) with the old paths replaced by the new ones."""
    if isinstance(value, str):
        for old, new in mapping:
            value = value.replace(old, new)
        return value
    if isinstance(value, list):
        return [relocate(v, mapping) for v in value]
    if isinstance(value, dict):
        return {k: relocate(v, mapping) for k, v in value.items()}
    return value


def relocate_listing(listing, mapping):
    listing["tests"] = relocate(listing["tests"], mapping)
