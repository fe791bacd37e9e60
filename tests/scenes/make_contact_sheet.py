#!/usr/bin/python3
"""Builds tests/scenes/contact_sheet.png: the eight committed renders tone-mapped by the built cgtmo
tool (global Drago with its default parameters, which adapts to each scene's own levels), in a
labelled 4x2 grid. Run from the repository root with Debian's Python (OIIO, matplotlib):

    /usr/bin/python3 tests/scenes/make_contact_sheet.py build/apps/cgtmo/cgtmo
"""
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import OpenImageIO as oiio  # noqa: E402

SCENES = ["cornell", "two-rooms", "sun-window", "night", "relief", "colored-lights", "lit-box", "dark-doorway"]


def main(cgtmo):
    fig, axes = plt.subplots(2, 4, figsize=(12.8, 3.9), dpi=100)
    with tempfile.TemporaryDirectory() as tmp:
        for ax, name in zip(axes.ravel(), SCENES):
            png = os.path.join(tmp, name + ".png")
            subprocess.run([cgtmo, "apply", "tests/scenes/%s/%s.exr" % (name, name), "-o", png, "--op", "drago"],
                           check=True, stdout=subprocess.DEVNULL)
            buf = oiio.ImageBuf(png)
            ax.imshow(buf.get_pixels(oiio.FLOAT)[:, :, :3], interpolation="lanczos")
            ax.set_title(name, fontsize=10)
            ax.axis("off")
    fig.suptitle("cgtmo test scenes (Blender 3.4.1 Cycles, 480x270), tone-mapped with cgtmo apply --op drago",
                 fontsize=9)
    fig.tight_layout(pad=0.4)
    out = "tests/scenes/contact_sheet.png"
    tmp_out = out + ".tmp.png"
    fig.savefig(tmp_out, metadata={"Software": None})
    os.replace(tmp_out, out)
    print("wrote " + out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
