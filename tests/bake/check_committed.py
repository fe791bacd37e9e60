#!/usr/bin/python3
"""Re-bakes every operator into WORK and compares with the committed luts/, ocio_config/config.ocio
and docs/lut-accuracy.md byte for byte. Fails (exit 1) listing the files that differ: the committed files are
stale and must be regenerated with the command their headers name.

usage: check_committed.py CGTMO SOURCE_DIR WORK"""
import os, re, shutil, subprocess, sys

CANONICAL = "cgtmo bake --out-luts luts --out-config ocio_config --report docs/lut-accuracy.md"


def main():
    cgtmo, src, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    for d in ("luts", "ocio_config", "docs"):
        os.makedirs(os.path.join(work, d))
    args = ["--out-luts", "luts", "--out-config", "ocio_config", "--report", "docs/lut-accuracy.md"]
    r = subprocess.run([cgtmo, "bake", *args], cwd=work)
    if r.returncode != 0:
        print("cgtmo bake failed with exit code", r.returncode)
        return 1
    rebaked = sorted(os.listdir(os.path.join(work, "luts")))
    committed = sorted(f for f in os.listdir(os.path.join(src, "luts")) if f != "README.md")
    bad = []
    if rebaked != committed:
        bad.append("luts/ file list: committed %s, re-baked %s" % (sorted(set(committed) - set(rebaked)), sorted(set(rebaked) - set(committed))))
    pairs = [("luts/" + f, "luts/" + f) for f in rebaked if f in committed]
    pairs += [("ocio_config/config.ocio", "ocio_config/config.ocio"), ("docs/lut-accuracy.md", "docs/lut-accuracy.md")]
    for mine, theirs in pairs:
        a = open(os.path.join(work, mine), "rb").read()
        try:
            b = open(os.path.join(src, theirs), "rb").read()
        except FileNotFoundError:
            bad.append(theirs + " is missing")
            continue
        if a != b:
            bad.append(theirs)
    if bad:
        print("stale committed files (regenerate with: %s):" % CANONICAL)
        for b in bad:
            print("  " + b)
        return 1
    print("all %d committed files match a fresh bake" % len(pairs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
