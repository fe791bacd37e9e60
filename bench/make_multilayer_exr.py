#!/usr/bin/python3
"""Writes a synthetic 1920x1080 multilayer EXR laid out like a Blender 3.4 render with AOVs, for
bench/e2e.sh (run with Debian's /usr/bin/python3: it needs numpy and OpenImageIO).

Channels, as Blender's OPEN_EXR_MULTILAYER with color_depth 16 names and types them (docs/platform.md):
  ViewLayer.Combined.{R,G,B,A}            half   (beauty; A = 1)
  ViewLayer.Depth.Z                       float  (1e10 on the background)
  ViewLayer.Normal.{X,Y,Z}                float
  ViewLayer.Position.{X,Y,Z}              float
  ViewLayer.DiffCol.{R,G,B}               half   (in [0, 1])
  ViewLayer.Emit.{R,G,B}                  half
  ViewLayer.Combined_{key,fill,rim}.{R,G,B} half (three light groups summing to Combined)
ZIP compression (Blender's default). 26 channels in all.

Content: a ground plane and a few spheres under a gradient sky, lit by three lights with soft
falloff, an emitter, and multiplicative render noise (about 4%, as a few hundred samples leave),
so that ZIP sees data that compresses like a render, not like flat colour or white noise.
Luminance spans about 1e-3 (shadowed ground far away) to about 1e3 (the emitter).

Usage: make_multilayer_exr.py OUT.exr [--width 1920 --height 1080] [--seed 1]
"""
import argparse

import numpy as np
import OpenImageIO as oiio


def render(width, height, seed):
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    u = (x + 0.5) / width * 2 - 1
    v = 1 - (y + 0.5) / height * 2
    aspect = width / height
    # Camera at the origin looking down -z; rays through the image plane at z = -1.5.
    d = np.stack([u * aspect, v, np.full_like(u, -1.5)], axis=-1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    depth = np.full((height, width), 1e10, np.float32)
    pos = np.zeros((height, width, 3), np.float32)
    nrm = np.zeros((height, width, 3), np.float32)
    alb = np.zeros((height, width, 3), np.float32)
    emit = np.zeros((height, width, 3), np.float32)
    # Ground plane y = -1.
    t = np.where(d[..., 1] < -1e-4, -1.0 / np.minimum(d[..., 1], -1e-4), np.inf)
    hit = np.isfinite(t) & (t < 200)
    depth[hit] = (t * -d[..., 2])[hit]
    pos[hit] = (d * t[..., None])[hit]
    nrm[hit] = (0, 1, 0)
    checker = ((np.floor(pos[..., 0]) + np.floor(pos[..., 2])) % 2 == 0)
    alb[hit] = np.where(checker[..., None], [0.6, 0.55, 0.5], [0.2, 0.22, 0.25])[hit]
    # Spheres: centre, radius, albedo, emission.
    spheres = [((-1.6, -0.3, -5.0), 0.7, (0.8, 0.1, 0.1), 0.0), ((0.0, -0.2, -6.5), 0.8, (0.1, 0.6, 0.9), 0.0),
               ((1.7, -0.4, -4.6), 0.6, (0.9, 0.9, 0.9), 0.0), ((0.6, 0.9, -9.0), 0.35, (1.0, 0.85, 0.6), 800.0)]
    for c, r, a, e in spheres:
        c = np.asarray(c, np.float32)
        b = (d * -c).sum(-1)
        disc = b * b - ((c * c).sum() - r * r)
        tt = -b - np.sqrt(np.maximum(disc, 0))
        z = tt * -d[..., 2]
        m = (disc > 0) & (tt > 0) & (z < depth)
        depth[m] = z[m]
        p = d * tt[..., None]
        pos[m] = p[m]
        nrm[m] = ((p - c) / r)[m]
        alb[m] = a
        emit[m] = np.asarray(a, np.float32) * e if e else 0
    # Light groups: key (warm, strong), fill (cool, weak), rim (from behind); Lambert with falloff.
    lights = {"key": ((-4, 5, -1), (60.0, 52.0, 40.0)), "fill": ((5, 2, 0), (6.0, 8.0, 12.0)),
              "rim": ((0, 4, -14), (30.0, 30.0, 36.0))}
    surf = depth < 1e10
    groups = {}
    for name, (lp, col) in lights.items():
        lv = np.asarray(lp, np.float32) - pos
        dist2 = (lv * lv).sum(-1) + 1e-6
        lam = np.maximum((nrm * lv).sum(-1) / np.sqrt(dist2), 0) / dist2
        g = alb * lam[..., None] * np.asarray(col, np.float32)
        g[~surf] = 0
        groups[name] = g
    sky = np.stack([0.3 + 0.5 * v, 0.5 + 0.5 * v, 1.0 + 0.8 * v], -1).clip(0.05) * 0.8
    groups["key"][~surf] = sky[~surf]  # the world is in the key group
    groups["key"] += emit
    noise = lambda: rng.normal(1.0, 0.04, (height, width, 1)).astype(np.float32)
    for name in groups:
        groups[name] = np.maximum(groups[name] * noise(), 0)
    combined = groups["key"] + groups["fill"] + groups["rim"]
    nrm_aa = nrm * np.where(surf, 1.0, 0.0)[..., None]
    return {
        "Combined": (np.concatenate([combined, np.ones((height, width, 1), np.float32)], -1), "RGBA", "half"),
        "Depth": (depth[..., None], "Z", "float"),
        "Normal": (nrm_aa, "XYZ", "float"),
        "Position": (pos, "XYZ", "float"),
        "DiffCol": (alb, "RGB", "half"),
        "Emit": (emit, "RGB", "half"),
        "Combined_key": (groups["key"], "RGB", "half"),
        "Combined_fill": (groups["fill"], "RGB", "half"),
        "Combined_rim": (groups["rim"], "RGB", "half"),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--width", type=int, default=1920)
    ap.add_argument("--height", type=int, default=1080)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    passes = render(a.width, a.height, a.seed)
    names, formats, planes = [], [], []
    for p, (data, chans, fmt) in passes.items():
        for i, c in enumerate(chans):
            names.append(f"ViewLayer.{p}.{c}")
            formats.append(oiio.TypeDesc(fmt))
            planes.append(data[..., i])
    pixels = np.ascontiguousarray(np.stack(planes, -1).astype(np.float32))
    spec = oiio.ImageSpec(a.width, a.height, len(names), "half")
    spec.channelnames = tuple(names)
    spec.channelformats = tuple(formats)
    spec.attribute("compression", "zip")
    spec.attribute("Software", "cgtmo bench/make_multilayer_exr.py (Blender-style multilayer layout)")
    out = oiio.ImageOutput.create(a.out)
    if not out or not out.open(a.out, spec):
        raise SystemExit(f"cannot write {a.out}: {oiio.geterror()}")
    if not out.write_image(pixels):
        raise SystemExit(f"cannot write {a.out}: {out.geterror()}")
    out.close()
    lum = pixels[..., names.index("ViewLayer.Combined.R")] * 0.2126 + pixels[..., names.index("ViewLayer.Combined.G")] * 0.7152 \
        + pixels[..., names.index("ViewLayer.Combined.B")] * 0.0722
    pos = lum[lum > 0]
    print(f"wrote {a.out}: {a.width}x{a.height}, {len(names)} channels, beauty luminance "
          f"{np.percentile(pos, 0.1):.3g} .. {pos.max():.3g} (0.1th percentile .. max)")


if __name__ == "__main__":
    main()
