"""Packs the Blender add-on zip: cgtmo_addon/*.py, the built cgtmo module, and the scene
generator's modules (scripts/blender/*.py) under cgtmo_addon/generator/, so the add-on and the
generator share one implementation of the sidecar, probe camera and emitter formulas.

The add-on's bl_info "version" is written here from the CMake project version (--version), so the
add-on, the module and the CLI report one version; bl_info stays a literal that Blender reads with
ast without importing the add-on.

Run by the CMake target cgtmo_blender_addon (scripts/build_blender_addon.sh builds it)."""
import argparse
import ast
import glob
import os
import re
import sys
import zipfile

# The bl_info entry, e.g.  "version": (0, 1, 0),
VERSION_ENTRY = re.compile(r'("version"\s*:\s*)\(\s*\d+\s*,\s*\d+\s*,\s*\d+\s*\)')


def bl_info_of(source):
    """The bl_info dict of an add-on's __init__.py, read the way Blender reads it (ast, no import)."""
    for node in ast.parse(source).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "bl_info" for t in node.targets):
            return ast.literal_eval(node.value)
    return None


def with_version(source, version):
    """`source` (the add-on's __init__.py) with bl_info's version set to `version` ("1.2.3")."""
    parts = version.split(".")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        sys.exit("make_zip.py: --version must be MAJOR.MINOR.PATCH, not '%s'" % version)
    wanted = tuple(int(p) for p in parts)
    out, n = VERSION_ENTRY.subn(lambda m: m.group(1) + repr(wanted), source)
    info = bl_info_of(out) if n == 1 else None
    if not info or info.get("version") != wanted:
        sys.exit("make_zip.py: cannot set bl_info's version in the add-on's __init__.py "
                 "(expected one literal entry \"version\": (MAJOR, MINOR, PATCH))")
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--package", required=True, help="plugins/blender/cgtmo_addon")
    p.add_argument("--module", required=True, help="the built cgtmo.cpython-*.so")
    p.add_argument("--generator", required=True, help="scripts/blender")
    p.add_argument("--out", required=True, help="zip to write")
    p.add_argument("--version", required=True, help="the project version, MAJOR.MINOR.PATCH")
    a = p.parse_args()
    entries = []
    for f in sorted(glob.glob(os.path.join(a.package, "*.py"))):
        entries.append((f, "cgtmo_addon/" + os.path.basename(f)))
    entries.append((a.module, "cgtmo_addon/" + os.path.basename(a.module)))
    for f in sorted(glob.glob(os.path.join(a.generator, "*.py"))):
        entries.append((f, "cgtmo_addon/generator/" + os.path.basename(f)))
    with open(os.path.join(a.package, "__init__.py"), encoding="utf-8") as f:
        init = with_version(f.read(), a.version)  # checked before anything is written
    tmp = a.out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for src, arc in entries:
            if arc == "cgtmo_addon/__init__.py":
                z.writestr(arc, init)
            else:
                z.write(src, arc)
    os.replace(tmp, a.out)  # never a half-written zip
    print("wrote %s (%d files, %.1f MB)" % (a.out, len(entries), os.path.getsize(a.out) / 1e6))


if __name__ == "__main__":
    main()
