#!/usr/bin/python3
"""Monte Carlo noise of `cgtmo apply --op cgtmo` in flat regions, per committed scene and per
`detail` mode, with TMQI: the measurement behind the default of `-p detail` (docs/cgtmo.md).

    /usr/bin/python3 bench/noise_flat_regions.py build/apps/cgtmo/cgtmo tests/scenes

Flat regions: 8x8 tiles of geometry whose normals and albedo are uniform (every pixel within
0.02 of the tile's mean, per component) and whose depth varies by under 5% of its mean: one
surface, one material. In each tile the log10 luminance minus its least-squares plane in x, y
(the smooth lighting gradient) leaves the noise; its standard deviation is measured on the input
beauty and on the operator's display-linear output (--no-display), over the tiles where the output
is neither black nor clipped. Printed per scene: the tiles used, the median input noise, each
mode's median output noise and the median per-tile ratio output / input (1: noise kept at full
contrast; below 1: compressed), and each mode's TMQI (8-bit sRGB, `cgtmo eval`).
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

MODES = ("luminance", "illumination")
TILE = 8


def channels(spec, names):
    idx = [spec.channelindex(n) for n in names]
    return idx if all(i >= 0 for i in idx) else None


def read_planes(path):
    buf = oiio.ImageBuf(path)
    spec = buf.spec()
    px = buf.get_pixels(oiio.FLOAT)
    layer = "ViewLayer."
    def plane(names):
        idx = channels(spec, [layer + n for n in names])
        return None if idx is None else px[:, :, idx]
    return {
        "rgb": plane(["Combined.R", "Combined.G", "Combined.B"]),
        "depth": plane(["Depth.Z"]),
        "normal": plane(["Normal.X", "Normal.Y", "Normal.Z"]),
        "albedo": plane(["DiffCol.R", "DiffCol.G", "DiffCol.B"]),
    }


def luminance(rgb):
    return 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]


def flat_tiles(p):
    h, w = p["depth"].shape[:2]
    tiles = []
    for y in range(0, h - TILE + 1, TILE):
        for x in range(0, w - TILE + 1, TILE):
            sl = (slice(y, y + TILE), slice(x, x + TILE))
            d = p["depth"][sl][..., 0]
            if not np.all(d < 1e9):
                continue
            n = p["normal"][sl]
            a = p["albedo"][sl]
            if np.abs(n - n.mean(axis=(0, 1))).max() > 0.02 or np.abs(a - a.mean(axis=(0, 1))).max() > 0.02:
                continue
            if (d.max() - d.min()) > 0.05 * d.mean():
                continue
            tiles.append(sl)
    return tiles


def detrended_std(log_lum):
    yy, xx = np.mgrid[0:TILE, 0:TILE]
    design = np.stack([np.ones(TILE * TILE), xx.ravel(), yy.ravel()], axis=1)
    coef, *_ = np.linalg.lstsq(design, log_lum.ravel(), rcond=None)
    return float(np.std(log_lum.ravel() - design @ coef))


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("noise_flat_regions: %s failed: %s" % (" ".join(cmd), r.stderr.strip()))
    return r.stdout


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: noise_flat_regions.py CGTMO SCENES_DIR")
    cgtmo, scenes = sys.argv[1], sys.argv[2]
    # Every SCENES_DIR/<folder>/<name>.exr but the probes, as `cgtmo eval --scenes` finds them.
    renders = []
    for folder in sorted(os.listdir(scenes)):
        d = os.path.join(scenes, folder)
        if not os.path.isdir(d):
            continue
        for f in sorted(os.listdir(d)):
            if f.endswith(".exr") and not f.endswith(".probe.exr"):
                renders.append((f[:-4], os.path.join(d, f)))
    print("| Scene | flat tiles | input noise | " +
          " | ".join("%s: output noise, ratio, TMQI" % m for m in MODES) + " |")
    print("|---|---:|---:|" + "---:|" * len(MODES))
    with tempfile.TemporaryDirectory() as tmp:
        for name, path in renders:
            p = read_planes(path)
            if any(v is None for v in p.values()):
                print("| %s | no Depth, Normal or DiffCol pass | | |" % name)
                continue
            tiles = flat_tiles(p)
            lum_in = luminance(p["rgb"])
            cells = []
            out_lums = {}
            for mode in MODES:
                lin = os.path.join(tmp, "%s-%s.exr" % (name, mode))
                png = os.path.join(tmp, "%s-%s.png" % (name, mode))
                run([cgtmo, "apply", path, "-o", lin, "--op", "cgtmo", "-p", "detail=" + mode, "--no-display", "-q"])
                run([cgtmo, "apply", path, "-o", png, "--op", "cgtmo", "-p", "detail=" + mode, "-q"])
                q = json.loads(run([cgtmo, "eval", path, png, "--json"]))["q"]
                out_lums[mode] = (luminance(oiio.ImageBuf(lin).get_pixels(oiio.FLOAT)[:, :, :3]), q)
            used = []
            for sl in tiles:
                if not np.all(lum_in[sl] > 0):
                    continue
                if not all(np.all((o[sl] > 0) & (o[sl] < 0.999)) for o, _ in out_lums.values()):
                    continue
                used.append(sl)
            noise_in = np.array([detrended_std(np.log10(lum_in[sl])) for sl in used])
            for mode in MODES:
                o, q = out_lums[mode]
                noise_out = np.array([detrended_std(np.log10(o[sl])) for sl in used])
                if len(used):
                    ratio = np.median(noise_out / np.maximum(noise_in, 1e-12))
                    cells.append("%.4f, %.3f, %.4f" % (np.median(noise_out), ratio, q))
                else:
                    cells.append("-, -, %.4f" % q)
            print("| %s | %d | %s | %s |" % (name, len(used), "%.4f" % np.median(noise_in) if len(used) else "-",
                                             " | ".join(cells)))


if __name__ == "__main__":
    main()
