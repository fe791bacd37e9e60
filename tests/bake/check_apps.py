#!/usr/bin/python3
"""The committed OCIO config in real applications, against `cgtmo apply`.

usage: check_apps.py {ociocheck|oiiotool|blender|scene|scene_commands} CGTMO SOURCE_DIR WORK

- ociocheck: `ociocheck --iconfig ocio_config/config.ocio` exits 0 and reports no error or warning.
- oiiotool:  for every operator, `--ociodisplay sRGB <op>` and `--ociolook <op>` + `--ociodisplay sRGB
             Standard` on a synthetic HDR EXR equal `cgtmo apply --op <op>` within 1 code value at 8 bits.
- blender:   Blender, headless with OCIO=the config, offers every view and look through bpy, and
             Image.save_render with an operator view equals cgtmo apply within 1 code value.
- scene:     `cgtmo bake --scene` on the EXR: the new view in the config copy (oiiotool) equals
             `cgtmo apply --op drago` with the render's statistics within 1 code value.
- scene_commands: `cgtmo bake --scene` into empty folders; every command it prints runs as printed
             (Blender headless), and the images they write equal the printed `cgtmo apply`'s."""
import json, os, shutil, subprocess, sys

import numpy as np
import OpenImageIO as oiio


def run(cmd, env=None, cwd=None):
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd)
    if r.returncode != 0:
        raise SystemExit("FAILED (%d): %s\n%s%s" % (r.returncode, " ".join(cmd), r.stdout[-3000:], r.stderr[-3000:]))
    return r.stdout + r.stderr


def write_test_exr(path):
    """A synthetic HDR test image: a log ramp of greys (2^-14 .. 2^15.9), ramps of the six
    primaries and secondaries, and random saturated colours; 512 x 64, float RGB."""
    w, h = 512, 64
    img = np.zeros((h, w, 3), np.float32)
    ramp = np.exp2(np.linspace(-14, 15.99, w)).astype(np.float32)
    hues = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1), (1, 0.3, 0.02), (0.05, 0.4, 1)]
    for y in range(8):
        img[y] = ramp[:, None]
    for i, hue in enumerate(hues):
        img[8 + 4 * i: 12 + 4 * i] = ramp[:, None] * np.array(hue, np.float32)
    rng = np.random.default_rng(7)
    rest = img[40:]
    c = np.exp2(rng.uniform(-12, 14, rest.shape)).astype(np.float32)
    c *= (rng.random(rest.shape) ** 3).astype(np.float32)  # saturated: one channel dominates
    img[40:] = np.minimum(c, 65504)
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(w, h, 3, oiio.FLOAT))
    out.write_image(img)
    out.close()


def read8(path):
    buf = oiio.ImageBuf(path)
    px = buf.get_pixels(oiio.UINT8)
    if px is None or buf.has_error:
        raise SystemExit("cannot read " + path + ": " + buf.geterror())
    return np.asarray(px, np.int32)[..., :3]


def compare(a_path, b_path, label, failures, allowed=1):
    """Equal within `allowed` 8-bit code values (1, or more for an operator the bake reports as
    missing its target: its stated 10-bit bound / 4, rounded up, plus 1 for 8-bit rounding)."""
    a, b = read8(a_path), read8(b_path)
    d = int(np.abs(a - b).max())
    n = int((np.abs(a - b) > allowed).sum())
    note = "" if allowed == 1 else " (allowed %d: reported as missing its target)" % allowed
    print("%-48s max diff %d code value(s)%s%s" % (label, d, "" if d <= allowed else ", %d values over" % n, note))
    if d > allowed:
        failures.append(label)


def allowed_8bit(m):
    if m["max_error_cv"] <= m["target_cv"]:
        return 1
    return int(np.ceil(m["max_error_cv"] / 4.0)) + 1


def apply_args(cgtmo, exr, out, config, op, params, extra=()):
    cmd = [cgtmo, "apply", exr, "-o", out, "--colorconfig", config, "--op", op, "-q", *extra]
    for k, v in params.items():
        cmd += ["-p", "%s=%s" % (k, v if isinstance(v, str) else repr(float(v)))]
    return cmd


def main():
    which, cgtmo, src, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    config = os.path.join(src, "ocio_config", "config.ocio")
    manifest = json.load(open(os.path.join(src, "luts", "manifest.json")))["operators"]
    exr = os.path.join(work, "hdr-test.exr")
    write_test_exr(exr)
    failures = []

    if which == "ociocheck":
        out = run(["ociocheck", "--iconfig", config])
        bad = [l for l in out.splitlines() if "ERROR" in l.upper() or "WARNING" in l.upper()]
        print(out[-1500:])
        if bad:
            failures += bad

    elif which == "oiiotool":
        for op, m in manifest.items():
            ref = os.path.join(work, op + "-cgtmo.png")
            run(apply_args(cgtmo, exr, ref, config, op, m["params"]))
            view = os.path.join(work, op + "-view.png")
            run(["oiiotool", "--colorconfig", config, exr, "--iscolorspace", "Linear Rec.709",
                 "--ociodisplay:from=Linear Rec.709", "sRGB", op, "-d", "uint8", "-o", view])
            compare(ref, view, "oiiotool --ociodisplay sRGB " + op, failures, allowed_8bit(m))
            look = os.path.join(work, op + "-look.png")
            run(["oiiotool", "--colorconfig", config, exr, "--iscolorspace", "Linear Rec.709",
                 "--ociolook:from=Linear Rec.709:to=Linear Rec.709", op,
                 "--ociodisplay:from=Linear Rec.709", "sRGB", "Standard", "-d", "uint8", "-o", look])
            compare(ref, look, "oiiotool --ociolook " + op + " + Standard", failures, allowed_8bit(m))
        # One exposure look over an operator view: +1 stop then the operator.
        op = "aces-narkowicz"
        ref = os.path.join(work, "exposure-cgtmo.png")
        run(apply_args(cgtmo, exr, ref, config, op, manifest[op]["params"], ["--exposure", "1"]))
        look = os.path.join(work, "exposure-look.png")
        run(["oiiotool", "--colorconfig", config, exr, "--iscolorspace", "Linear Rec.709",
             "--ociolook:from=Linear Rec.709:to=Linear Rec.709", op + " - +1 stop",
             "--ociodisplay:from=Linear Rec.709", "sRGB", "Standard", "-d", "uint8", "-o", look])
        compare(ref, look, "oiiotool --ociolook '%s - +1 stop'" % op, failures)

    elif which == "blender":
        ops = list(manifest)
        script = os.path.join(work, "blender_check.py")
        with open(script, "w") as f:
            f.write(BLENDER_SCRIPT)
        env = dict(os.environ, OCIO=config)
        out = run(["blender", "-b", "--factory-startup", "--python", script, "--", exr, work, ",".join(ops), ",".join(SAVE_RENDER_VIEWS)], env=env)
        print("\n".join(l for l in out.splitlines() if l.startswith("cgtmo-check")))
        if "cgtmo-check: ok" not in out:
            failures.append("blender script did not finish")
        for op in ops:
            if "cgtmo-check: missing" in out and (" " + op + "\n") in out:
                failures.append("blender misses " + op)
        for op in SAVE_RENDER_VIEWS:
            ref = os.path.join(work, op + "-cgtmo.png")
            run(apply_args(cgtmo, exr, ref, config, op, manifest[op]["params"]))
            compare(ref, os.path.join(work, op + "-blender.png"), "blender save_render view " + op, failures, allowed_8bit(manifest[op]))
        failures += [l for l in out.splitlines() if l.startswith("cgtmo-check: missing")]

    elif which == "scene":
        # A copy of the committed config and LUTs, so the scene bake never touches the repository.
        for d in ("luts", "ocio_config"):
            shutil.copytree(os.path.join(src, d), os.path.join(work, d))
        out = run([cgtmo, "bake", "--scene", exr, "--name", "test", "--out-luts", "luts", "--out-config", "ocio_config"], cwd=work)
        print(out)
        scene_config = os.path.join(work, "ocio_config", "test.ocio")
        stats = oiio.ImageBufAlgo.computePixelStats(oiio.ImageBuf(exr))
        view = os.path.join(work, "scene-view.png")
        run(["oiiotool", "--colorconfig", scene_config, exr, "--iscolorspace", "Linear Rec.709",
             "--ociodisplay:from=Linear Rec.709", "sRGB", "drago-test", "-d", "uint8", "-o", view])
        ref = os.path.join(work, "scene-cgtmo.png")
        # cgtmo apply's own defaults for drago are the image's statistics: the same numbers.
        run([cgtmo, "apply", exr, "-o", ref, "--colorconfig", scene_config, "--op", "drago", "-q"])
        compare(ref, view, "bake --scene view drago-test", failures)
        if not [f for f in os.listdir(os.path.join(work, "luts")) if f.startswith("drago-test.")]:
            failures.append("missing luts/drago-test.*")
        if not os.path.exists(os.path.join(work, "ocio_config", "test.ocio")):
            failures.append("missing ocio_config/test.ocio")

    elif which == "scene_commands":
        # Into empty folders (no config.ocio yet), then every command bake prints (its indented
        # lines) is run as printed, in a shell, from the same folder: oiiotool and cgtmo apply write
        # out.png (compared with each other), Blender is started headless on the printed OCIO= line
        # with a script that selects the printed view and look.
        for d in ("luts", "ocio_config"):
            os.makedirs(os.path.join(work, d))
        env = {k: v for k, v in os.environ.items() if k != "OCIO"}
        out = run([cgtmo, "bake", "--scene", exr, "--name", "shot", "--out-luts", "luts", "--out-config", "ocio_config"], cwd=work, env=env)
        print(out)
        commands = [l[4:] for l in out.splitlines() if l.startswith("    ")]
        if len(commands) != 4:
            failures.append("expected 4 printed commands, got %d" % len(commands))
        outputs = []
        for i, c in enumerate(commands):
            if c.startswith("cgtmo "):
                c = cgtmo + c[len("cgtmo"):]
            if c.rstrip().endswith(" blender"):
                c += (" -b --factory-startup --python-expr \"import bpy, sys; vs = bpy.context.scene.view_settings; "
                      "vs.view_transform = 'drago-shot'; vs.view_transform = 'Standard'; vs.look = 'drago-shot'; "
                      "print('cgtmo-check: blender ok')\"")
            r = subprocess.run(["bash", "-c", c], cwd=work, env=env, capture_output=True, text=True)
            ok = r.returncode == 0 and ("blender" not in c or "cgtmo-check: blender ok" in r.stdout)
            print("%s: %s" % ("ran" if ok else "FAILED", c))
            if not ok:
                failures.append("printed command failed (%d): %s\n%s%s" % (r.returncode, c, r.stdout[-1500:], r.stderr[-1500:]))
            if os.path.exists(os.path.join(work, "out.png")):
                outputs.append((c, os.path.join(work, "out%d.png" % i)))
                os.replace(os.path.join(work, "out.png"), outputs[-1][1])
        apply_out = [p for c, p in outputs if " apply " in c]
        for c, p in outputs:
            if apply_out and p != apply_out[0]:
                compare(apply_out[0], p, "printed: " + c.split(" -o ")[0][-60:], failures)
        if len(outputs) != 3:
            failures.append("expected out.png from 3 commands, got %d" % len(outputs))

    if failures:
        print("FAILED:", *failures, sep="\n  ")
        return 1
    print("passed")
    return 0


# Views rendered through Image.save_render: one per LUT design (1D per channel, 1D with
# matrices, 1D on luminance in xyY, HSV with 1D LUTs in a .ctf, 3D with a node warp in a .ctf).
SAVE_RENDER_VIEWS = ("reinhard", "agx", "reinhard-lum", "drago", "pbr-neutral", "reinhard-jodie")

BLENDER_SCRIPT = r'''
import sys, bpy
exr, work, ops, rendered = sys.argv[sys.argv.index("--") + 1:]
ops = ops.split(",")
scene = bpy.context.scene
vs = scene.view_settings
scene.display_settings.display_device = "sRGB"
missing = []
for op in ["Standard", "Raw"] + ops:
    try:
        vs.view_transform = op
    except TypeError:
        missing.append("view " + op)
for op in ops:
    try:
        vs.view_transform = "Standard"
        vs.look = op
    except TypeError:
        missing.append("look " + op)
    try:
        vs.view_transform = op
        vs.look = op + " - +1 stop"
    except TypeError:
        missing.append("look " + op + " - +1 stop")
for m in missing:
    print("cgtmo-check: missing " + m)
img = bpy.data.images.load(exr)
img.colorspace_settings.name = "Linear Rec.709"
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
scene.render.image_settings.color_mode = "RGB"
scene.render.dither_intensity = 0.0
for op in rendered.split(","):
    vs.view_transform = op
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0
    vs.use_curve_mapping = False
    img.save_render(work + "/" + op + "-blender.png", scene=scene)
print("cgtmo-check: views and looks listed: %d views" % (len(ops) + 2))
print("cgtmo-check: ok")
'''

if __name__ == "__main__":
    sys.exit(main())
