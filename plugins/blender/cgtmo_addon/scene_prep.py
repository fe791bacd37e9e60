"""'Prepare scene': checks the scene, then enables the passes the chosen operator needs, puts every
emitter and the world in a light group of its own, sets multilayer EXR output, renders the 64x32
equirectangular probe and writes the JSON sidecar, NAME.probe.exr and NAME.json beside NAME.exr.

The probe camera, camera record, emitter radiance formulas and in-frame test are the scene
generator's (scripts/blender/render_scene.py and scene_kit.py, bundled in the zip), so renders
prepared here read exactly like the committed test scenes. Every check runs before any change:
a refused scene is left untouched."""
import json
import math
import os
import types

import bpy

from . import engine

PROBE_W, PROBE_H = 64, 32
EXR_FORMATS = ("OPEN_EXR", "OPEN_EXR_MULTILAYER")
IMAGE_EXTENSIONS = (".exr", ".png", ".tif", ".tiff", ".jpg", ".jpeg", ".bmp", ".tga", ".hdr", ".webp", ".jp2")


# ---- paths --------------------------------------------------------------------------------------
def frame_base(scene, frame):
    """The render's path for `frame` without its image extension: NAME of NAME.exr, NAME.json..."""
    path = bpy.path.abspath(scene.render.frame_path(frame=frame))
    stem, ext = os.path.splitext(path)
    return stem if ext.lower() in IMAGE_EXTENSIONS else path


def check_writable_folder(folder):
    """Raises CgtmoError unless files can be created in `folder` (created if missing)."""
    try:
        os.makedirs(folder, exist_ok=True)
        probe = os.path.join(folder, ".cgtmo-write-test-%d" % os.getpid())
        with open(probe, "w"):
            pass
        os.remove(probe)
    except OSError as e:
        raise engine.CgtmoError("cannot write to the output folder %s (%s): change Output Properties > Output"
                                % (folder, e.strerror or e))


def write_json_atomic(path, data):
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    try:
        with open(tmp, "w") as f:
            json.dump(data, f, indent=1)
            f.write("\n")
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


# ---- emitters -----------------------------------------------------------------------------------
def lightgroup_name(name, taken):
    """Blender accepts only letters, digits and '_' in light group names; unique within the layer."""
    base = "".join(c if (c.isascii() and c.isalnum()) or c == "_" else "_" for c in name) or "emitter"
    out, i = base, 1
    while out in taken:
        i += 1
        out = "%s_%d" % (base, i)
    taken.add(out)
    return out


def _unlinked(socket):
    return None if socket.is_linked else socket.default_value


def _material_emission(mat):
    """(rgb, strength) of a node material's constant emission, (None, None) when it emits through
    linked inputs (texture, ramp...), or None when it does not emit."""
    if mat is None or not mat.use_nodes or mat.node_tree is None:
        return None
    best = None
    for node in mat.node_tree.nodes:
        if node.bl_idname == "ShaderNodeEmission":
            col, strength = node.inputs["Color"], node.inputs["Strength"]
        elif node.bl_idname == "ShaderNodeBsdfPrincipled" and "Emission Strength" in node.inputs:
            col, strength = node.inputs["Emission"], node.inputs["Emission Strength"]
        else:
            continue
        c, s = _unlinked(col), _unlinked(strength)
        if c is None or s is None:
            best = best or (None, None)
            continue
        rgb = [float(v) for v in c[:3]]
        if s > 0 and max(rgb) > 0:
            if best is None or best[0] is None or s * max(rgb) > best[1] * max(best[0]):
                best = (rgb, float(s))
    return best


def find_emitters(scene):
    """Every emitter that renders: light objects, meshes with emissive materials, and the world.
    Records follow the scene generator's sidecar (scene_kit.py)."""
    kit, _ = engine.generator()
    emitters = []
    for obj in scene.objects:
        if obj.hide_render:
            continue
        if obj.type == "LIGHT":
            data = obj.data
            kind = data.type
            colour = [float(c) for c in data.color]
            rec = {"name": obj.name, "type": kind, "color": colour, "visible_to_camera": bool(obj.visible_camera),
                   "object": obj}
            rgb, formula = None, None
            if kind == "SUN":
                rec.update(strength=data.energy, angle=data.angle, irradiance=data.energy)
                if data.angle > 0:
                    rgb, formula = kit.emitted_radiance(kind, colour, strength=data.energy, angle=data.angle)
            elif kind == "AREA":
                sy = data.size_y if data.shape in ("RECTANGLE", "ELLIPSE") else data.size
                area = data.size * sy * (math.pi / 4.0 if data.shape in ("DISK", "ELLIPSE") else 1.0)
                rec.update(power=data.energy, shape=data.shape, size=[data.size, sy], area=area)
                if area > 0:
                    rgb, formula = kit.emitted_radiance(kind, colour, power=data.energy, area=area)
            else:
                rec.update(power=data.energy, radius=data.shadow_soft_size)
                if kind == "SPOT":
                    rec.update(spot_size=data.spot_size, spot_blend=data.spot_blend)
                if data.shadow_soft_size > 0:
                    rgb, formula = kit.emitted_radiance(kind, colour, power=data.energy, radius=data.shadow_soft_size)
            if data.energy <= 0 or max(colour) <= 0:
                continue  # a switched-off light emits nothing
            emitters.append(_with_radiance(kit, rec, rgb, formula))
        elif obj.type in ("MESH", "CURVE", "SURFACE", "META", "FONT"):
            found = None
            for slot in obj.material_slots:
                em = _material_emission(slot.material)
                if em is not None and (found is None or (em[0] is not None and (found[0] is None or
                                                         em[1] * max(em[0]) > found[1] * max(found[0])))):
                    found = em
            if found is None:
                continue
            rgb, strength = found
            rec = {"name": obj.name, "type": "MESH", "color": rgb, "strength": strength,
                   "size": list(obj.dimensions), "visible_to_camera": bool(obj.visible_camera), "object": obj}
            radiance = (kit.emitted_radiance("MESH", rgb, strength=strength) if rgb is not None else (None, None))
            emitters.append(_with_radiance(kit, rec, *radiance))
    world = scene.world
    if world is not None:
        rgb, strength = None, None
        if world.use_nodes and world.node_tree is not None:
            bg = next((n for n in world.node_tree.nodes if n.bl_idname == "ShaderNodeBackground"), None)
            if bg is not None:
                c, s = _unlinked(bg.inputs["Color"]), _unlinked(bg.inputs["Strength"])
                if c is not None and s is not None:
                    rgb, strength = [float(v) for v in c[:3]], float(s)
            else:
                rgb, strength = [0.0, 0.0, 0.0], 0.0
        else:
            rgb, strength = [float(v) for v in world.color], 1.0
        rec = {"name": "world", "type": "WORLD", "color": rgb, "strength": strength, "visible_to_camera": True,
               "object": None}
        radiance = kit.emitted_radiance("WORLD", rgb, strength=strength) if rgb is not None else (None, None)
        emitters.append(_with_radiance(kit, rec, *radiance))
    return emitters


def _with_radiance(kit, rec, rgb, formula):
    # None: not computable from constants (textured emission, zero-size light); the scene reader
    # then measures the light-group pass instead.
    rec.update(radiance=rgb, luminance=kit.luminance(rgb) if rgb is not None else None, formula=formula)
    return rec


def emits(rec):
    return rec["luminance"] is None or rec["luminance"] > 0


# ---- checks -------------------------------------------------------------------------------------
def check_scene(scene, op_name):
    """Everything that would make the preparation or the operator fail, as a list of
    (level, message); an ERROR means nothing is changed."""
    out = []
    if not engine.is_scene_operator(op_name):
        return out
    if scene.render.engine != "CYCLES":
        out.append(("ERROR", "%s needs Cycles (light groups and the Position pass); the render engine is %s"
                    % (op_name, scene.render.engine)))
    cam = scene.camera
    if cam is None:
        out.append(("ERROR", "the scene has no camera"))
    elif cam.type != "CAMERA" or cam.data.type != "PERSP":
        kind = cam.data.type if cam.type == "CAMERA" else cam.type
        out.append(("ERROR", "%s needs a perspective camera: '%s' is %s (set Camera > Lens > Type to Perspective)"
                    % (op_name, cam.name, {"ORTHO": "orthographic", "PANO": "a panorama"}.get(kind, kind))))
    emitters = [e for e in find_emitters(scene) if emits(e)]
    if not emitters:
        out.append(("ERROR", "the scene has no lights: no light, emissive material or world emits, so %s has no "
                    "Lw_max and the render is black; add a light or choose a global operator" % op_name))
    elif all(e["type"] == "WORLD" for e in emitters):
        out.append(("WARNING", "no light objects or emissive materials: only the world emits, so Lw_max comes from "
                    "the world's radiance"))
    try:
        check_writable_folder(os.path.dirname(frame_base(scene, scene.frame_current)) or ".")
    except engine.CgtmoError as e:
        out.append(("ERROR", str(e)))
    return out


# ---- preparation --------------------------------------------------------------------------------
def enable_passes(scene, op_name, params):
    vl = bpy.context.view_layer or scene.view_layers[0]
    vl.use_pass_combined = True
    for flag in engine.passes_needed(op_name, params):
        setattr(vl, flag, True)
    return vl


def assign_lightgroups(view_layer, emitters):
    taken = set()
    existing = {g.name for g in view_layer.lightgroups}
    for rec in emitters:
        obj = rec["object"]
        name = lightgroup_name("world" if obj is None else obj.name, taken)
        if name not in existing:
            view_layer.lightgroups.add(name=name)
            existing.add(name)
        if obj is None:
            bpy.context.scene.world.lightgroup = name
        else:
            obj.lightgroup = name
        rec["lightgroup"] = name


def set_multilayer_exr(scene):
    im = scene.render.image_settings
    im.file_format = "OPEN_EXR_MULTILAYER"
    im.color_depth = "16"   # half colour passes; Depth, Normal and Position stay float32 (docs/platform.md)
    im.exr_codec = "ZIP"


def render_probe(scene, cam_obj, path, samples):
    """The 64x32 equirectangular probe at the camera's position, written atomically to `path`."""
    from . import handlers
    _, rs = engine.generator()
    r = scene.render
    saved = (scene.camera, r.resolution_x, r.resolution_y, r.resolution_percentage, r.filepath,
             r.use_file_extension, scene.cycles.samples, r.use_border)
    probe_obj, heading = rs.probe_camera(scene, cam_obj)
    handlers.suspended = True  # our own render handlers must not tone-map the probe
    try:
        scene.camera = probe_obj
        r.resolution_x, r.resolution_y, r.resolution_percentage = PROBE_W, PROBE_H, 100
        r.use_file_extension = False
        r.use_border = False
        scene.cycles.samples = samples
        rs.render_to(scene, path)
    finally:
        handlers.suspended = False
        (scene.camera, r.resolution_x, r.resolution_y, r.resolution_percentage, r.filepath,
         r.use_file_extension, scene.cycles.samples, r.use_border) = saved
        data = probe_obj.data
        bpy.data.objects.remove(probe_obj)
        bpy.data.cameras.remove(data)
    return heading


def sidecar(scene, cam_obj, emitters, base, probe):
    _, rs = engine.generator()
    pct = scene.render.resolution_percentage / 100.0
    size = types.SimpleNamespace(width=int(scene.render.resolution_x * pct), height=int(scene.render.resolution_y * pct))
    lights = []
    for rec in emitters:
        out = {k: v for k, v in rec.items() if k != "object"}
        seen = rs.in_frame_check(scene, cam_obj, rec)
        if seen is not None:
            out["in_frame"] = bool(seen and rec["visible_to_camera"])
        obj = rec["object"]
        if obj is not None:
            out["location"] = list(obj.matrix_world.translation)
            from mathutils import Vector
            out["direction"] = list((obj.matrix_world.to_3x3() @ Vector((0.0, 0.0, -1.0))).normalized())
        lights.append(out)
    return {
        "format": "cgtmo-scene-sidecar",
        "version": 1,
        "scene": scene.name,
        "generator": "plugins/blender/cgtmo_addon (Prepare scene)",
        "blender": bpy.app.version_string,
        "engine": scene.render.engine,
        "samples": scene.cycles.samples,
        "frame": scene.frame_current,
        "units": "Cycles scene-linear Rec.709 radiance, as stored in the EXR; luminance is Rec.709 Y "
                 "(0.2126 R + 0.7152 G + 0.0722 B)",
        "image": os.path.basename(base) + ".exr",
        "view_layer": bpy.context.view_layer.name,
        "camera": rs.camera_record(scene, cam_obj, size),
        "probe": probe,
        "lights": lights,
        "background_depth": 1e10,
    }


def prepare(scene, op_name, params, frames, probe_samples):
    """Returns (list of messages, list of files written). Raises CgtmoError on a refused scene.
    `params`: the operator's parameters (they decide, e.g., whether the G-buffer is read)."""
    problems = check_scene(scene, op_name)
    errors = [m for lvl, m in problems if lvl == "ERROR"]
    if errors:
        raise engine.CgtmoError("; ".join(errors))
    notes = [m for lvl, m in problems if lvl == "WARNING"]
    if not engine.is_scene_operator(op_name):
        return ["%s is a global operator: it needs only the beauty, nothing to prepare" % op_name], []
    vl = enable_passes(scene, op_name, params)
    emitters = [e for e in find_emitters(scene) if emits(e)]
    assign_lightgroups(vl, emitters)
    set_multilayer_exr(scene)
    cam_obj = scene.camera
    written = []
    current = scene.frame_current
    todo = [current] if frames == "CURRENT" else list(range(scene.frame_start, scene.frame_end + 1, scene.frame_step))
    try:
        for f in todo:
            if f != scene.frame_current:
                scene.frame_set(f)
            base = frame_base(scene, f)
            os.makedirs(os.path.dirname(base) or ".", exist_ok=True)
            probe_path = base + ".probe.exr"
            heading = render_probe(scene, cam_obj, probe_path, probe_samples)
            probe = {"file": os.path.basename(probe_path), "projection": "equirectangular",
                     "resolution": [PROBE_W, PROBE_H], "location": list(cam_obj.matrix_world.translation),
                     "heading_rad": heading, "samples": probe_samples,
                     "convention": "row 0 is straight up (+Z), the last row straight down; the image centre "
                                   "looks along heading_rad (angle from +X in the XY plane)"}
            write_json_atomic(base + ".json", sidecar(scene, cam_obj, emitters, base, probe))
            written += [probe_path, base + ".json"]
    finally:
        if scene.frame_current != current:
            scene.frame_set(current)
    names = {"use_pass_z": "Depth", "use_pass_normal": "Normal", "use_pass_position": "Position",
             "use_pass_diffuse_color": "DiffCol"}
    passes = ["Combined"] + [names[f] for f in engine.passes_needed(op_name, params)]
    notes.append("prepared for %s: passes %s, %d light groups (%s), multilayer EXR, %d probe(s) and sidecar(s)"
                 % (op_name, ", ".join(passes), len(emitters), ", ".join(e["lightgroup"] for e in emitters),
                    len(todo)))
    return notes, written
