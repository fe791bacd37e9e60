"""Render one procedural test scene with the AOVs the CG-TMO operator reads.

Run headless with Blender 3.4 (Cycles, CPU):
    blender -b --factory-startup --python scripts/blender/render_scene.py -- \
        --scene cornell --out tests/scenes/cornell --width 480 --height 270 --samples 256

Writes into --out (created if missing), each file first under a temporary name, then renamed:
    NAME.exr        multilayer OpenEXR: Combined, Depth, Normal, Position, DiffCol, Emit and one
                    Combined_<group> pass per emitter and for the world (half-float colour passes,
                    float32 Depth/Normal/Position, ZIP). Depth is 1e10 on the background.
    NAME.probe.exr  the same passes, 64x32 equirectangular panorama from the camera's position
                    (level: row 0 straight up, the centre looks along the camera's heading).
    NAME.json       sidecar: camera (world matrix, field of view, sensor, resolution, clip), the
                    probe's orientation, and every emitter with its light group, colour, power or
                    strength, size or radius and emitted radiance/luminance (formulas in
                    scene_kit.py and tests/scenes/README.md).
"""
import argparse
import json
import math
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scene_kit  # noqa: E402
import scenes  # noqa: E402

PROBE_W, PROBE_H = 64, 32


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(
        prog="blender -b --factory-startup --python scripts/blender/render_scene.py --",
        description="Render one of the cgtmo test scenes (Cycles CPU, no denoising) with its AOVs, "
                    "a 64x32 equirectangular adaptation probe and a JSON sidecar.",
        epilog="Scenes: " + ", ".join(scenes.SCENES) + ". Render cost on a 2-core VM is about 1.2 us per "
               "pixel-sample: 480x270 at 256 spp takes about 40 s.")
    p.add_argument("--scene", required=True, choices=sorted(scenes.SCENES), help="scene to build")
    p.add_argument("--out", required=True, help="output folder (created if missing)")
    p.add_argument("--name", help="base name of the files (default: the scene name)")
    p.add_argument("--width", type=int, default=480, help="frame width in pixels (default 480)")
    p.add_argument("--height", type=int, default=270, help="frame height in pixels (default 270)")
    p.add_argument("--samples", type=int, default=256, help="samples per pixel of the frame (default 256; "
                   "adaptive sampling off, so every pixel gets exactly this many)")
    p.add_argument("--probe-samples", type=int, default=256, help="samples per pixel of the probe (default 256)")
    p.add_argument("--no-probe", action="store_true", help="skip the probe")
    p.add_argument("--seed", type=int, default=0, help="Cycles seed (renders are still not bit-reproducible)")
    p.add_argument("--threads", type=int, default=0, help="render threads (0: all cores)")
    p.add_argument("--codec", default="ZIP", choices=["ZIP", "PIZ", "PXR24", "ZIPS"], help="EXR compression")
    # argparse prints help and exits; inside Blender, make that a clean exit without rendering.
    try:
        a = p.parse_args(argv)
    except SystemExit as e:
        sys.stdout.flush()
        os._exit(e.code or 0)
    if a.width < 1 or a.height < 1 or a.samples < 1 or a.probe_samples < 1:
        p.error("width, height and samples must be positive")
    return a


def configure(scene, args):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.samples
    c.use_adaptive_sampling = False
    c.use_denoising = False          # Debian's build has no OpenImageDenoise (docs/platform.md)
    c.seed = args.seed
    c.max_bounces = 12
    c.diffuse_bounces = 8
    c.glossy_bounces = 4
    c.sample_clamp_direct = 0.0      # no clamping: light groups must sum to Combined, in true units
    c.sample_clamp_indirect = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    scene.render.threads_mode = "FIXED" if args.threads else "AUTO"
    if args.threads:
        scene.render.threads = args.threads
    scene.render.film_transparent = False
    scene.render.resolution_percentage = 100
    scene.render.use_file_extension = False
    im = scene.render.image_settings
    im.file_format = "OPEN_EXR_MULTILAYER"
    im.color_depth = "16"            # half colour passes; Depth/Normal/Position stay float32
    im.exr_codec = args.codec
    vl = scene.view_layers[0]
    vl.use_pass_combined = True
    vl.use_pass_z = True
    vl.use_pass_normal = True
    vl.use_pass_position = True
    vl.use_pass_diffuse_color = True
    vl.use_pass_emit = True


def render_to(scene, path):
    """Render the current camera into `path` via a temporary name (no partial file on failure)."""
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    scene.render.filepath = tmp
    bpy.ops.render.render(write_still=True)
    if not os.path.exists(tmp):
        raise RuntimeError("Blender wrote no file for " + path)
    os.replace(tmp, path)


def matrix_rows(m):
    return [[float(m[r][c]) for c in range(4)] for r in range(4)]


def camera_record(scene, cam_obj, args):
    cam = cam_obj.data
    w, h = args.width, args.height
    # sensor_fit HORIZONTAL: the sensor width spans the frame width.
    fov_x = 2.0 * math.atan(cam.sensor_width / (2.0 * cam.lens))
    fov_y = 2.0 * math.atan(math.tan(fov_x / 2.0) * h / w)
    return {
        "type": "PERSP",
        "world_matrix": matrix_rows(cam_obj.matrix_world),
        "convention": "Blender: the camera looks along its local -Z, +Y is up; world Z is up",
        "location": list(cam_obj.matrix_world.translation),
        "lens_mm": cam.lens,
        "sensor_fit": cam.sensor_fit,
        "sensor_width_mm": cam.sensor_width,
        "sensor_height_mm": cam.sensor_width * h / w,
        "fov_x_rad": fov_x,
        "fov_y_rad": fov_y,
        "fov_x_deg": math.degrees(fov_x),
        "fov_y_deg": math.degrees(fov_y),
        "resolution": [w, h],
        "clip_start": cam.clip_start,
        "clip_end": cam.clip_end,
        # Useful for footprint-scaled filter widths: world size of a pixel at distance 1.
        "pixel_footprint_at_1m": 2.0 * math.tan(fov_x / 2.0) / w,
    }


def probe_camera(scene, cam_obj):
    """An equirectangular camera at the camera's position, level, facing the camera's heading."""
    from mathutils import Euler
    fwd = cam_obj.matrix_world.to_3x3() @ __import__("mathutils").Vector((0.0, 0.0, -1.0))
    heading = math.atan2(fwd.y, fwd.x)  # angle of the forward direction in the XY plane
    data = bpy.data.cameras.new("probe")
    data.type = "PANO"
    data.cycles.panorama_type = "EQUIRECTANGULAR"
    data.clip_start = cam_obj.data.clip_start
    data.clip_end = cam_obj.data.clip_end
    obj = bpy.data.objects.new("probe", data)
    obj.location = cam_obj.matrix_world.translation
    # Rotation (90 deg, 0, 0) looks along +Y with Z up; then turn about Z to the heading.
    obj.rotation_euler = Euler((math.pi / 2, 0.0, heading - math.pi / 2))
    scene.collection.objects.link(obj)
    return obj, heading


def in_frame_check(scene, cam_obj, rec):
    """Whether any of the emitter's points (light centre, or mesh vertices) projects inside the
    frame with nothing in between. A geometric check, so two-rooms can prove its light hidden."""
    from bpy_extras.object_utils import world_to_camera_view
    obj = rec["object"]
    if obj is None:
        return None
    if obj.type == "LIGHT":
        if obj.data.type == "SUN":
            return False  # a sun is never hit by camera rays
        points = [obj.matrix_world.translation]
    else:
        points = [obj.matrix_world @ v.co for v in obj.data.vertices]
    depsgraph = bpy.context.evaluated_depsgraph_get()
    origin = cam_obj.matrix_world.translation
    for p in points:
        ndc = world_to_camera_view(scene, cam_obj, p)
        if not (0.0 <= ndc.x <= 1.0 and 0.0 <= ndc.y <= 1.0 and ndc.z > 0.0):
            continue
        d = p - origin
        dist = d.length
        hit, loc, _n, _i, hit_obj, _m = scene.ray_cast(depsgraph, origin, d.normalized(), distance=dist)
        if not hit or hit_obj.name == obj.name or (loc - p).length < 1e-3:
            return True
    return False


def main():
    args = parse_args()
    name = args.name or args.scene
    os.makedirs(args.out, exist_ok=True)
    kit = scene_kit.Kit()
    scene = kit.scene
    scenes.SCENES[args.scene](kit)
    configure(scene, args)
    scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
    cam_obj = scene.camera

    exr = os.path.join(args.out, name + ".exr")
    t0 = time.time()
    render_to(scene, exr)
    frame_s = time.time() - t0

    probe_rec = None
    if not args.no_probe:
        probe_obj, heading = probe_camera(scene, cam_obj)
        scene.camera = probe_obj
        scene.cycles.samples = args.probe_samples
        scene.render.resolution_x, scene.render.resolution_y = PROBE_W, PROBE_H
        t1 = time.time()
        render_to(scene, os.path.join(args.out, name + ".probe.exr"))
        probe_s = time.time() - t1
        scene.camera = cam_obj
        scene.render.resolution_x, scene.render.resolution_y = args.width, args.height
        probe_rec = {
            "file": name + ".probe.exr",
            "projection": "equirectangular",
            "resolution": [PROBE_W, PROBE_H],
            "location": list(cam_obj.matrix_world.translation),
            "heading_rad": heading,
            "convention": "row 0 is straight up (+Z), the last row straight down; the image centre "
                          "looks along heading_rad (angle from +X in the XY plane), longitude grows "
                          "to the left (counter-clockwise seen from above)",
            "samples": args.probe_samples,
            "render_seconds": round(probe_s, 3),
        }

    lights = []
    for rec in kit.emitters:
        out = {k: v for k, v in rec.items() if k != "object"}
        seen = in_frame_check(scene, cam_obj, rec)
        if seen is not None:
            out["in_frame"] = bool(seen and rec["visible_to_camera"])
        if rec["object"] is not None:
            out["location"] = list(rec["object"].matrix_world.translation)
            out["direction"] = list((rec["object"].matrix_world.to_3x3() @
                                     __import__("mathutils").Vector((0.0, 0.0, -1.0))).normalized())
        lights.append(out)

    sidecar = {
        "format": "cgtmo-scene-sidecar",
        "version": 1,
        "scene": args.scene,
        "generator": "scripts/blender/render_scene.py",
        "command": "blender -b --factory-startup --python scripts/blender/render_scene.py -- " +
                   " ".join(sys.argv[sys.argv.index("--") + 1:]),
        "blender": bpy.app.version_string,
        "engine": "CYCLES",
        "samples": args.samples,
        "seed": args.seed,
        "render_seconds": round(frame_s, 3),
        "units": "Cycles scene-linear Rec.709 radiance, as stored in the EXR; luminance is Rec.709 Y "
                 "(0.2126 R + 0.7152 G + 0.0722 B)",
        "image": name + ".exr",
        "view_layer": scene.view_layers[0].name,
        "camera": camera_record(scene, cam_obj, args),
        "probe": probe_rec,
        "lights": lights,
        "background_depth": 1e10,
    }
    path = os.path.join(args.out, name + ".json")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(sidecar, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)
    print("cgtmo-render: wrote %s (%.1f s), probe %s, sidecar %s" %
          (exr, frame_s, "none" if probe_rec is None else probe_rec["file"], path))


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # make Blender exit non-zero (it would otherwise exit 0)
        import traceback
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)
    sys.stdout.flush()
