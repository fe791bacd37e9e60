#!/usr/bin/python3
"""A labelled side-by-side of CG-TMO and Blender's default view (Filmic) on one render, with a box
around the region where they differ most, and a line saying where to look.

    /usr/bin/python3 scripts/demo_sheet.py RENDER.exr CGTMO.png OUT.png [--blender-config FILE]

CGTMO.png is `cgtmo apply RENDER.exr -o CGTMO.png --op cgtmo`. The Filmic side is the render's
beauty (the first of Combined, RGB channels) through Blender's config with OpenImageIO's
ociodisplay, as Blender shows it with View Transform Filmic. OUT is written to a temporary file
in its folder and renamed. Exit 1 with one line when an input cannot be read.
"""
import argparse
import os
import sys
import tempfile

import numpy as np
import OpenImageIO as oiio

BLENDER_CONFIG = "/usr/share/blender/datafiles/colormanagement/config.ocio"
BLOCKS = 8  # the frame is cut into BLOCKS x BLOCKS regions; the one that differs most is boxed


def fail(message):
    sys.exit("demo_sheet.py: error: " + message)


def beauty_channels(spec):
    """The beauty's R, G, B channel names: plain R,G,B or Blender's <layer>.Combined.R,G,B."""
    names = list(spec.channelnames)
    for prefix in [""] + sorted({n.rsplit(".", 1)[0] + "." for n in names if n.endswith(".Combined.R")}):
        rgb = [prefix + c for c in "RGB"]
        if all(c in names for c in rgb):
            return rgb
    fail("no beauty channels (R,G,B or <layer>.Combined.R,G,B) among: " + ", ".join(names[:12]))


def filmic(render, config):
    src = oiio.ImageBuf(render)
    if src.has_error:
        fail("cannot read '%s': %s" % (render, src.geterror().splitlines()[0]))
    rgb = oiio.ImageBufAlgo.channels(src, tuple(beauty_channels(src.spec())))
    out = oiio.ImageBufAlgo.ociodisplay(rgb, "sRGB", "Filmic", fromspace="Linear", colorconfig=config)
    if out.has_error:
        fail("OpenColorIO cannot show '%s' with Filmic of '%s': %s" % (render, config, out.geterror().splitlines()[0]))
    return np.clip(out.get_pixels(oiio.FLOAT)[:, :, :3], 0, 1)


def read_png(path):
    buf = oiio.ImageBuf(path)
    if buf.has_error:
        fail("cannot read '%s': %s" % (path, buf.geterror().splitlines()[0]))
    return buf.get_pixels(oiio.FLOAT)[:, :, :3]


def most_different_block(a, b):
    """(x0, y0, x1, y1) of the block whose mean luminance difference is largest, and that mean."""
    diff = np.abs((a - b) @ np.array([0.2126, 0.7152, 0.0722]))
    h, w = diff.shape
    best = (0.0, (0, 0, w, h))
    for j in range(BLOCKS):
        for i in range(BLOCKS):
            y0, y1, x0, x1 = h * j // BLOCKS, h * (j + 1) // BLOCKS, w * i // BLOCKS, w * (i + 1) // BLOCKS
            if y1 > y0 and x1 > x0:
                best = max(best, (float(diff[y0:y1, x0:x1].mean()), (x0, y0, x1, y1)))
    return best[1], best[0]


def where(box, w, h):
    x = (box[0] + box[2]) / 2 / w
    y = (box[1] + box[3]) / 2 / h
    return ("top" if y < 1 / 3 else "bottom" if y > 2 / 3 else "middle") + "-" + \
        ("left" if x < 1 / 3 else "right" if x > 2 / 3 else "centre")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("render")
    p.add_argument("cgtmo_png")
    p.add_argument("out")
    p.add_argument("--blender-config", default=BLENDER_CONFIG)
    a = p.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.patches as patches
    import matplotlib.pyplot as plt

    ours = read_png(a.cgtmo_png)
    theirs = filmic(a.render, a.blender_config)
    if ours.shape != theirs.shape:
        fail("'%s' is %dx%d, the render %dx%d" % (a.cgtmo_png, ours.shape[1], ours.shape[0], theirs.shape[1], theirs.shape[0]))
    h, w = ours.shape[:2]
    box, mean = most_different_block(ours, theirs)
    fig, axes = plt.subplots(1, 2, figsize=(12.8, 12.8 * h / w / 2 + 0.9), dpi=100)
    for ax, img, title in zip(axes, (ours, theirs), ("CG-TMO (cgtmo apply --op cgtmo)", "Blender's default view (Filmic)")):
        ax.imshow(img, interpolation="lanczos")
        ax.add_patch(patches.Rectangle((box[0], box[1]), box[2] - box[0], box[3] - box[1], fill=False, edgecolor="#ff3030", linewidth=1.5))
        ax.set_title(title, fontsize=10)
        ax.axis("off")
    text = "They differ most in the boxed region (%s of the frame): mean difference %.3f of display white." % (where(box, w, h), mean)
    fig.suptitle(text, fontsize=9)
    fig.tight_layout(pad=0.4)
    folder = os.path.dirname(os.path.abspath(a.out))
    fd, tmp = tempfile.mkstemp(suffix=".png", dir=folder, prefix=".demo_sheet-")
    os.close(fd)
    try:
        fig.savefig(tmp, metadata={"Software": None})
        os.replace(tmp, a.out)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    print("wrote %s: %s" % (a.out, text))


if __name__ == "__main__":
    main()
