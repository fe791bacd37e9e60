#!/usr/bin/python3
"""Colours outside Rec.709 through every face that applies an operator, against `cgtmo apply`.

usage: check_wide_gamut.py CGTMO SOURCE_DIR WORK [IMAGE COLOURSPACE]

A wide-gamut chart (hue sweeps at full and 70% saturation over 14 stops, and random colours of
the gamut) is written once as ACEScg and once as linear Rec.2020; about half its pixels have a
negative Rec.709 component. (IMAGE COLOURSPACE: measure one image instead, with the name of its
colour space in both configs, e.g. OpenEXR's WideColorGamut.exr and "Linear Rec.709".) For every
operator, `cgtmo apply --colorspace` of the file is the reference, and each of these must equal
it within 1 code value at 8 bits (more only where the bake reports the export missing its
target: its stated 10-bit bound / 4, plus 1):
- the view of `cgtmo bake --into` an ACES-style studio config (scene_linear ACEScg), through
  `oiiotool --ociodisplay:from=<space> sRGB "cgtmo <op>"`;
- luts/<op>.clf read by OpenColorIO, given the file converted to linear Rec.709 by cgtmo's config
  (negative components kept, as any application converting it would);
- luts/<op>.cube, after the Log2 Shaper, clipped to [0, 1] (docs/ocio.md).
cgtmo apply clips the negative components at 0 (scene/sanitize.h); a look or export that applies
an operator's input matrix to them first spreads them into the other channels."""
import json, os, shutil, subprocess, sys

import numpy as np
import OpenImageIO as oiio
import PyOpenColorIO as ocio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_apps import run, read8, apply_args  # noqa: E402
from check_into import write_aces_style  # noqa: E402

SPACES = {"ACEScg": "ACEScg", "Linear Rec.2020": "Linear Rec.2020"}  # chart name -> name in both configs


def chart():
    """Rows of hue sweeps (one channel 0: the gamut's edge, and 70% saturation) at 2^-6 .. 2^8 and
    random colours inside the gamut: 256 x 64 float RGB."""
    w, h = 256, 64
    img = np.zeros((h, w, 3), np.float32)
    hue = np.linspace(0.0, 6.0, w, endpoint=False)
    for row in range(56):
        sat = 1.0 if row % 2 == 0 else 0.7
        scale = 2.0 ** (-6 + 14 * (row // 2) / 27.0)
        k = hue[:, None] + np.array([0.0, 4.0, 2.0])[None, :]  # HSV to RGB, value 1
        rgb = 1.0 - sat * np.clip(np.minimum(np.mod(k, 6.0), 4.0 - np.mod(k, 6.0)), 0.0, 1.0)
        img[row] = rgb * scale
    rng = np.random.default_rng(11)
    img[56:] = (np.exp2(rng.uniform(-8, 6, (8, w, 1))) * rng.random((8, w, 3)) ** 2).astype(np.float32)
    return img


def write_exr(path, px):
    out = oiio.ImageOutput.create(path)
    out.open(path, oiio.ImageSpec(px.shape[1], px.shape[0], 3, oiio.FLOAT))
    out.write_image(px)
    out.close()


def read_float(path):
    return np.asarray(oiio.ImageBuf(path).get_pixels(oiio.FLOAT), np.float32)[..., :3]


def ocio_apply(config, transform, px):
    out = np.ascontiguousarray(px, np.float32).copy()
    config.getProcessor(transform).getDefaultCPUProcessor().applyRGB(out)
    return out


def to8(px):
    return np.clip(np.round(px * 255.0), 0, 255).astype(np.int32)


def allowed(max_cv, target):
    return 1 if max_cv <= target else int(np.ceil(max_cv / 4.0)) + 1


class Tally:
    def __init__(self):
        self.failures, self.rows = [], []

    def compare(self, ref, got, label, limit):
        d = np.abs(ref - got)
        worst, mean = int(d.max()), float(d.mean())
        self.rows.append((label, worst, mean))
        print("%-58s max %3d, mean %.3f code values (8-bit)%s" % (label, worst, mean, "" if worst <= limit else "  > %d: FAIL" % limit))
        if worst > limit:
            self.failures.append(label)


def main():
    cgtmo, src, work = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    ours_path = os.path.join(src, "ocio_config", "config.ocio")
    ours = ocio.Config.CreateFromFile(ours_path)
    manifest = json.load(open(os.path.join(src, "luts", "manifest.json")))["operators"]
    studio, _ = write_aces_style(os.path.join(work, "studio"))
    merged = os.path.join(work, "merged")
    run([cgtmo, "bake", "--into", studio, "--cgtmo-config", ours_path, "-q", "-o", merged])
    merged_config = os.path.join(merged, "config.ocio")

    inputs = []
    if len(sys.argv) > 5:
        inputs.append((sys.argv[4], sys.argv[5]))
    else:
        px = chart()
        for name in SPACES:
            path = os.path.join(work, "chart-%s.exr" % name.replace(" ", "_"))
            write_exr(path, px)
            inputs.append((path, name))
    tally = Tally()
    for exr, space in inputs:
        lin709 = ocio_apply(ours, ocio.ColorSpaceTransform(src=space, dst="Linear Rec.709"), read_float(exr))
        print("%s as %s: %.1f%% of the pixels have a negative Rec.709 component" %
              (os.path.basename(exr), space, 100.0 * float((lin709.min(axis=2) < 0).mean())))
        tag = os.path.basename(exr).rsplit(".", 1)[0]
        for op, m in manifest.items():
            ref_png = os.path.join(work, "%s-%s-apply.png" % (tag, op))
            run(apply_args(cgtmo, exr, ref_png, ours_path, op, m["params"], ["--colorspace", space]))
            ref = read8(ref_png)
            view_png = os.path.join(work, "%s-%s-merged.png" % (tag, op))
            run(["oiiotool", "--colorconfig", merged_config, exr, "--iscolorspace", space,
                 "--ociodisplay:from=" + space, "sRGB", "cgtmo " + op, "-d", "uint8", "-o", view_png])
            tally.compare(ref, read8(view_png), "%s %s: bake --into view" % (space, op), allowed(m["max_error_cv"], m["target_cv"]))
            clf = ocio.FileTransform(src=os.path.join(src, "luts", m["clf"]), interpolation=ocio.INTERP_DEFAULT)
            tally.compare(ref, to8(ocio_apply(ours, clf, lin709)), "%s %s: .clf" % (space, op),
                          allowed(m["clf_max_error_cv"], m["target_cv"]))
            cube = ocio.GroupTransform([
                ocio.ColorSpaceTransform(src="Linear Rec.709", dst="Log2 Shaper"),
                ocio.FileTransform(src=os.path.join(src, "luts", m["cube"]),
                                   interpolation=ocio.INTERP_LINEAR if m["cube_dims"] == 1 else ocio.INTERP_TETRAHEDRAL),
                ocio.RangeTransform(minInValue=0.0, maxInValue=1.0, minOutValue=0.0, maxOutValue=1.0)])
            tally.compare(ref, to8(ocio_apply(ours, cube, lin709)), "%s %s: .cube" % (space, op),
                          allowed(m["cube_max_error_cv"], m["target_cv"]))
    if tally.failures:
        print("FAILED:", *tally.failures, sep="\n  ")
        return 1
    print("ok: %d comparisons" % len(tally.rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
