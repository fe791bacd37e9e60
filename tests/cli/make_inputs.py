#!/usr/bin/python3
"""Writes the CLI tests' input renders into a folder (deterministic, so references stay valid).

  hdr.exr      96x54 Blender-style multilayer: ViewLayer.Combined.{R,G,B,A} (float), Depth.Z,
               Normal.{X,Y,Z}; a log ramp over 2^-10..2^14, saturated primaries and secondaries,
               a grey chart, and a few NaN/Inf/negative pixels to exercise the non-finite policy.
  plain.exr    the same beauty as top-level R,G,B (no alpha).
  norgb.exr    only ViewLayer.Depth.Z: a file with no beauty layer.
  truncated.exr / corrupt.exr / notimage.exr: damaged copies of hdr.exr and a text file.

Usage: make_inputs.py OUTDIR
"""
import math
import os
import sys
import numpy as np
import OpenImageIO as oiio

W, H = 96, 54


def exp2(x):
    """2^x from + and * only (math.ldexp is exact): numpy's and libm's exp2 may pick CPU-specific
    variants, and these inputs must be the same bits everywhere, so that golden outputs are too."""
    k = math.floor(x + 0.5)
    r = (x - k) * 0.6931471805599453
    term, total = 1.0, 1.0
    for n in range(1, 20):
        term = term * r / n
        total = total + term
    return math.ldexp(total, k)


def beauty():
    img = np.zeros((H, W, 4), np.float32)
    x = np.linspace(-10.0, 14.0, W, dtype=np.float64)
    ramp = np.array([exp2(float(v)) for v in x]).astype(np.float32)
    # rows 0-17: grey ramp; 18-35: hue sweep with the ramp's energy; 36-53: patches
    img[0:18, :, 0:3] = ramp[None, :, None]
    hues = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1]], np.float32)
    for i in range(W):
        h = hues[(i * 6) // W]
        img[18:36, i, 0:3] = h * ramp[(i * 7) % W]
    greys = [0.0, 0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 8.0, 64.0, 1000.0, 65504.0, 1e-30]
    for k, g in enumerate(greys):
        x0 = k * W // len(greys)
        x1 = (k + 1) * W // len(greys)
        img[36:45, x0:x1, 0:3] = g
        img[45:54, x0:x1, 0:3] = np.array([g, 0.25 * g, 0.02 * g], np.float32)
    img[:, :, 3] = 1.0
    img[40, 2, 0] = np.nan
    img[41, 3, 1] = np.inf
    img[42, 4, 2] = -np.inf
    img[43, 5, 0] = -2.0
    img[44, 6, 1] = 1e30
    return img


def write(path, names, data):
    spec = oiio.ImageSpec(W, H, len(names), oiio.FLOAT)
    spec.channelnames = tuple(names)
    spec.attribute("compression", "zip")
    out = oiio.ImageOutput.create(path)
    if not out or not out.open(path, spec) or not out.write_image(data) or not out.close():
        sys.exit("cannot write " + path + ": " + oiio.geterror())


def main():
    d = sys.argv[1]
    os.makedirs(d, exist_ok=True)
    b = beauty()
    depth = np.full((H, W, 1), 5.0, np.float32)
    normal = np.zeros((H, W, 3), np.float32)
    normal[:, :, 2] = 1.0
    full = np.concatenate([b, depth, normal], axis=2)
    write(os.path.join(d, "hdr.exr"),
          ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A",
           "ViewLayer.Depth.Z", "ViewLayer.Normal.X", "ViewLayer.Normal.Y", "ViewLayer.Normal.Z"], full)
    write(os.path.join(d, "plain.exr"), ["R", "G", "B"], np.ascontiguousarray(b[:, :, 0:3]))
    write(os.path.join(d, "norgb.exr"), ["ViewLayer.Depth.Z"], depth)
    raw = open(os.path.join(d, "hdr.exr"), "rb").read()
    open(os.path.join(d, "truncated.exr"), "wb").write(raw[: len(raw) // 2])
    bad = bytearray(raw)
    for i in range(len(bad) // 2, len(bad) - 16, 97):
        bad[i] ^= 0x5A
    open(os.path.join(d, "corrupt.exr"), "wb").write(bytes(bad))
    open(os.path.join(d, "notimage.exr"), "w").write("this is not an OpenEXR file\n")


if __name__ == "__main__":
    main()
