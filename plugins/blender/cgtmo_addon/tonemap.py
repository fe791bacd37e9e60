"""After a render: the frame's EXR (Blender's own output, or the Render Result saved as EXR)
goes through the library's apply pipeline (the same call as `cgtmo apply`), the result is written
next to the render as NAME.cgtmo.<ext> and shown as an Image in Blender."""
import os

import bpy

from . import engine, properties, scene_prep

RESULT_IMAGE = "cgtmo result"


def save_render_result(scene, path):
    """Writes the Render Result as a multilayer float EXR, atomically (temporary name, rename).
    The scene's image settings are restored afterwards."""
    img = bpy.data.images.get("Render Result")
    if img is None or not img.has_data and img.type != "RENDER_RESULT":
        raise engine.CgtmoError("there is no render result to tone-map")
    folder = os.path.dirname(path) or "."
    scene_prep.check_writable_folder(folder)
    tmp = os.path.join(folder, "." + os.path.basename(path) + ".tmp")
    im = scene.render.image_settings
    saved = (im.file_format, im.color_depth, im.exr_codec)
    try:
        im.file_format = "OPEN_EXR_MULTILAYER"
        im.color_depth = "32"
        im.exr_codec = "ZIP"
        img.save_render(tmp, scene=scene)
        if not os.path.exists(tmp):
            raise engine.CgtmoError("Blender could not save the render result to %s" % path)
        os.replace(tmp, path)
    except RuntimeError as e:
        raise engine.CgtmoError("cannot save the render result to %s: %s" % (path, str(e).strip()))
    finally:
        im.file_format, im.color_depth, im.exr_codec = saved
        if os.path.exists(tmp):
            os.remove(tmp)
    return path


def written_file(scene, frame, since):
    """The file Blender wrote for `frame` during the render that started at `since`: an animation
    frame (`-a`, `-f`) is named by frame_path(); a still saved by render(write_still=True) is the
    output path itself, without a frame number. None when neither was written."""
    still = bpy.path.abspath(scene.render.filepath)
    ext = scene.render.file_extension
    if scene.render.use_file_extension and not still.lower().endswith(ext.lower()):
        still += ext
    fresh = []
    for path in (bpy.path.abspath(scene.render.frame_path(frame=frame)), still):
        try:
            mtime = os.path.getmtime(path)
        except OSError:
            continue
        if mtime >= since - 1.0:
            fresh.append((mtime, path))
    return max(fresh)[1] if fresh else None


def source_for_frame(scene, frame, written=None):
    """The linear EXR of the frame: the file Blender wrote when it is an EXR, else the Render
    Result saved as NAME.exr (NAME from frame_path, as Prepare scene names the probe)."""
    if written and scene.render.image_settings.file_format in scene_prep.EXR_FORMATS:
        return written
    return save_render_result(scene, scene_prep.frame_base(scene, frame) + ".exr")


def output_for(scene, source):
    stem = os.path.splitext(source)[0]
    return stem + ".cgtmo." + scene.cgtmo.output_format


def match_scene_files(scene, frame, source):
    """A still saved without a frame number (NAME.exr) gets the probe and sidecar that Prepare
    scene made for its frame, copied as NAME.probe.exr and NAME.json, so the reader finds them."""
    import shutil
    base, stem = scene_prep.frame_base(scene, frame), os.path.splitext(source)[0]
    if base == stem:
        return
    for suffix in (".probe.exr", ".json"):
        if os.path.exists(base + suffix):
            tmp = os.path.join(os.path.dirname(stem), "." + os.path.basename(stem + suffix) + ".tmp")
            shutil.copyfile(base + suffix, tmp)
            os.replace(tmp, stem + suffix)


def tonemap_file(scene, source, out, frame):
    """Runs the chosen operator on `source`, writes `out`. Returns the library's report."""
    s = scene.cgtmo
    lib = engine.lib()
    common = dict(op=s.operator, params=properties.chosen_params(s), exposure=s.exposure,
                  config=bpy.path.abspath(s.color_config), display="" if s.display == "DEFAULT" else s.display,
                  view="" if s.view == "DEFAULT" else s.view, colorspace=properties.chosen_colorspace(s))
    if engine.is_scene_operator(s.operator):
        match_scene_files(scene, frame, source)
        if not hasattr(lib, "apply_scene"):
            raise engine.CgtmoError(
                "this cgtmo module has no CG-TMO pipeline yet: the passes, probe and sidecar are ready in %s; "
                "choose a global operator to tone-map here" % os.path.dirname(source))
        return lib.apply_scene(source, out, **common)
    return lib.apply_file(source, out, **common)


def show_result(path):
    """Loads (or reloads) the written image as the Image 'cgtmo result' and shows it in any open
    Image Editor. The file is display-encoded: Blender must not transform it again."""
    img = bpy.data.images.get(RESULT_IMAGE)
    if img is None:
        img = bpy.data.images.load(path, check_existing=False)
        img.name = RESULT_IMAGE
    else:
        img.filepath = path
        img.reload()
    try:
        img.colorspace_settings.is_data = False
        img.colorspace_settings.name = "sRGB"
    except (TypeError, AttributeError):
        pass  # a config without an 'sRGB' space: Blender's default for the file type stays
    wm = bpy.context.window_manager
    for window in (wm.windows if wm else []):
        for area in window.screen.areas:
            if area.type == "IMAGE_EDITOR" and area.spaces.active.image is not bpy.data.images.get("Render Result"):
                area.spaces.active.image = img
    return img


def describe_report(rep, out):
    params = " ".join("%s=%s" % (k, ("%.6g" % v) if isinstance(v, float) else v) for k, v in sorted(rep["params"].items()))
    enc = "%s/%s" % (rep["display"], rep["view"]) if rep["display"] else "linear"
    text = "wrote %s (%dx%d, %s %s, %s)" % (out, rep["width"], rep["height"], rep["op"], params, enc)
    for w in rep.get("warnings", []):
        text += "; warning: " + w
    for n in rep.get("notes", []):  # scene operators: what the reader did not find, and the fallback
        text += "; note: " + n
    return text
