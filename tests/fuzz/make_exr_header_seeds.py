#!/usr/bin/python3
"""Writes the header-mutation seeds of fuzz_exr_header into corpus/exr_header/: valid small files of
the shapes a header can take (tiled, negative origin, many parts, each compression family, deep)
and hostile ones made by patching a valid header (a huge or inverted dataWindow, an attribute
claiming more bytes than the file has). Usage: tests/fuzz/make_exr_header_seeds.py"""
import os
import struct

import numpy as np
import OpenImageIO as oiio

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "exr_header")


def write(name, w, h, channels=("R", "G", "B"), compression="zip", tile=0, origin=(0, 0), fmt="half"):
    spec = oiio.ImageSpec(w, h, len(channels), fmt)
    spec.channelnames = channels
    spec.attribute("compression", compression)
    spec.x, spec.y = origin
    if tile:
        spec.tile_width = spec.tile_height = tile
    path = os.path.join(OUT, name)
    out = oiio.ImageOutput.create(path)
    assert out.open(path, spec), out.geterror()
    px = (np.arange(w * h * len(channels), dtype=np.float32).reshape(h, w, len(channels)) % 7) / 7
    out.write_image(px)
    out.close()
    return path


def patch(src, dst, name, type_, fmt, values, offset=0):
    """Rewrites attribute `name` (struct format `fmt`) of file `src` into `dst`; offset -4 patches the size."""
    b = bytearray(open(os.path.join(OUT, src), "rb").read())
    key = name.encode() + b"\0" + type_.encode() + b"\0"
    at = b.index(key) + len(key) + 4 + offset
    struct.pack_into(fmt, b, at, *values)
    open(os.path.join(OUT, dst), "wb").write(b)


write("tiled.exr", 16, 8, tile=8)
write("negative_origin.exr", 8, 4, origin=(-5, -3))
for c in ("piz", "b44a", "dwaa", "rle", "none"):
    write("compression_%s.exr" % c, 16, 8, compression=c)

# Many parts: one part per pass, as Nuke writes them.
specs = []
for i, chans in enumerate((("R", "G", "B"), ("Z",), ("N.x", "N.y", "N.z"), ("P.x", "P.y", "P.z"), ("A",), ("albedo.r", "albedo.g", "albedo.b"))):
    s = oiio.ImageSpec(4, 2, len(chans), "half")
    s.channelnames = chans
    s.attribute("compression", "zip")
    s.attribute("name", "part%d" % i)
    specs.append(s)
path = os.path.join(OUT, "many_parts.exr")
out = oiio.ImageOutput.create(path)
assert out.open(path, specs), out.geterror()
for i, s in enumerate(specs):
    if i:
        out.open(path, s, "AppendSubimage")
    out.write_image(np.full((2, 4, s.nchannels), 0.5, np.float32))
out.close()

spec = oiio.ImageSpec(4, 2, 5, "float")
spec.channelnames = ("R", "G", "B", "A", "Z")
spec.deep = True
path = os.path.join(OUT, "deep.exr")
out = oiio.ImageOutput.create(path)
assert out.open(path, spec), out.geterror()
dd = oiio.DeepData()
dd.init(spec)
for px in range(8):
    dd.set_samples(px, 1)
    for c in range(5):
        dd.set_deep_value(px, c, 0, 0.5)
out.write_deep_image(dd)
out.close()

# Hostile headers, from the valid files above.
patch("compression_none.exr", "huge_window.exr", "dataWindow", "box2i", "<4i", (0, 0, 7700000, 7))
patch("compression_none.exr", "huge_negative_window.exr", "dataWindow", "box2i", "<4i", (-2000000000, 0, 2000000000, 7))
patch("compression_dwaa.exr", "huge_window_dwaa.exr", "dataWindow", "box2i", "<4i", (0, 0, 100000000, 7))
patch("compression_none.exr", "inverted_window.exr", "dataWindow", "box2i", "<4i", (15, 7, 0, 0))
patch("tiled.exr", "huge_tiles.exr", "tiles", "tiledesc", "<II", (1 << 30, 1 << 30))
patch("compression_none.exr", "attribute_too_long.exr", "channels", "chlist", "<i", (0x7FFFFFFF,), offset=-4)
# A display window far larger than the data window: the frame is read on it (2.5 GB as float32 for
# 3,932,256 x 54), though no byte of the file stands for those pixels.
patch("compression_none.exr", "huge_display_window.exr", "displayWindow", "box2i", "<4i", (0, 0, 3932255, 53))
patch("compression_none.exr", "huge_negative_display_window.exr", "displayWindow", "box2i", "<4i", (-2000000000, -5, 2000000000, 7))
