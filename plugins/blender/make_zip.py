"""Packs the Blender add-on zip: cgtmo_addon/*.py, the built cgtmo module, and the scene
generator's modules (scripts/blender/*.py) under cgtmo_addon/generator/, so the add-on and the
generator share one implementation of the sidecar, probe camera and emitter formulas.

Run by the CMake target cgtmo_blender_addon (scripts/build_blender_addon.sh builds it)."""
import argparse
import glob
import os
import zipfile


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--package", required=True, help="plugins/blender/cgtmo_addon")
    p.add_argument("--module", required=True, help="the built cgtmo.cpython-*.so")
    p.add_argument("--generator", required=True, help="scripts/blender")
    p.add_argument("--out", required=True, help="zip to write")
    a = p.parse_args()
    entries = []
    for f in sorted(glob.glob(os.path.join(a.package, "*.py"))):
        entries.append((f, "cgtmo_addon/" + os.path.basename(f)))
    entries.append((a.module, "cgtmo_addon/" + os.path.basename(a.module)))
    for f in sorted(glob.glob(os.path.join(a.generator, "*.py"))):
        entries.append((f, "cgtmo_addon/generator/" + os.path.basename(f)))
    tmp = a.out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for src, arc in entries:
            z.write(src, arc)
    os.replace(tmp, a.out)  # never a half-written zip
    print("wrote %s (%d files, %.1f MB)" % (a.out, len(entries), os.path.getsize(a.out) / 1e6))


if __name__ == "__main__":
    main()
