#!/usr/bin/python3
"""End-to-end test of the input colour space of `cgtmo apply`.

The same scene is written three times, as linear Rec.709 (no attribute), as ACEScg (AP1 primaries,
`chromaticities` attribute set) and as CIE XYZ (attribute set), with matrices taken from the
published values (not from cgtmo). Every operator of `cgtmo list --json` must then give the same
8-bit PNG within 1 code value from the three files: the global operators on a synthetic image
(grey ramp, saturated hues over 24 stops, grey and coloured patches), the scene operators on
tests/scenes/cornell (its beauty, light groups, albedo, emission and probe converted alike;
depth, normal and position as rendered). The run also measures the error of ignoring the
attribute (--colorspace "Linear Rec.709" on the ACEScg file, which is what cgtmo did before it
read the attribute) and requires it to be visible, so that the comparison can fail.

Then: a space named from an OCIO config (ours: ACEScg, CIE-XYZ-D65; Blender's: Linear ACEScg)
on copies without the attribute gives the attribute's result within 1 code value; a name that
disagrees with the attribute warns in one line naming both; an unknown name is a usage error
(exit 2, one line, some of the config's names); outputs record the input space.

  colorspace_e2e.py CGTMO_BINARY WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CORNELL = os.path.join(ROOT, "tests", "scenes", "cornell")
SHIPPED_CONFIG = os.path.join(ROOT, "ocio_config", "config.ocio")
BLENDER_CONFIG = "/usr/share/blender/datafiles/colormanagement/config.ocio"

# The matrices, derived from the primaries and whites (the chromaticities attribute defines the
# space): RGB -> XYZ from the primaries, Bradford adaptation of the white. Checked against the
# published ones below; the files are written with the derivation, as exact as float64 allows.
def _xyz(x, y):
    return np.array([x / y, 1.0, (1.0 - x - y) / y])


def _npm(prims, white):
    p = np.array([_xyz(*c) for c in prims]).T
    return p * np.linalg.solve(p, _xyz(*white))


_BRADFORD = np.array([[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]])
_D65, _D60 = (0.3127, 0.3290), (0.32168, 0.33767)
_REC709 = ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06))
_AP1 = ((0.713, 0.293), (0.165, 0.830), (0.128, 0.044))
REC709_TO_XYZ = _npm(_REC709, _D65)
_D60_TO_D65 = np.linalg.inv(_BRADFORD) @ np.diag((_BRADFORD @ _xyz(*_D65)) / (_BRADFORD @ _xyz(*_D60))) @ _BRADFORD
AP1_TO_REC709 = np.linalg.inv(REC709_TO_XYZ) @ _D60_TO_D65 @ _npm(_AP1, _D60)
# Published: ITU-R BT.709 -> XYZ; AP1 -> Rec.709 of the ACES reference configs (Bradford).
assert np.abs(REC709_TO_XYZ - [[0.4123907993, 0.3575843394, 0.1804807884], [0.2126390059, 0.7151686788, 0.0721923054],
                               [0.0193308187, 0.1191947798, 0.9505321522]]).max() < 1e-6
assert np.abs(AP1_TO_REC709 - [[1.7050509927, -0.6217921206, -0.0832588720], [-0.1302564175, 1.1408047366, -0.0105483190],
                               [-0.0240033568, -0.1289689761, 1.1529723329]]).max() < 1e-6
REC709_TO_AP1 = np.linalg.inv(AP1_TO_REC709)
AP1_ATTR = (0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767)
XYZ_ATTR = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0 / 3.0, 1.0 / 3.0)
SPACES = {"rec709": (np.eye(3), None), "acescg": (REC709_TO_AP1, AP1_ATTR), "xyz": (REC709_TO_XYZ, XYZ_ATTR)}

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what)


def synthetic():
    w, h = 128, 72
    img = np.zeros((h, w, 3), np.float64)
    ramp = np.exp2(np.linspace(-10.0, 14.0, w))
    img[0:24] = ramp[None, :, None]
    hues = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1], [1, 0.5, 0.1], [0.2, 0.4, 1]])
    for i in range(w):
        img[24:48, i] = hues[(i * len(hues)) // w] * ramp[(i * 7) % w]
    greys = [0.0, 0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 8.0, 64.0, 1000.0]
    for k, g in enumerate(greys):
        x0, x1 = k * w // len(greys), (k + 1) * w // len(greys)
        img[48:60, x0:x1] = g
        img[60:72, x0:x1] = np.array([g, 0.25 * g, 0.02 * g])
    return img


def write_exr(path, names, pixels, formats, chromaticities):
    h, w, c = pixels.shape
    spec = oiio.ImageSpec(w, h, c, oiio.FLOAT)
    spec.channelnames = tuple(names)
    spec.channelformats = tuple(formats)
    spec.attribute("compression", "zip")
    if chromaticities is not None:
        spec.attribute("chromaticities", oiio.TypeDesc("float[8]"), chromaticities)
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, spec) or not out.write_image(np.ascontiguousarray(pixels, np.float32)) or not out.close():
        sys.exit("cannot write " + path + ": " + oiio.geterror())


def convert_file(src, dst, matrix, chromaticities):
    """A copy of the render `src` whose colour passes (beauty, light groups, DiffCol, Emit) are
    multiplied by `matrix`, stored as float32; every other channel as it was."""
    inp = oiio.ImageInput.open(src)
    spec = inp.spec()
    names = list(spec.channelnames)
    px = inp.read_image(oiio.FLOAT).astype(np.float64)
    inp.close()
    colour_prefixes = set()
    for n in names:
        prefix, _, comp = n.rpartition(".")
        last = prefix.rpartition(".")[2]
        if comp == "R" and (last == "Combined" or last.startswith("Combined_") or last in ("DiffCol", "Emit")):
            colour_prefixes.add(prefix)
    for p in colour_prefixes:
        idx = [names.index(p + "." + c) for c in "RGB"]
        px[:, :, idx] = px[:, :, idx] @ matrix.T
    write_exr(dst, names, px, ["float"] * len(names), chromaticities)
    return len(colour_prefixes)


def read_png(path):
    inp = oiio.ImageInput.open(path)
    if not inp:
        return None
    px = inp.read_image(oiio.UINT8)
    inp.close()
    return px.astype(np.int32)


def run(cgtmo, args, expect_rc=0):
    p = subprocess.run([cgtmo, "apply", "-q"] + args, capture_output=True, text=True,
                       env=dict(os.environ, OCIO=""))
    if p.returncode != expect_rc:
        check(False, "cgtmo apply %s: exit %d, wanted %d: %s" % (" ".join(args), p.returncode, expect_rc, p.stderr.strip()))
    return p


def max_diff(a, b):
    pa, pb = read_png(a), read_png(b)
    if pa is None or pb is None:
        return 999
    return int(np.abs(pa - pb).max())


def main():
    cgtmo, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    ops = json.loads(subprocess.run([cgtmo, "list", "--json"], capture_output=True, text=True, check=True).stdout)
    # Inputs: the synthetic image and the cornell scene, once per space.
    img = synthetic()
    for space, (m, attr) in SPACES.items():
        write_exr(os.path.join(work, space + ".exr"), ["R", "G", "B"], img @ m.T, ["float"] * 3, attr)
        d = os.path.join(work, "cornell_" + space)
        os.makedirs(d)
        n = convert_file(os.path.join(CORNELL, "cornell.exr"), os.path.join(d, "cornell.exr"), m, attr)
        check(n >= 4, "cornell: %d colour passes converted, expected beauty, 2 light groups, DiffCol, Emit" % n)
        convert_file(os.path.join(CORNELL, "cornell.probe.exr"), os.path.join(d, "cornell.probe.exr"), m, attr)
        shutil.copyfile(os.path.join(CORNELL, "cornell.json"), os.path.join(d, "cornell.json"))
    # The ACEScg file without its attribute, for the named-space path.
    write_exr(os.path.join(work, "acescg_noattr.exr"), ["R", "G", "B"], img @ REC709_TO_AP1.T, ["float"] * 3, None)

    print("%-16s %8s %8s %8s   (max 8-bit code-value difference against the Rec.709 file)" %
          ("operator", "ACEScg", "XYZ", "ignored"))
    for op in ops:
        name = op["name"]
        scene = op["scope"] == "scene"
        outs = {}
        for space in SPACES:
            src = os.path.join(work, "cornell_" + space, "cornell.exr") if scene else os.path.join(work, space + ".exr")
            outs[space] = os.path.join(work, "%s_%s.png" % (name, space))
            run(cgtmo, [src, "-o", outs[space], "--op", name])
        ignored = os.path.join(work, "%s_ignored.png" % name)
        src = os.path.join(work, "cornell_acescg", "cornell.exr") if scene else os.path.join(work, "acescg.exr")
        run(cgtmo, [src, "-o", ignored, "--op", name, "--colorspace", "Linear Rec.709"])
        d_ap1, d_xyz = max_diff(outs["acescg"], outs["rec709"]), max_diff(outs["xyz"], outs["rec709"])
        d_ign = max_diff(ignored, outs["rec709"])
        print("%-16s %8d %8d %8d" % (name, d_ap1, d_xyz, d_ign))
        check(d_ap1 <= 1, "%s: ACEScg file differs by %d code values" % (name, d_ap1))
        check(d_xyz <= 1, "%s: XYZ file differs by %d code values" % (name, d_xyz))
        check(d_ign >= 4, "%s: ignoring the attribute changes only %d code values: the test cannot tell" % (name, d_ign))

    ref = os.path.join(work, "agx_acescg.png")
    # The record names the space as resolved.
    info = subprocess.run([cgtmo, "info", ref], capture_output=True, text=True).stdout
    check("chromaticities attribute (ACEScg (AP1) primaries, ACES white (D60))" in info,
          "cgtmo info does not show the resolved input space:\n" + info)
    scene_info = subprocess.run([cgtmo, "info", os.path.join(work, "cgtmo_xyz.png")], capture_output=True, text=True).stdout
    check("chromaticities attribute (CIE XYZ, white E)" in scene_info, "scene output record:\n" + scene_info)

    # Sequences: per-pixel and scene operators, each frame converted by its attribute; a second run
    # finds every output up to date (the record's colour space is stable).
    seq = os.path.join(work, "seq")
    os.makedirs(seq)
    for f in (1, 2):
        shutil.copyfile(os.path.join(work, "acescg.exr"), os.path.join(seq, "img.%04d.exr" % f))
        for suffix in (".exr", ".probe.exr", ".json"):
            shutil.copyfile(os.path.join(work, "cornell_acescg", "cornell" + suffix), os.path.join(seq, "cornell.%04d%s" % (f, suffix)))
        shutil.copyfile(os.path.join(work, "cornell_acescg", "cornell.probe.exr"), os.path.join(seq, "cornell.probe.exr"))
    for stem, op, ref_png in (("img", "agx", ref), ("cornell", "cgtmo", os.path.join(work, "cgtmo_rec709.png"))):
        pattern_in, pattern_out = os.path.join(seq, stem + ".####.exr"), os.path.join(seq, stem + "_out.####.png")
        run(cgtmo, [pattern_in, "-o", pattern_out, "--op", op])
        for f in (1, 2):
            d = max_diff(os.path.join(seq, "%s_out.%04d.png" % (stem, f)), ref_png)
            print("sequence %s frame %d against the Rec.709 file: %d" % (op, f, d))
            check(d <= 1, "sequence %s frame %d differs by %d" % (op, f, d))
        p = run(cgtmo, [pattern_in, "-o", pattern_out, "--op", op, "--dry-run"])
        check("todo" not in p.stdout and "skip" in p.stdout, "sequence %s: a second run would redo frames: %s" % (op, p.stdout))

    # Statistics held steady over a shot (--temporal) are measured on the converted frames too.
    for f in (1, 2):
        shutil.copyfile(os.path.join(work, "rec709.exr"), os.path.join(seq, "ref.%04d.exr" % f))
        for suffix in (".exr", ".probe.exr", ".json"):
            shutil.copyfile(os.path.join(work, "cornell_rec709", "cornell" + suffix), os.path.join(seq, "cref.%04d%s" % (f, suffix)))
    for stem, ref_stem, op in (("img", "ref", "drago"), ("cornell", "cref", "cgtmo")):
        outs = {}
        for s_ in (stem, ref_stem):
            run(cgtmo, [os.path.join(seq, s_ + ".####.exr"), "-o", os.path.join(seq, s_ + "_t.####.png"), "--op", op,
                        "--temporal", "1"])
        d = max(max_diff(os.path.join(seq, "%s_t.%04d.png" % (stem, f)), os.path.join(seq, "%s_t.%04d.png" % (ref_stem, f)))
                for f in (1, 2))
        print("sequence %s --temporal 1 against the Rec.709 frames: %d" % (op, d))
        check(d <= 1, "sequence %s --temporal 1 differs by %d" % (op, d))

    # Named spaces of a config, on the copy without the attribute.
    named = [(SHIPPED_CONFIG, "ACEScg")]
    if os.path.exists(BLENDER_CONFIG):
        named.append((BLENDER_CONFIG, "Linear ACEScg"))
    for config, space in named:
        out = os.path.join(work, "named_%s.png" % space.replace(" ", "_"))
        run(cgtmo, [os.path.join(work, "acescg_noattr.exr"), "-o", out, "--op", "agx", "--colorconfig", config,
                    "--colorspace", space])
        d = max_diff(out, ref)
        print("named '%s' (%s) against the attribute: %d" % (space, os.path.basename(os.path.dirname(config)), d))
        check(d <= 1, "--colorspace '%s' of %s differs from the attribute's result by %d" % (space, config, d))
    # A name that agrees with the attribute says nothing; one that disagrees warns, naming both.
    p = run(cgtmo, [os.path.join(work, "xyz.exr"), "-o", os.path.join(work, "agree.png"), "--op", "agx",
                    "--colorconfig", SHIPPED_CONFIG, "--colorspace", "CIE-XYZ-D65"])
    check("warning" not in p.stderr, "an agreeing name warned: " + p.stderr)
    check(max_diff(os.path.join(work, "agree.png"), ref) <= 1, "CIE-XYZ-D65 by name differs from the attribute path")
    for args in (["--op", "agx"], ["--op", "cgtmo"]):
        src = os.path.join(work, "cornell_acescg", "cornell.exr") if "cgtmo" in args else os.path.join(work, "acescg.exr")
        p = run(cgtmo, [src, "-o", os.path.join(work, "disagree.png"), "--colorspace", "Linear Rec.709"] + args)
        lines = [l for l in p.stderr.splitlines() if "disagrees" in l]
        check(len(lines) >= 1 and "'Linear Rec.709'" in lines[0] and "ACEScg (AP1) primaries" in lines[0],
              "%s: no one-line warning naming both spaces: %r" % (args[1], p.stderr))
    # An unknown name: usage error, one line, some names of the config; nothing written.
    bad_out = os.path.join(work, "bad.png")
    p = run(cgtmo, [os.path.join(work, "acescg.exr"), "-o", bad_out, "--colorspace", "Nope"], expect_rc=2)
    err = p.stderr.strip().splitlines()
    check(len(err) == 1 and "'Nope'" in err[0] and "'Linear Rec.709'" in err[0], "unknown name: %r" % p.stderr)
    check(not os.path.exists(bad_out), "unknown name: an output was written")
    p = run(cgtmo, [os.path.join(CORNELL, "cornell.exr"), "-o", bad_out, "--op", "wls", "--colorspace", "Nope"], expect_rc=2)
    check(len(p.stderr.strip().splitlines()) == 1 and "'Nope'" in p.stderr, "unknown name, scene operator: %r" % p.stderr)

    if failures:
        print("%d failure(s)" % len(failures))
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
