"""Bad input for the Blender add-on, headless (run through run_blender.py, which also fails on
any Python traceback on the console): a scene without lights, a camera that is not perspective,
an unwritable output folder, a render cancelled halfway, and a sidecar that is not a JSON object.
Each gives one clear message, changes nothing in the scene when refused, and leaves no file behind."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from blender_common import args, check, install_addon, passed, tiny_scene  # noqa: E402

A = args()
OUT = os.path.join(A.work, "out")


def files():
    return sorted(os.listdir(OUT)) if os.path.isdir(OUT) else []


def prepare():
    """Calls Prepare scene as a script does: an operator that reports an ERROR makes bpy.ops raise
    RuntimeError carrying the message (the user who presses the button sees the report instead)."""
    try:
        return bpy.ops.cgtmo.prepare_scene(), ""
    except RuntimeError as e:
        return {"CANCELLED"}, str(e)


def untouched(vl, label):
    check(not vl.use_pass_position and not vl.use_pass_normal and len(vl.lightgroups) == 0
          and bpy.context.scene.render.image_settings.file_format == "PNG", label + ": the scene is unchanged")


def main():
    install_addon(A.zip)
    scene = tiny_scene(os.path.join(OUT, "bad_"))
    s = scene.cgtmo
    vl = bpy.context.view_layer
    s.operator = "cgtmo"

    # ---- no lights: remove the light and the strip's emission, and the world ------------------
    light = bpy.data.objects["Light"]
    strip = bpy.data.objects["Neon strip"]
    light.hide_render = True
    strip.hide_render = True
    world = scene.world
    scene.world = None
    r, err = prepare()
    check(r == {"CANCELLED"} and "the scene has no lights" in s.last_message and "the scene has no lights" in err,
          "no lights: refused with a message")
    untouched(vl, "no lights")
    check(files() == [], "no lights: nothing written")

    # world only: allowed, with a warning
    scene.world = world
    check(any(lvl == "WARNING" and "only the world emits" in m
              for lvl, m in __import__("cgtmo_addon.scene_prep", fromlist=["x"]).check_scene(scene, "cgtmo")),
          "world only: a warning, not a refusal")
    light.hide_render = False
    strip.hide_render = False

    # ---- a camera that is not perspective ------------------------------------------------------
    scene.camera.data.type = "ORTHO"
    r, err = prepare()
    check(r == {"CANCELLED"} and "needs a perspective camera" in s.last_message and "orthographic" in s.last_message,
          "orthographic camera: refused with a message")
    untouched(vl, "orthographic camera")
    scene.camera.data.type = "PANO"
    r, err = prepare()
    check(r == {"CANCELLED"} and "panorama" in s.last_message, "panoramic camera: refused with a message")
    scene.camera.data.type = "PERSP"
    check(files() == [], "camera errors: nothing written")

    # ---- an unwritable output folder (its parent is a file: unwritable even for root) --------
    os.makedirs(OUT, exist_ok=True)
    blocker = os.path.join(OUT, "a_file")
    open(blocker, "w").close()
    scene.render.filepath = os.path.join(blocker, "sub", "bad_")
    r, err = prepare()
    check(r == {"CANCELLED"} and "cannot write to the output folder" in s.last_message,
          "unwritable folder: Prepare scene refused with a message")
    untouched(vl, "unwritable folder")
    s.operator = "reinhard"
    s.last_message = ""
    bpy.ops.render.render(write_still=False)
    check(s.last_level == "ERROR" and "not tone-mapped" in s.last_message and "cannot write" in s.last_message,
          "unwritable folder: the render's tone-mapping reports it: " + s.last_message)
    check(files() == ["a_file"], "unwritable folder: nothing written")

    # ---- a render cancelled halfway --------------------------------------------------------------
    # Headless Blender cannot be interrupted mid-render, so the handler sequence of a cancelled
    # render (pre, cancel; no post/write/complete for the unfinished frame) is driven directly.
    from cgtmo_addon import handlers
    scene.render.filepath = os.path.join(OUT, "cancel_")
    handlers.on_render_pre(scene)
    handlers.on_render_cancel(scene)
    check(s.last_level == "WARNING" and "render cancelled" in s.last_message, "cancelled render: a message")
    check(files() == ["a_file"], "cancelled render: nothing written")
    # ... and the next render goes through normally.
    bpy.ops.render.render(write_still=False)
    check(os.path.exists(os.path.join(OUT, "cancel_0001.cgtmo.png")) and s.last_level == "INFO",
          "after a cancel the next render is tone-mapped")
    check(not [n for n in files() if n.startswith(".")], "no temporary files left")

    # ---- CG-TMO on a scene that was never prepared: the library says what is missing -----------
    from cgtmo_addon import engine as eng
    if hasattr(eng.lib(), "apply_scene"):
        s.operator = "cgtmo"
        scene.render.filepath = os.path.join(OUT, "unprepared_")
        bpy.ops.render.render(write_still=False)
        print("unprepared CG-TMO: %s: %s" % (s.last_level, s.last_message))
        check(s.last_level == "WARNING" and "no adaptation probe" in s.last_message and "no sidecar" in s.last_message,
              "CG-TMO without probe and sidecar: tone-mapped with the fallbacks, named in a warning")
        s.operator = "reinhard"

    # ---- a sidecar that is JSON but not an object: bad data, as in every face -----------------------
    if hasattr(eng.lib(), "apply_scene"):
        from cgtmo_addon import scene_prep
        s.operator = "cgtmo"
        scene.render.filepath = os.path.join(OUT, "badside_")
        for text, kind in (("[1, 2]", "an array"), ("null", "null"), ("42", "a number"), ('"text"', "a string")):
            with open(scene_prep.frame_base(scene, 1) + ".json", "w") as f:
                f.write(text)
            bpy.ops.render.render(write_still=False)
            check(s.last_level == "ERROR" and "not tone-mapped" in s.last_message
                  and "not a JSON object (%s)" % kind in s.last_message,
                  "CG-TMO, a sidecar that is %s: the frame is refused with the library's message: %s" % (kind, s.last_message))
            check(not os.path.exists(os.path.join(OUT, "badside_0001.cgtmo.png")), "... and nothing tone-mapped is written")
        s.operator = "reinhard"

    # ---- the UI path: jobs queued from the render thread, run by a main-thread timer ------------
    # (headless Blender runs no timers, so the queue is drained here by hand)
    scene.render.filepath = os.path.join(OUT, "queued_")
    handlers._submit(scene, 1, None, defer=True)
    check(len(handlers._queue) == 1 and bpy.app.timers.is_registered(handlers._drain_queue)
          and not os.path.exists(os.path.join(OUT, "queued_0001.cgtmo.png")), "UI path: the frame waits in the queue")
    bpy.app.timers.unregister(handlers._drain_queue)
    handlers._drain_queue()
    check(not handlers._queue and os.path.exists(os.path.join(OUT, "queued_0001.cgtmo.png")),
          "UI path: the timer's drain tone-maps it")
    check(bpy.ops.cgtmo.report(level="INFO", message="cgtmo report test") == {"FINISHED"},
          "the report operator the UI path uses")

    # ---- CG-TMO chosen while the module has no scene pipeline: a clear message, no output -------
    from cgtmo_addon import engine
    if not hasattr(engine.lib(), "apply_scene"):
        s.operator = "cgtmo"
        scene.render.filepath = os.path.join(OUT, "scene_")
        bpy.ops.render.render(write_still=False)
        check(s.last_level == "ERROR" and "no CG-TMO pipeline yet" in s.last_message,
              "CG-TMO without the library pipeline: " + s.last_message)
        check(not os.path.exists(os.path.join(OUT, "scene_0001.cgtmo.png")), "... and no tone-mapped file")
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
