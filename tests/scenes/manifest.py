#!/usr/bin/python3
"""The manifest of the committed renders: which scene scripts made them, and their checksums.

    /usr/bin/python3 tests/scenes/manifest.py --write   after regenerating (tests/scenes/render_all.sh)
    /usr/bin/python3 tests/scenes/manifest.py --check   (a ctest): fails when the scene definitions
                                                        changed since the renders, or a file did

The scene definitions are scripts/blender/scenes.py and scene_kit.py: editing either without
re-rendering makes the committed files stale. render_scene.py (command line, sidecar writing) is
not hashed; the sidecars record the command that made them.
"""
import glob
import hashlib
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCRIPTS = ["scripts/blender/scenes.py", "scripts/blender/scene_kit.py"]
MANIFEST = os.path.join(HERE, "MANIFEST.json")


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def current():
    files = sorted(glob.glob(os.path.join(HERE, "*", "*.exr")) + glob.glob(os.path.join(HERE, "*", "*.json")) +
                   glob.glob(os.path.join(HERE, "*.png")))
    return {
        "scripts": {s: sha256(os.path.join(ROOT, s)) for s in SCRIPTS},
        "files": {os.path.relpath(f, ROOT): {"bytes": os.path.getsize(f), "sha256": sha256(f)} for f in files},
    }


def main(argv):
    if argv == ["--write"]:
        with open(MANIFEST, "w") as f:
            json.dump(current(), f, indent=1, sort_keys=True)
            f.write("\n")
        print("wrote " + os.path.relpath(MANIFEST, ROOT))
        return 0
    if argv != ["--check"]:
        print(__doc__)
        return 2
    want = json.load(open(MANIFEST))
    have = current()
    problems = []
    for s, h in want["scripts"].items():
        if have["scripts"].get(s) != h:
            problems.append("%s changed since the renders were made: re-render (sh tests/scenes/render_all.sh), "
                            "then /usr/bin/python3 tests/scenes/manifest.py --write" % s)
    for f, rec in want["files"].items():
        got = have["files"].get(f)
        if got is None:
            problems.append("%s is missing" % f)
        elif got != rec:
            problems.append("%s differs from the manifest (%d bytes, expected %d)" % (f, got["bytes"], rec["bytes"]))
    for f in have["files"]:
        if f not in want["files"]:
            problems.append("%s is not in the manifest" % f)
    for p in problems:
        print("STALE: " + p)
    if not problems:
        print("%d files and %d scene scripts match the manifest" % (len(want["files"]), len(want["scripts"])))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
