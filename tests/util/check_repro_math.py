#!/usr/bin/python3
"""Every elementary function the library and the tool call comes from util/repro_math.h: glibc's
exp, log, pow, sin, ... differ by CPU in the last bit, and committed files must not. Fails naming
each call of a libm function (std:: or C) in src/ and apps/, comments and string literals aside.

usage: check_repro_math.py SOURCE_DIR"""
import os
import re
import sys

FUNCTIONS = ("exp exp2 expm1 log log2 log10 log1p pow sin cos tan asin acos atan atan2 sinh cosh tanh "
             "asinh acosh atanh cbrt hypot erf erfc lgamma tgamma").split()
CALL = re.compile(r"(?:std::|(?<![\w:.>]))(?:%s)[fl]?\s*\(" % "|".join(FUNCTIONS))
STRIP = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)


def blank(match):
    return re.sub(r"[^\n]", " ", match.group(0))


def main():
    root = sys.argv[1]
    hits = []
    for top in ("src", "apps"):
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".cpp", ".h", ".inc")) or name.startswith("repro_math."):
                    continue
                path = os.path.join(folder, name)
                code = STRIP.sub(blank, open(path, encoding="utf-8").read())
                for n, line in enumerate(code.split("\n"), 1):
                    if CALL.search(line):
                        hits.append("%s:%d: %s" % (os.path.relpath(path, root), n, line.strip()))
    if hits:
        print("libm calls outside util/repro_math (use cgtmo::repro::, see docs/numerics.md):")
        print("\n".join(hits))
        return 1
    print("no libm elementary function called in src/ or apps/")
    return 0


if __name__ == "__main__":
    sys.exit(main())
