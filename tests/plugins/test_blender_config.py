"""The Blender config cgtmo builds (Blender's own config with cgtmo's looks and views merged by
`cgtmo bake --into`) loses nothing of a saved .blend: a file saved under it, reopened under
Blender's own config, keeps every image's colour space and the view transform. The same round
trip under cgtmo's plain config (no Non-Color, no Filmic) is shown to lose them, so the check
can fail.

    test_blender_config.py --blender BLENDER --config MERGED.ocio --plain OURS.ocio --work DIR
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

# Saves a .blend with images in the spaces an artist uses and the Filmic view (argv after "--":
# the .blend path). Prints what it set, or the error Blender gives, as one JSON line.
SAVE = r'''
import bpy, json, sys
path = sys.argv[sys.argv.index("--") + 1]
got = {}
try:
    for name, space in (("albedo", "sRGB"), ("normal", "Non-Color"), ("hdr", "Linear")):
        img = bpy.data.images.new(name, 4, 4, float_buffer=(space == "Linear"))
        img.colorspace_settings.name = space
        img.use_fake_user = True
        got[name] = [img.colorspace_settings.name, bool(img.colorspace_settings.is_data)]
    bpy.context.scene.view_settings.view_transform = "Filmic"
    got["view"] = bpy.context.scene.view_settings.view_transform
except Exception as e:
    got["error"] = str(e).splitlines()[0]
bpy.ops.wm.save_as_mainfile(filepath=path)
print("RESULT " + json.dumps(got))
'''

# Opens the .blend and prints the spaces and view it holds.
CHECK = r'''
import bpy, json, sys
bpy.ops.wm.open_mainfile(filepath=sys.argv[sys.argv.index("--") + 1])
# Only the images SAVE made (Blender adds its own, such as "Render Result").
got = {i.name: [i.colorspace_settings.name, bool(i.colorspace_settings.is_data)] for i in bpy.data.images
       if i.name in ("albedo", "normal", "hdr")}
got["view"] = bpy.context.scene.view_settings.view_transform
print("RESULT " + json.dumps(got))
'''

EXPECTED = {"albedo": ["sRGB", False], "normal": ["Non-Color", True], "hdr": ["Linear", False], "view": "Filmic"}


def blender(exe, expr, blend, ocio, work):
    env = dict(os.environ)
    env["BLENDER_USER_SCRIPTS"] = os.path.join(work, "user", "scripts")
    env["BLENDER_USER_CONFIG"] = os.path.join(work, "user", "config")
    env.pop("OCIO", None)
    if ocio:
        env["OCIO"] = ocio
    p = subprocess.run([exe, "-b", "--factory-startup", "--python-exit-code", "3", "--python-expr", expr, "--", blend],
                       env=env, capture_output=True, text=True, timeout=300)
    lines = [l for l in p.stdout.splitlines() if l.startswith("RESULT ")]
    if p.returncode != 0 or not lines:
        sys.exit("blender failed (%d):\n%s%s" % (p.returncode, p.stdout[-2000:], p.stderr[-2000:]))
    return json.loads(lines[-1][len("RESULT "):])


def round_trip(a, config, name):
    blend = os.path.join(a.work, name + ".blend")
    saved = blender(a.blender, SAVE, blend, config, a.work)
    reopened = blender(a.blender, CHECK, blend, "", a.work)
    print("%s: set %s; reopened under Blender's config: %s" % (name, saved, reopened))
    return saved, reopened


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--blender", required=True)
    p.add_argument("--config", required=True)
    p.add_argument("--plain", required=True)
    p.add_argument("--work", required=True)
    a = p.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    failures = []
    saved, reopened = round_trip(a, os.path.abspath(a.config), "merged")
    if saved != EXPECTED:
        failures.append("under the merged config the spaces and view could not be set: %s" % saved)
    if reopened != EXPECTED:
        failures.append("saved under the merged config, reopened under Blender's: %s, expected %s" % (reopened, EXPECTED))
    # The plain config lacks Blender's spaces: the test would catch a Blender config that loses them.
    _, plain_reopened = round_trip(a, os.path.abspath(a.plain), "plain")
    if plain_reopened == EXPECTED:
        failures.append("cgtmo's plain config kept everything too: the check cannot tell the configs apart")
    for f in failures:
        print("FAIL " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
