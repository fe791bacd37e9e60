"""The built Blender add-on zip carries the project version in bl_info, read the way Blender reads
it (ast, without importing the add-on), and make_zip.py refuses a source it cannot set it in.
    test_addon_zip.py --zip <build>/cgtmo_addon.zip --version MAJOR.MINOR.PATCH --make-zip plugins/blender/make_zip.py"""
import argparse
import ast
import importlib.util
import sys
import zipfile


def bl_info(source):
    for node in ast.parse(source).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "bl_info" for t in node.targets):
            return ast.literal_eval(node.value)
    return None


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--zip", required=True)
    p.add_argument("--version", required=True)
    p.add_argument("--make-zip", required=True)
    a = p.parse_args()
    fail = 0

    def check(name, ok):
        nonlocal fail
        print(("ok   " if ok else "FAIL ") + name)
        fail |= not ok

    with zipfile.ZipFile(a.zip) as z:
        info = bl_info(z.read("cgtmo_addon/__init__.py").decode("utf-8"))
    wanted = tuple(int(x) for x in a.version.split("."))
    check("the zip's bl_info version %s is the project version %s" % (info and info.get("version"), a.version),
          bool(info) and info.get("version") == wanted)

    spec = importlib.util.spec_from_file_location("make_zip", a.make_zip)
    make_zip = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_zip)
    source = 'bl_info = {\n    "name": "x",\n    "version": (0, 1, 0),\n    "blender": (3, 4, 0),\n}\n'
    check("with_version sets the version and leaves the blender entry",
          bl_info(make_zip.with_version(source, "2.10.3")) == {"name": "x", "version": (2, 10, 3), "blender": (3, 4, 0)})
    for bad_source, bad_version, what in ((source.replace('"version": (0, 1, 0),\n', ""), "1.2.3", "no version entry"),
                                          (source, "1.2", "a version of two numbers")):
        try:
            make_zip.with_version(bad_source, bad_version)
            refused = False
        except SystemExit as e:
            refused = bool(e.code) and str(e.code).startswith("make_zip.py: ")
        check("with_version refuses %s with a one-line error" % what, refused)
    return fail


if __name__ == "__main__":
    sys.exit(main())
