"""Helpers shared by the Blender test scripts (run inside Blender's embedded Python)."""
import argparse
import os
import subprocess
import sys

import bpy


def args():
    argv = sys.argv[sys.argv.index("--") + 1:]
    p = argparse.ArgumentParser()
    p.add_argument("--zip", required=True)
    p.add_argument("--cgtmo", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--blender", default="blender")
    return p.parse_args(argv)


def fail(msg):
    print("TEST FAILED: " + msg, flush=True)
    sys.stdout.flush()
    os._exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)
    print("ok: " + msg, flush=True)


def install_addon(zip_path):
    """Preferences > Add-ons > Install from the zip, then enable (the user's way)."""
    r = bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    check(r == {"FINISHED"}, "add-on installed from %s" % os.path.basename(zip_path))
    r = bpy.ops.preferences.addon_enable(module="cgtmo_addon")
    check(r == {"FINISHED"} and hasattr(bpy.context.scene, "cgtmo"), "add-on enabled")


def tiny_scene(out_prefix, width=48, height=27, samples=4):
    """The factory scene (cube, point light, perspective camera) plus a floor and an emissive
    strip, rendered tiny with Cycles on the CPU."""
    scene = bpy.context.scene
    bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, -1))
    bpy.ops.mesh.primitive_cube_add(size=0.3, location=(-1.5, 1.0, 0.2))
    strip = bpy.context.object
    strip.name = "Neon strip"
    mat = bpy.data.materials.new("neon")
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    em = nt.nodes.new("ShaderNodeEmission")
    em.inputs["Color"].default_value = (1.0, 0.2, 0.1, 1.0)
    em.inputs["Strength"].default_value = 20.0
    outn = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(em.outputs[0], outn.inputs["Surface"])
    strip.data.materials.append(mat)
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.filepath = out_prefix
    return scene


def cgtmo_cli(cli, *a):
    p = subprocess.run([cli, *a], capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def read_png(path):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(path)
    check(not buf.has_error, "read " + os.path.basename(path))
    return buf.get_pixels(oiio.UINT8)


def channels(path):
    import OpenImageIO as oiio
    inp = oiio.ImageInput.open(path)
    check(inp is not None, "open " + os.path.basename(path))
    spec = inp.spec()
    inp.close()
    return spec.width, spec.height, list(spec.channelnames)


def passed():
    print("TEST PASSED", flush=True)
    sys.stdout.flush()
