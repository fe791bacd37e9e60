"""Blender started with our OCIO config (OCIO=ocio_config/config.ocio, set by run_blender.py
--ocio): Blender's own view transforms and looks list every registry operator (the panel shows
those properties), the add-on's display/view choices come from the same config, and a frame
tone-mapped by the add-on through that config equals `cgtmo apply` with it."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_common import args, cgtmo_cli, check, install_addon, passed, read_png, tiny_scene  # noqa: E402

A = args()
OUT = os.path.join(A.work, "out")


def main():
    config = os.environ.get("OCIO", "")
    check(os.path.exists(config), "Blender runs with OCIO=%s" % config)
    install_addon(A.zip)
    import cgtmo_addon.engine as engine
    import cgtmo_addon.properties as props
    scene = tiny_scene(os.path.join(OUT, "ocio_"))
    vs = scene.view_settings
    # Every per-pixel operator is a view and a look of the config (scene operators read passes: no view).
    for op in [o["name"] for o in engine.lib().operators() if o["scope"] == "pixel"]:
        vs.view_transform = op  # raises when Blender does not offer it
        check(vs.view_transform == op, "Blender offers the view " + op)
        vs.look = op
        check(vs.look == op, "Blender offers the look " + op)
    vs.view_transform, vs.look = "Standard", "None"
    s = scene.cgtmo
    views = [i[0] for i in props._view_items(s, bpy.context)]
    check("drago" in views and "Standard" in views, "the add-on's view choices come from $OCIO (%d)" % len(views))
    check(engine.lib().color_config()["origin"].endswith("($OCIO)"), "the module reads $OCIO")
    s.operator = "reinhard"
    s.view = "Standard"
    bpy.ops.render.render(write_still=False)
    exr, png = os.path.join(OUT, "ocio_0001.exr"), os.path.join(OUT, "ocio_0001.cgtmo.png")
    check(os.path.exists(png), "tone-mapped through $OCIO: " + s.last_message)
    ref = os.path.join(A.work, "cli.png")
    rc, text = cgtmo_cli(A.cgtmo, "apply", exr, "-o", ref, "--op", "reinhard", "--view", "Standard", "-q")
    check(rc == 0, "cgtmo apply with $OCIO: " + text.strip())
    diff = abs(read_png(png).astype(int) - read_png(ref).astype(int)).max()
    check(diff <= 1, "equals cgtmo apply within 1 code value (%d)" % diff)
    passed()


try:
    main()
except SystemExit:
    raise
except BaseException as e:
    import traceback
    traceback.print_exc()
    print("TEST FAILED: unexpected %s" % e, flush=True)
    sys.stdout.flush()
    os._exit(1)
